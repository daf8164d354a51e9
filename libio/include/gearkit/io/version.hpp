#pragma once
// The gearkit release, for what a run leaves behind (drawings' title blocks, HTML reports), so that
// a picture in a report can be traced to the program that made it.
#include <string_view>

namespace gearkit::io {

/// "0.1.0": the project version of the build (CMake's PROJECT_VERSION).
std::string_view version();

}  // namespace gearkit::io
