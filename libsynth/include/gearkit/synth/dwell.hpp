#pragma once
// Single-dwell six-bar from a four-bar coupler curve with a near-circular arc (Norton, Design of
// Machinery, ch. 3, dwell mechanisms): while the coupler point P runs along an arc of radius
// R about D, a link of length R from P to D leaves D at rest, so the output rocker O6 D that
// carries D dwells; when P leaves the arc, the link drags D and the rocker swings. The arc is
// the window of the given crank rotation whose least-squares circle (Kasa's algebraic fit) has
// the smallest radial deviation. SI units (m, rad).
#include <gearkit/synth/mechanism_writer.hpp>
#include <optional>

namespace gearkit::synth {

struct DwellTask {
  FourBar four_bar;                ///< must be a crank (turns fully); its coupler point traces the curve
  double dwell = 1.0471975511965976;  ///< crank rotation of the dwell [rad] (default 60 deg), 5..180 deg
  std::optional<double> output_rocker;  ///< |O6 D| [m]; absent: the best of a few multiples of R
  std::optional<Vec2> output_pivot;     ///< O6 [m]; absent: chosen for the largest output swing
  int samples = 720;               ///< coupler-curve samples over one turn (72..7200)
};

struct DwellResult {
  FourBar four_bar;
  double window_start = 0;         ///< crank angle where the dwell begins [rad] (counter-clockwise)
  Vec2 D{0, 0};                    ///< centre of the fitted arc: the dwelling joint [m]
  double radius = 0;               ///< R = |P D| [m]
  double arc_deviation = 0;        ///< max | |P - D| - R | over the window [m]
  Vec2 O6{0, 0};                   ///< output rocker pivot [m]
  double output_rocker = 0;        ///< |O6 D| [m]
  int output_branch = 1;           ///< branch_of(P, D, O6) of the output dyad
  double dwell_motion = 0;         ///< output rocker rotation within the dwell window [rad]
  double swing = 0;                ///< output rocker swing over the whole turn [rad]
};

/// Output rocker angle [rad] at crank angle theta2, or nullopt where the six-bar cannot close.
std::optional<double> output_angle(const DwellResult& six_bar, double theta2);

/// Finds the arc, places the dyad and measures the dwell.
/// @throws std::invalid_argument for a dwell outside 5..180 deg, samples outside their limits,
///         or non-positive lengths.
/// @throws NoSolution if the four-bar's crank does not turn fully or no output dyad assembles
///         over the whole turn.
DwellResult synthesize_dwell(const DwellTask& task);

/// The six-bar as a mechanism sketch: the four-bar of four_bar_sketch(), plus link5 (P, D) and
/// rocker6 (O6, D), drawn at the start of the dwell, driver over one full turn, output theta6.
MechanismSketch dwell_sketch(const DwellResult& six_bar, std::string title);

}  // namespace gearkit::synth
