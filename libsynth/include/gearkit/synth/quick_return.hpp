#pragma once
// Crank-rocker for a given rocker swing and time ratio (Norton, Design of Machinery, sec. 3.3:
// two-position synthesis with rocker output, and the quick-return four-bar). At the rocker's
// two limit positions B1, B2 the crank and coupler are in line, extended (|O2 B| = b + a) and
// folded (|O2 B| = b - a); the crank turns pi + delta on one stroke and pi - delta on the other,
// so the time ratio Q = (pi + delta)/(pi - delta) fixes delta = pi (Q - 1)/(Q + 1), the angle
// B1 O2 B2. O2 may sit anywhere on the arcs that see the chord B1 B2 under delta (the line B1 B2
// beyond the chord when Q = 1): that is the free choice, fixed here by the ground length or by
// the best minimum transmission angle. SI units (m, rad).
#include <gearkit/synth/linkage.hpp>
#include <optional>

namespace gearkit::synth {

struct QuickReturnTask {
  double swing = 0;            ///< rocker swing psi [rad], 0 < psi < pi
  double time_ratio = 1;       ///< Q = slow stroke / fast stroke, 1 <= Q < 10
  double rocker = 0.1;         ///< c = |O4 B| [m] (sets the scale)
  std::optional<double> ground;  ///< d = |O2 O4| [m]; absent: the best transmission angle decides
  int samples = 3600;          ///< positions of O2 tried along its locus (100..100000)
};

struct QuickReturnResult {
  FourBar linkage;             ///< O4 at the origin, B1 and B2 symmetric about the y axis; P = B
  double delta = 0;            ///< angle B1 O2 B2 [rad]
  double theta2_extended = 0;  ///< crank angle at the extended limit position [rad]
  double theta2_folded = 0;    ///< crank angle at the folded limit position [rad]
  double ccw_stroke = 0;       ///< crank rotation, turning counter-clockwise, from extended to folded [rad]
  double min_transmission = 0; ///< over the whole turn [rad]
};

/// Synthesises the crank-rocker.
/// @throws std::invalid_argument for a swing outside (0, pi), Q outside [1, 10), a non-positive
///         rocker or ground length, samples outside their limits.
/// @throws NoSolution if no position of O2 (at the given ground length) gives a Grashof
///         crank-rocker.
QuickReturnResult synthesize_quick_return(const QuickReturnTask& task);

}  // namespace gearkit::synth
