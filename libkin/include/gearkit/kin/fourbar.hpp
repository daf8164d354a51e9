#pragma once
// Four-bar linkage properties: Grashof class and transmission angle.
#include <gearkit/kin/data.hpp>
#include <optional>
#include <string>

namespace gearkit::kin {

enum class GrashofClass {
  crank_rocker,       ///< Grashof, shortest link is the input (crank) or output adjacent to ground
  double_crank,       ///< Grashof, shortest link is the ground (drag link)
  double_rocker,      ///< Grashof, shortest link is the coupler
  change_point,       ///< s + l = p + q: passes through a flat (uncertainty) configuration
  triple_rocker,      ///< non-Grashof: no link turns fully
  cannot_assemble,    ///< l > s + p + q: the longest link is longer than the three others together
};

struct GrashofResult {
  GrashofClass kind = GrashofClass::triple_rocker;
  double s = 0.0, l = 0.0, pq = 0.0;  ///< shortest, longest, sum of the other two [m]
  std::string text;  ///< e.g. "Grashof crank-rocker (s + l = 120 mm < p + q = 200 mm)": lengths in mm,
                     ///< as mechanism files and reports give them
};

/// Grashof class from the link lengths [m] (ground, input crank, coupler, output rocker).
/// Lengths must be positive; the equality s + l = p + q is judged to 1e-9 relative. A loop whose
/// longest link exceeds the sum of the other three can never close (cannot_assemble).
/// @param ground, crank, coupler, rocker  link lengths [m], > 0 (not checked)
/// @throws std::bad_alloc only (the text).
GrashofResult grashof(double ground, double crank, double coupler, double rocker);

/// Transmission angle [rad] in [0, pi/2]: the acute angle between the coupler (B - A) and the
/// rocker (B - O4) lines at their common joint; pi/2 is ideal, below ~40 deg is poor.
/// @param coupler, rocker  the two lines' direction vectors [m] (any length > 0). Never throws.
double transmission_angle(const Eigen::Vector2d& coupler, const Eigen::Vector2d& rocker);

/// A model recognised as a four-bar: three bodies, four revolutes, a loop ground-crank-coupler-
/// rocker-ground, driven on the crank.
struct FourBar {
  int crank = 0, coupler = 0, rocker = 0;
  BodyPoint o2, a_crank, a_coupler, b_coupler, b_rocker, o4;  ///< joint points on each side
  double ground = 0.0, crank_length = 0.0, coupler_length = 0.0, rocker_length = 0.0;  ///< [m]
};

/// Recognises a four-bar (or the four-bar loop of a model with exactly those bodies and
/// joints plus one angle driver). @returns nullopt for anything else.
/// @throws std::bad_alloc only.
std::optional<FourBar> find_four_bar(const Model& model);

/// Transmission angle [rad] of a recognised four-bar at data.q [m, rad].
/// @param f  found by find_four_bar in the model `data` was made for. Never throws.
double transmission_angle(const FourBar& f, const Data& data);

}  // namespace gearkit::kin
