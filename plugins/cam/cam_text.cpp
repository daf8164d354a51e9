#include "cam_text.hpp"

#include <gearkit/io/report.hpp>

namespace gearkit::plugins::cam {

nlohmann::json number(double v) { return io::json_number(v); }

}  // namespace gearkit::plugins::cam
