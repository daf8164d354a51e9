#pragma once
// Numbers and units as the cam command writes them: degrees, cam angles in [0, 360), JSON
// numbers without the noise of unit conversions, the follower's value unit (mm or deg).
#include "cam_model.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <numbers>
#include <string>

namespace gearkit::plugins::cam {

inline double deg(double rad) { return rad * 180 / std::numbers::pi; }

/// A cam angle in [0, 360) deg.
inline double angle_deg(double rad) {
  const double d = std::fmod(deg(rad), 360.0);
  return d < 0 ? d + 360 : d;
}

/// A JSON number rounded to 12 significant digits (30 deg stays 30, not 29.999999999999996
/// after the round trip through radians); null for a non-finite value (the report says why).
nlohmann::json number(double v);

/// The follower coordinate's name and units: translating s [mm], oscillating psi [deg].
struct FollowerUnits {
  explicit FollowerUnits(const CamModel& model)
      : oscillating(model.design.follower.motion == gearkit::cam::FollowerMotion::oscillating),
        s_name(oscillating ? "psi" : "s"),
        s_unit(oscillating ? "deg" : "mm"),
        d_unit(oscillating ? "rad" : "mm") {}
  /// The model value (mm or rad) in the unit shown (mm or deg).
  double s_value(double s) const { return oscillating ? deg(s) : s; }

  bool oscillating;
  std::string s_name, s_unit, d_unit;
};

}  // namespace gearkit::plugins::cam
