#pragma once
// Motion generation: a four-bar whose coupler passes through given poses (rigid-body guidance),
// built from two dyads (ground pivot + moving pivot), as Norton's Design of Machinery does it in
// ch. 3 (graphical: perpendicular bisectors for two positions, circumcentres for three, the
// inversion for specified fixed pivots) and ch. 5 (analytical: the dyad equation
// W (e^{i beta_j} - 1) + Z (e^{i alpha_j} - 1) = delta_j in complex numbers).
// Every candidate is assembled as a FourBar and checked for branch, order and Grashof defects.
// SI units (m, rad), global frame.
#include <gearkit/synth/function_generation.hpp>
#include <gearkit/synth/linkage.hpp>
#include <optional>
#include <span>
#include <vector>

namespace gearkit::synth {

/// A pose of the coupler: where a point P of it is and the angle of a line fixed on it.
struct Pose {
  Vec2 point{0, 0};  ///< [m]
  double angle = 0;  ///< [rad]
};

/// A pose given by two coupler points C and D (Norton's C1 D1 notation): P = C, angle of C -> D.
/// @throws std::invalid_argument if C and D coincide.
Pose pose_from_points(const Vec2& C, const Vec2& D);

/// Where the coupler point that is at `p` in pose `from` lies in pose `to`.
Vec2 carry(const Pose& from, const Pose& to, const Vec2& p);

/// A dyad of the four-bar: its ground pivot and its moving pivot in pose 1 [m].
struct Dyad {
  Vec2 ground_pivot{0, 0}, moving_pivot{0, 0};
};

/// Two positions (Norton Ex. 3-3): the ground pivot lies on the perpendicular bisector of the
/// moving pivot's two positions, `offset` [m] from the chord's midpoint (positive to the left of
/// the chord M1 -> M2). @throws NoSolution if the moving pivot does not move between the poses.
Dyad dyad_two_positions(const Pose& p1, const Pose& p2, const Vec2& moving_pivot, double offset);

/// Three positions, moving pivot chosen (Norton Ex. 3-5): the ground pivot is the centre of the
/// circle through the moving pivot's three positions. @throws NoSolution if they are collinear.
Dyad dyad_from_moving_pivot(std::span<const Pose> poses, const Vec2& moving_pivot);

/// Three positions, ground pivot chosen (Norton Ex. 3-7, the inversion): seen from the coupler,
/// the ground pivot's three positions lie on a circle about the moving pivot.
/// @throws NoSolution if those positions are collinear.
Dyad dyad_from_ground_pivot(std::span<const Pose> poses, const Vec2& ground_pivot);

/// Three positions, analytical with free choices (Norton sec. 5.6): the dyad's rotations
/// beta2, beta3 [rad] from pose 1 to poses 2 and 3; solves the 2x2 complex dyad equations for
/// W (crank vector, ground -> moving pivot) and Z (moving pivot -> P) in pose 1.
/// @throws NoSolution if the equations are singular (e.g. beta_j equal to the coupler's alpha_j).
Dyad dyad_from_rotations(std::span<const Pose> poses, double beta2, double beta3);

/// A synthesised motion generator and its checks.
struct MotionCandidate {
  FourBar linkage;               ///< crank from the first dyad; coupler point = the poses' point
  std::vector<double> theta2;    ///< crank angle at each pose [rad]
  std::vector<int> branches;     ///< branch_of() at each pose as constructed
  DefectReport defects;
  TransmissionRange transmission;  ///< over the crank's travel through the poses
  double link_ratio = 0;         ///< longest / shortest of ground, crank, coupler, rocker
};

/// Assembles the four-bar of two dyads (the first drives) and checks it through the poses.
/// @throws NoSolution if a dyad is degenerate (zero-length crank, rocker or coupler, pivots
///         together).
MotionCandidate four_bar_from_dyads(std::span<const Pose> poses, const Dyad& input, const Dyad& output,
                                    bool require_crank);

/// Ranks candidates: defect-free first, then a link ratio within `max_link_ratio`, then the
/// largest minimum transmission angle. @returns true if `a` is better than `b`.
bool better_candidate(const MotionCandidate& a, const MotionCandidate& b, double max_link_ratio);

/// The best four-bar of any ordered pair of `dyads` (first drives): every pair screened at the
/// poses, the best few checked over the crank's whole travel. Dyads with a pivot more than five
/// times the poses' spread from their centre are left out (the linkage would dwarf its task).
/// @throws NoSolution if no pair assembles.
MotionCandidate best_pair_of_dyads(std::span<const Pose> poses, std::span<const Dyad> dyads, double max_link_ratio,
                                   bool require_crank);

/// Search limits of the automatic choices below (docs/cli.md).
inline constexpr int kMaxTwoPositionGrid = 200;
inline constexpr int kMaxThreePositionGrid = 40;

/// Two positions with the moving pivots given and the free choices (the bisector offsets) left
/// to a search over `grid` x `grid` offsets within +-2 chord lengths for the best candidate.
/// @throws std::invalid_argument if grid is outside 2..kMaxTwoPositionGrid; NoSolution if every
///         candidate is degenerate.
MotionCandidate best_two_position(std::span<const Pose> poses, const Vec2& input_moving_pivot,
                                  const Vec2& output_moving_pivot, int grid, double max_link_ratio,
                                  bool require_crank);

/// Three positions with every free choice left open: moving pivots on a `grid` x `grid` lattice
/// over the poses' extent (enlarged by their span), dyads by circumcentres, every ordered pair
/// screened at the poses and the best few checked over the whole travel.
/// @throws std::invalid_argument if grid is outside 2..kMaxThreePositionGrid; NoSolution if no
///         pair assembles.
MotionCandidate best_three_position(std::span<const Pose> poses, int grid, double max_link_ratio,
                                    bool require_crank);

}  // namespace gearkit::synth
