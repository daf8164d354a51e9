#pragma once
// The gear mesh element: gears on two links, both pivoted on a common carrier (the ground for
// fixed axes, or an arm), turn with the tooth ratio. Relative to the carrier c an external pair
// turns in opposite senses and an internal pair (gear 1 inside ring gear 2) in the same sense:
//     (theta_2 - theta_c) + k (theta_1 - theta_c) = phase,   k = z1/z2 external, -z1/z2 internal.
// One equation; its multiplier lambda is the torque the mesh puts on gear 2: T_2 = -lambda,
// T_1 = -k lambda [N m]. The mesh acts on the gears as torques only: the joint reactions of the
// gear shafts do not contain the tooth force, whose components the reaction reports.
#include <gearkit/kin/element.hpp>
#include <gearkit/kin/model.hpp>

#include <memory>
#include <optional>
#include <string>

namespace gearkit::elements {

struct GearMeshParameters {
  int gear1 = kin::kGround;    ///< body of gear 1
  int gear2 = kin::kGround;    ///< body of gear 2
  int carrier = kin::kGround;  ///< body holding both axes (kin::kGround: fixed axes)
  int z1 = 0;                  ///< teeth of gear 1, >= 1
  int z2 = 0;                  ///< teeth of gear 2, >= 1
  bool internal = false;       ///< gear 2 is a ring gear with gear 1 inside it
  /// [rad] the constant of the equation; nullopt: from the model's drawn angles (Body::angle_guess),
  /// so that the drawing is a meshing position.
  std::optional<double> phase;
  /// Normal module m_n [m] (> 0). With it the reaction reports the tooth forces.
  std::optional<double> module;
  double pressure_angle = 0.3490658503988659;  ///< normal pressure angle alpha_n [rad], in (0, 45 deg)
  double helix_angle = 0.0;                    ///< helix angle beta [rad], |beta| < 45 deg
};

/// Builds a gear mesh between bodies of `model`.
/// @throws kin::ElementError (field "gear1", "gear2", "carrier", "z1", "z2", "module",
///         "pressure_angle", "helix_angle") for a body index not in the model, gear1, gear2 and
///         carrier not three different bodies, a tooth number below 1, an internal gear 2 not
///         larger than gear 1, a module <= 0, an angle out of its range.
/// Reaction values: T_1, T_2 [N m] (torques on gear 1 and 2 from the other, counter-clockwise
/// positive) and, with a module, on the reference circle of gear 2 (ISO 6336-1, 21771):
///   F_t = |T_2| / r_2,  r_2 = m_n z2 / (2 cos beta)          nominal tangential force [N]
///   F_r = F_t tan alpha_t,  tan alpha_t = tan alpha_n / cos beta      radial force [N]
///   F_n = F_t / (cos alpha_n cos beta)                              normal tooth force [N]
///   F_a = F_t tan |beta|                                           axial force [N] (helical)
std::unique_ptr<kin::Constraint> make_gear_mesh(const kin::Model& model, const GearMeshParameters& p);

/// make_gear_mesh added to `model` as constraint `name`. @returns its index.
/// @throws kin::ElementError as make_gear_mesh; std::invalid_argument for a repeated name.
int add_gear_mesh(kin::Model& model, std::string name, const GearMeshParameters& p);

}  // namespace gearkit::elements
