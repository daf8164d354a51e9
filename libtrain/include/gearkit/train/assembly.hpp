#pragma once
// Assembly conditions of planetary stages: whether the planets of each carrier can actually be
// mounted. For every planet member (a member carried by an arm):
//  - coaxiality: each central gear it meshes with (sun or ring, coaxial with the arm) must sit at
//    the same centre distance from the planet axis;
//  - equal spacing of N planets: with central gears A and B meshing planet gears p1 and p2, and
//    i0 = (w_B - w_c)/(w_A - w_c) the basic ratio through the planet,
//      (1 - i0) z_B z_p1 / (N gcd(z_p1, z_p2))  must be an integer
//    (for a simple planet p1 = p2 this is the familiar (z_s + z_r)/N integer);
//  - neighbour clearance: 2 a sin(pi/N) > tip diameter of the largest planet gear,
//    d_a = m_n z / cos(beta) + 2 m_n (1 + x).
// Lengths are in mm when modules are given; with no module anywhere in a planet set a common
// module is assumed and lengths are in modules.
#include <gearkit/train/model.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace gearkit::train {

/// Working centre distance [mm] of two meshing gears, or nullopt when it cannot be computed.
using CentreDistanceFunction = std::function<std::optional<double>(const Gear& a, const Gear& b)>;

/// a = m_n (z_a + z_b)/(2 cos beta) for an external pair, m_n (z_int - z_ext)/(2 cos beta) with an
/// internal gear [mm] (ISO 21771 reference centre distance; beta the helix angle of gear a).
/// nullopt when a module is missing, the modules differ, or a profile shift is not zero (then the
/// working centre distance depends on the shifts: pass a function that computes it).
std::optional<double> reference_centre_distance(const Gear& a, const Gear& b);

struct AssemblyCheck {
  std::string subject;    ///< "planet '23' on carrier 'b'" or "mesh 'p-r'"
  std::string condition;  ///< "coaxiality", "equal spacing", "neighbour clearance", "internal mesh"
  bool checked = false;   ///< false: not applicable or data missing (see detail)
  bool satisfied = false;
  std::string detail;     ///< the numbers, for the report
  /// Not checked because the train itself looks wrong, which a report should warn about: a
  /// planet that meshes no gear at all (nothing to space the planets against).
  bool suspect = false;
};

/// Runs every assembly check that applies. Centre distances count as equal within
/// `tolerance` (mm, or modules when no module is given). Never throws for a valid model.
std::vector<AssemblyCheck> check_assembly(const TrainModel& model,
                                          const CentreDistanceFunction& centre_distance = reference_centre_distance,
                                          double tolerance = 1e-3);

}  // namespace gearkit::train
