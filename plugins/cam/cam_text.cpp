#include "cam_text.hpp"

#include <fmt/format.h>

#include <cstdlib>

namespace gearkit::plugins::cam {

nlohmann::json number(double v) {
  if (!std::isfinite(v)) return nullptr;
  if (v == 0) return 0.0;
  return std::strtod(fmt::format("{:.12g}", v).c_str(), nullptr);
}

}  // namespace gearkit::plugins::cam
