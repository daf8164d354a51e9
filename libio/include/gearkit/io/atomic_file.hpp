#pragma once
#include <string>
#include <string_view>

namespace gearkit::io {

/// Writes one output file: an OutputSet (gearkit/io/output.hpp) with that single output,
/// committed at once. A command that writes several files must put them all in one OutputSet
/// so that they are committed together.
/// @param option the option that named the path ("--dxf"), for the error message.
/// @throws InputError as OutputSet::add() and OutputSet::commit().
void write_file_atomic(const std::string& path, std::string_view content, std::string_view option);

}  // namespace gearkit::io
