#pragma once
// The working centre distance of two meshing gears of a train, computed by libgear, for the
// coaxiality check of planetary stages with profile shift (libtrain itself knows no involutes).
#include <gearkit/train/model.hpp>

#include <optional>

namespace gearkit::plugins::train {

/// Working centre distance [mm] of spur gears a and b with the standard 20 deg pressure angle:
/// inv alpha_w = inv alpha + 2 tan alpha (x_a + x_b)/(z_a + z_b), a = a_d cos alpha / cos alpha_w
/// (ISO 21771; an internal gear has z < 0 in the formula and keeps the ISO sign of its x).
/// nullopt when a module is missing or the modules differ, or the shifts are so negative that
/// no working pressure angle exists.
std::optional<double> working_centre_distance(const gearkit::train::Gear& a, const gearkit::train::Gear& b);

}  // namespace gearkit::plugins::train
