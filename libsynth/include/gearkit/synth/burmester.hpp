#pragma once
// Burmester theory for four and five coupler poses (Burmester, Lehrbuch der Kinematik, 1888;
// Erdman, Sandor & Kota, Mechanism Design, the four- and five-position standard form; Norton,
// Design of Machinery, ch. 5). A dyad G + W e^{i beta_j} + Z e^{i alpha_j} = P_j guides
// the coupler through the poses when
//   W (e^{i beta_j} - 1) + Z (e^{i alpha_j} - 1) = delta_j = P_j - P_1,  j = 2..n.
// For four poses the three equations in W, Z are compatible only if
//   D2 e^{i beta2} + D3 e^{i beta3} + D4 e^{i beta4} + D1 = 0          (compatibility)
// with D2 = a3 d4 - a4 d3, D3 = a4 d2 - a2 d4, D4 = a2 d3 - a3 d2, D1 = -(D2 + D3 + D4),
// a_j = e^{i alpha_j} - 1, d_j = delta_j: every beta2 gives (up to) two closures of that
// triangle, hence a one-parameter family of dyads whose ground pivots trace the centre-point
// curve and whose moving pivots (pose 1) the circle-point curve. A fifth pose keeps only the
// dyads that also satisfy |delta_5 - Z (e^{i alpha_5} - 1) + W| = |W|: the Burmester points,
// none, two or four. SI units, global frame.
#include <gearkit/synth/motion_generation.hpp>
#include <span>
#include <vector>

namespace gearkit::synth {

/// A dyad of the Burmester family with its crank rotations from pose 1 [rad].
struct BurmesterDyad {
  Dyad dyad;               ///< ground pivot = centre point, moving pivot = circle point (pose 1)
  std::vector<double> beta;  ///< rotation of W to each pose after the first (beta2, beta3, ...)
  int closure = 0;         ///< which closure of the compatibility triangle (0 or 1)
};

/// Limit on `samples` below (docs/cli.md).
inline constexpr int kMaxBurmesterSamples = 3600;

/// The four-pose centre-point/circle-point curves, sampled at `samples` values of beta2 over
/// [0, 2 pi) on both closures; samples where the triangle does not close or the dyad equations
/// are singular are left out (so the curves show as the runs of consecutive samples).
/// @throws std::invalid_argument unless poses.size() == 4 and 8 <= samples <= kMaxBurmesterSamples.
std::vector<BurmesterDyad> burmester_curves(std::span<const Pose> poses, int samples);

/// The dyad of the four-pose family at rotation `beta2` [rad] and closure 0 or 1.
/// @throws NoSolution if the triangle does not close there or the equations are singular.
BurmesterDyad burmester_dyad(std::span<const Pose> poses, double beta2, int closure);

/// The Burmester points of five poses: the dyads (0, 2 or 4) that guide the coupler through all
/// five, located by sign changes of the fifth-pose residual along the four-pose family
/// (`samples` per closure) and refined by bisection to 1e-12 rad.
/// @throws std::invalid_argument unless poses.size() == 5 and 8 <= samples <= kMaxBurmesterSamples.
std::vector<BurmesterDyad> burmester_points(std::span<const Pose> poses, int samples);

/// How far the dyad's moving pivot strays from its circle about the ground pivot over the poses
/// [m]: max_j | |M_j - G| - |M_1 - G| |, 0 for an exact dyad.
double dyad_error(std::span<const Pose> poses, const Dyad& dyad);

}  // namespace gearkit::synth
