#include <gearkit/io/version.hpp>

namespace gearkit::io {

std::string_view version() { return GEARKIT_VERSION_STRING; }

}  // namespace gearkit::io
