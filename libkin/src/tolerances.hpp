#pragma once
// The numerical tolerances of libkin's solver, in one place (internal: no header outside
// libkin/src includes it). Each says what it decides and what goes wrong when it is too small
// and when it is too large, as SolveSpace's system.cpp explains its rank tolerance. They are
// dimensionless unless a unit is given; "rcond" is the reciprocal condition estimate of Phi_q
// (Data::rcond: KLU's pivot ratio, or its 1-norm estimate below kCheapRcondLimit; the spread of
// the pivots of the QR for redundant models).
//
// The user-facing tolerances are options, not constants: SolverOptions::tolerance (on max |Phi|,
// 1e-10 m or rad) and SweepOptions::min_step (1e-10 of the input's unit).
//
// Two constants were once both called kSingularRcond (1e-13 in jacobian_lu.cpp, 1e-6 in
// sweep.cpp). They are different tests, not one value set twice: kSingularRcond is absolute
// (is this matrix invertible in double precision?), kBranchSingularFraction is relative to the
// best conditioning met on a sweep's branch (has the sweep reached a singular position of this
// mechanism?). Their names now say so.

namespace gearkit::kin::tolerance {

// --- Factorisation (jacobian_lu.cpp, solve.cpp) ----------------------------------------------

/// A Jacobian whose rcond is at or below this is singular: no step is taken with it. Too small
/// (toward the 2.2e-16 of double rounding) and a numerically singular Phi_q at a toggle is
/// accepted, its Newton step carries an error of about eps / rcond (here up to 2e-3 relative)
/// and may leap to another assembly branch; too large and a regular but badly scaled mechanism
/// (links of 1 mm and 10 m, a long chain) is refused as locked. 1e-13 leaves three digits of
/// margin over rounding, and the sweep's own, stricter tests below catch the approach to a
/// singular position long before it.
constexpr double kSingularRcond = 1e-13;

/// A refactorisation keeps the pivots of the last full factorisation (the fast path of a
/// sweep); once the pivot ratio has dropped by this factor since then, pivots are chosen again.
/// Too small and stale pivots are kept while growing element growth costs accuracy near a
/// toggle; too large and nearly every position of a sweep pays the full pivot search.
constexpr double kPivotDecay = 1e-3;

/// Below this pivot ratio the cheap rcond (the spread of U's diagonal) is replaced by KLU's
/// 1-norm condition estimate. The pivot ratio can overstate the conditioning by orders of
/// magnitude, but only matters near the singular tests; too small and a singular Jacobian is
/// judged by the crude ratio; too large and every well-conditioned position pays the estimate
/// (a solve with Phi_q and one with its transpose).
constexpr double kCheapRcondLimit = 1e-4;

/// Column-pivoting QR of redundant models (more equations than coordinates): a pivot below this
/// fraction of the largest is zero (Eigen's setThreshold). Too small and the rounding left of
/// an exactly redundant row (a parallelogram's extra link, ~1e-16) counts as rank, making the
/// consistent model look over-determined and its least-squares step meaningless; too large and
/// a nearly dependent but real constraint (a link almost in line) is dropped and its equation
/// silently ignored. 1e-10 sits midway in decades between the two.
constexpr double kQrRankThreshold = 1e-10;

/// Relative threshold of the mobility rank tests (dof.cpp): a constraint row is dependent when
/// what is left of it, after removing its components along the rows before it, is below this
/// fraction of the largest row norm. Too small and rounding makes a redundant constraint of a
/// drawn configuration count as independent (a wrong, too small mobility); too large and a
/// drawing close to a singular position reports a redundancy it does not have.
constexpr double kRankTolerance = 1e-9;

// --- Continuation (sweep.cpp) ----------------------------------------------------------------

/// An absolute floor of rcond for a position the sweep keeps as an anchor (a regular solution
/// on the branch). Newton "at" a singular position converges to within sqrt(tolerance) of it,
/// where rcond is of the order of sqrt(tolerance); a position at 1e-10 is far closer still and
/// its tangent is noise. Too small and such a position anchors the predictor, which then extrapolates a
/// meaningless tangent; too large and a mechanism that is merely badly scaled cannot be swept.
constexpr double kRegularRcond = 1e-10;

/// A configuration whose rcond is below this fraction of the best rcond met on its branch is
/// taken as singular and the sweep crosses it (cross()) instead of stepping onto it. Relative,
/// because a mechanism's conditioning is set by its proportions. Too small and steps land
/// within ~1e-12 of a change point, where the tangent dq is any solution of a nearly singular
/// system and the sweep may leave its branch unnoticed; too large and regular positions of a
/// mechanism that passes close to a toggle are taken as dead points. 1e-6 stops the
/// continuation about 1e-6 rad from a change point, where the Hermite crossing is accurate.
constexpr double kBranchSingularFraction = 1e-6;

/// Largest fall of rcond over one step: approaching a singular point by halving divides it by
/// about 2 per step, a step landing on one divides it by orders of magnitude. Too small (a
/// larger allowed fall) and a step that lands on a change point is kept and the branch is lost;
/// too large and regular steps toward a toggle are refused and halved needlessly (slower).
constexpr double kConditioningDrop = 1e-3;

/// The same test for the sweep's first position against the position one step further:
/// conditioning grows linearly with the distance from a change point, so a start within a
/// hundredth of a step of one has rcond below this fraction and is taken as on it. Too small
/// and a start on a flat parallelogram is taken as regular (its tangent is meaningless); too
/// large and a regular start near a change point is needlessly extrapolated.
constexpr double kStartConditioningDrop = 1e-2;

/// Largest relative change of the tangent dq/d(input) that a step may show against its
/// prediction: a regular step's tangent is predicted to O(h^2) (O(h) without history), while a
/// jump to another branch through a bifurcation changes it at first order (a parallelogram's
/// rocker turns with the crank, an anti-parallelogram's does not). The driven coordinate's own
/// entry is 1, so the norm is never small. Too small and fine regular steps are refused on
/// curvature alone (the sweep crawls); too large and a branch switch through a bifurcation
/// passes unnoticed.
constexpr double kTangentJump = 0.1;
constexpr double kTangentJumpWithoutHistory = 0.3;

/// Largest change of any angle coordinate [rad] between a step's prediction and its solution.
/// A step whose Newton solution lies farther from its O(h^3) prediction has landed on another
/// assembly (the mirror image of a four-bar's coupler). Too small and the first steps of a
/// sweep, predicted only to first order, are halved needlessly; too large and Newton's leap to
/// the other assembly branch is kept.
constexpr double kMaxAngleFromPrediction = 0.1;

/// Solves around a change point are this much tighter than SolverOptions::tolerance: Newton's
/// residual test leaves an error of about tolerance / sigma_min in q, sigma_min ~ the distance
/// to the point, and the Hermite extrapolations across the point need the anchors exact. Too
/// large (looser) and the crossing lands off the branch and is refused; too small and the
/// tolerance falls below rounding of the residual and Newton never converges.
constexpr double kTightFactor = 1e-3;

}  // namespace gearkit::kin::tolerance
