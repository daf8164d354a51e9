#pragma once
// Path generation: a four-bar whose coupler point passes near target points, with or without
// prescribed timing (crank angles), found by global optimisation (NLopt: `restarts` runs of the
// evolution strategy ESCH and of controlled random search CRS2-LM share 80 % of the evaluations,
// then Powell's BOBYQA polishes the best five with the rest; docs/design.md has the choice).
//
// Design variables, as in the optimisation literature (Cabrera, Simon & Prado 2002, Mechanism
// and Machine Theory 37: 1165-1177) less the placement: link lengths r1 (ground), r2 (crank),
// r3 (coupler), r4 (rocker), the coupler point (rcx, rcy) in the coupler frame, and the crank
// angle at each point (its first value, then non-negative increments that add up to at most one
// turn, so the points are met in order; given when the timing is prescribed). The placement of
// the linkage (O2 and the ground's direction) is solved for every candidate in closed form, as
// the rigid motion that best fits its coupler points to the targets (Kabsch). The objective is
// the tracking error
//   E = sum_j |C(theta2_j) - T_j|^2,
// with the constraints (Grashof crank, transmission angle, link-length ratio, pivot regions,
// assembly at every point) as quadratic penalties during the search and checked exactly at the
// end. Reproducible: NLopt's random generator is seeded from `seed` before every stage.
// SI units (m, rad).
#include <gearkit/synth/linkage.hpp>
#include <optional>
#include <string>
#include <vector>

namespace gearkit::synth {

/// An axis-aligned region for a ground pivot [m].
struct Region {
  Vec2 min{0, 0}, max{0, 0};
  bool contains(const Vec2& p) const;
};

/// The Grashof type asked of the linkage.
enum class GrashofType {
  crank,         ///< the crank turns fully: crank-rocker or double crank (Grashof, crank or ground shortest)
  crank_rocker,  ///< Grashof with the crank the shortest link
  double_crank,  ///< Grashof with the ground the shortest link (drag link)
  any,           ///< no Grashof condition: the input may rock between toggles
};

struct PathConstraints {
  GrashofType grashof = GrashofType::crank;
  bool require_crank() const { return grashof != GrashofType::any; }
  double min_transmission = 0.5235987755982988;  ///< [rad] (30 deg), over the motion
  double max_link_ratio = 10;            ///< longest / shortest link
  std::optional<double> min_link, max_link;  ///< link-length bounds [m]; default from the targets' span
  std::optional<Region> O2_region, O4_region;  ///< ground-pivot regions; default: the targets' box
                                               ///< enlarged by twice its diagonal
};

/// Limits of the optimiser budget (docs/cli.md): a run stays under a few seconds. One
/// evaluation costs about 0.3 us per target point, plus the local stage's own overhead.
inline constexpr long kMaxEvaluations = 2'000'000;
inline constexpr long kMaxPointEvaluations = 12'000'000;  ///< evaluations x target points
inline constexpr int kMaxRestarts = 64;
inline constexpr int kMaxPathPoints = 100;

/// The default evaluation budget for `points` targets: 300 000, less for many points so that
/// evaluations x points stays at 3 000 000 (about a second on the project's machine).
long default_path_evaluations(std::size_t points);

struct PathBudget {
  long evaluations = 300'000;  ///< objective evaluations over all restarts (1000..kMaxEvaluations,
                               ///< and evaluations x points <= kMaxPointEvaluations)
  int restarts = 16;           ///< independent global searches; they cycle through both assembly
                               ///< branches and both crank directions (1..kMaxRestarts)
  unsigned seed = 1;           ///< fixes NLopt's random generator: same seed, same result
};

struct PathTask {
  std::vector<Vec2> points;                 ///< targets, in the order the coupler meets them (3..kMaxPathPoints)
  std::optional<std::vector<double>> timing;  ///< crank rotation from the first point to each point [rad]
                                            ///< (first 0, increasing, < 2 pi); absent: free timing
  PathConstraints constraints;
  PathBudget budget;
};

struct PathResult {
  FourBar linkage;
  std::vector<double> theta2;           ///< global crank angle at each target [rad]
  std::vector<Vec2> reached;            ///< the coupler point there [m]
  double error = 0;                     ///< sum of squared distances [m^2]
  double max_distance = 0;              ///< largest distance to a target [m]
  long evaluations = 0;                 ///< objective evaluations spent
  int restarts = 0;
  DefectReport defects;
  TransmissionRange transmission;       ///< over the whole cycle (crank) or the points' range
  std::vector<std::string> notes;       ///< which constraints were active, etc.
};

/// Runs the optimisation.
/// @throws std::invalid_argument for a malformed task: fewer than 3 or more than kMaxPathPoints
///         targets, non-finite coordinates, targets all in one place, timing of the wrong size or
///         not increasing within one turn, budget outside its limits, empty regions or bounds.
/// @throws NoSolution if no restart ends at a linkage meeting every constraint (the message
///         names the constraint that stayed violated).
PathResult synthesize_path(const PathTask& task);

/// The tracking error sum |C(theta2_j) - T_j|^2 [m^2] of a linkage at given crank angles, with
/// the reached points; infinity if it cannot be assembled at one of them.
double tracking_error(const FourBar& linkage, const std::vector<double>& theta2, const std::vector<Vec2>& targets,
                      std::vector<Vec2>* reached = nullptr);

}  // namespace gearkit::synth
