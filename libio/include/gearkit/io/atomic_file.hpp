#pragma once
#include <string>
#include <string_view>

namespace gearkit::io {

/// Writes `content` to `path` atomically: a temporary file in the same folder, flushed, then
/// renamed over `path`. A failure leaves no file behind (and any earlier file untouched).
/// @param option the option that named the path ("--dxf"), for the error message.
/// @throws InputError "option '--dxf': cannot write 'path': reason" when the folder does not
///         exist, is not writable, or `path` is a directory.
void write_file_atomic(const std::string& path, std::string_view content, std::string_view option);

}  // namespace gearkit::io
