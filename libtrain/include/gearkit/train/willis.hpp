#pragma once
// Willis' equation of one mesh. Seen from the carrier c, gears a and b form a fixed-axis pair:
//   (w_b - w_c) / (w_a - w_c) = -z_a / z_b   (two external gears)
//   (w_b - w_c) / (w_a - w_c) = +z_a / z_b   (one internal gear)
// written without fractions as  z_b (w_b - w_c) - s z_a (w_a - w_c) = 0,  s = -1 or +1,
// a linear equation with integer coefficients in the member speeds.
#include <gearkit/train/model.hpp>
#include <gearkit/train/rational.hpp>

#include <string>
#include <utility>
#include <vector>

namespace gearkit::train {

/// The sign s of the basic ratio: -1 for an external pair, +1 when one gear is internal.
int basic_ratio_sign(const Gear& a, const Gear& b);

/// The basic (Willis) ratio of a mesh, i0 = (w_b - w_c)/(w_a - w_c) = s z_a / z_b, exact.
Rational basic_ratio(const TrainModel& model, MeshId mesh);

/// Integer coefficients of the mesh's equation, per gear: coefficient of w_a, of w_b and of w_c
/// before members are merged (a gear on the carrier itself adds to the carrier's coefficient).
/// Also the mesh torques in the ideal case: mesh multiplier times these coefficients.
struct WillisCoefficients {
  long long on_a = 0;        ///< -s z_a
  long long on_b = 0;        ///< z_b
  long long on_carrier = 0;  ///< s z_a - z_b
};
WillisCoefficients willis_coefficients(const TrainModel& model, MeshId mesh);

/// The equation as a row over members (merged, zero terms dropped, ordered by member id).
std::vector<std::pair<MemberId, long long>> willis_row(const TrainModel& model, MeshId mesh);

/// The equation as a student writes it, with the tooth counts as given (not reduced):
/// "(w_ring - w_arm) / (w_planet - w_arm) = +18/60" for a mesh on an arm and
/// "w_2 / w_1 = -35/90" on fixed axes. Member names follow "w_".
std::string willis_equation_text(const TrainModel& model, MeshId mesh);

/// The same equation in linear form: "60·(w_ring - w_arm) - 24·(w_sun - w_arm) = 0".
std::string willis_linear_text(const TrainModel& model, MeshId mesh);

}  // namespace gearkit::train
