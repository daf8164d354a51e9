#pragma once
// The working centre distance of two meshing gears of a train, computed by libgear, for the
// coaxiality check of planetary stages with profile shift (libtrain itself knows no involutes).
#include <gearkit/train/model.hpp>

#include <optional>

namespace gearkit::plugins::train {

/// Working centre distance [mm] of gears a and b with their normal pressure angle alpha_n and
/// helix angle beta (from the train file; 20 deg and 0 by default), ISO 21771:
///   tan alpha_t = tan alpha_n / cos beta, a_d = m_n (z_a + z_b) / (2 cos beta),
///   inv alpha_wt = inv alpha_t + 2 tan alpha_n (x_a + x_b)/(z_a + z_b), a = a_d cos alpha_t / cos alpha_wt
/// (an internal gear has z < 0 in the formula and keeps the ISO sign of its x).
/// nullopt when a module is missing or the modules differ, or the shifts are so negative that
/// no working pressure angle exists. (make_train_model has already checked that the pressure
/// angles are equal and the helices match.)
std::optional<double> working_centre_distance(const gearkit::train::Gear& a, const gearkit::train::Gear& b);

}  // namespace gearkit::plugins::train
