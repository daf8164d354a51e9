#pragma once
#include <string>
#include <string_view>

namespace gearkit::io {

/// Text made safe for XML/SVG content and attribute values (&, <, >, quotes); control
/// characters, which XML 1.0 forbids, become spaces.
std::string xml_escape(std::string_view text);

}  // namespace gearkit::io
