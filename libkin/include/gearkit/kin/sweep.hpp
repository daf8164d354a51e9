#pragma once
// Sweeps of one driver's input over a range, keeping the assembly branch continuous, with dead
// points (where the driver can no longer move the mechanism) and the extremes of chosen outputs
// (limit positions) located precisely.
#include <gearkit/kin/output.hpp>
#include <gearkit/kin/solve.hpp>
#include <functional>
#include <string>
#include <vector>

namespace gearkit::kin {

struct SweepOptions {
  int driver = 0;            ///< index in Model::drivers()
  double start = 0.0;        ///< first input value [rad or m]
  double end = 0.0;          ///< last input value
  double step = 0.0;         ///< spacing of the samples (sign is taken from end - start); > 0
  SolverOptions solver;
  std::vector<Output> outputs;  ///< their extremes are located
  /// Smallest continuation step [same unit as the input] before a failure to continue is
  /// declared a dead point; also the precision of the dead point's input.
  double min_step = 1e-10;
  bool velocities = true;    ///< also solve qd and qdd at every sample
  /// At each change point crossed, go on along the other branch through it instead of the one
  /// whose tangent continues the motion (a parallelogram folding into an anti-parallelogram).
  bool switch_branch = false;
};

struct SweepSample {
  double input = 0.0;
  Eigen::VectorXd q, qd, qdd;
  Eigen::VectorXd dq;  ///< input sensitivity dq/d(input) at the sample (velocity ratios)
  int iterations = 0;
  /// The sample lies on a change point (interpolated, see sweep()): Phi_q is singular there, so
  /// the reactions are statically indeterminate; dq is the tangent of the branch followed.
  bool on_change_point = false;
  /// The sweep's own workspace when it is factorised at this sample (q, qd, qdd and the inputs
  /// set, Phi_q factorised at q), else null (an interpolated sample, or one after an extreme was
  /// located). A visitor may solve with that factorisation (kin::solve_forces, input_sensitivity)
  /// to save a factorisation per position, but must not refactorise it or change q, qd or qdd:
  /// the sweep's next step starts from it.
  Data* data = nullptr;
};

/// A configuration where the driven coordinate cannot go on: the dependent Jacobian turns
/// singular (toggle or limit position of the input, a change point).
struct DeadPoint {
  double input = 0.0;        ///< located to options.min_step
  Eigen::VectorXd q;         ///< the last assembled configuration before it
  std::string description;
};

/// A located extreme of an output over the input (a limit position of that output, where its
/// velocity ratio to the input vanishes).
struct OutputExtreme {
  int output = 0;            ///< index in SweepOptions::outputs
  bool maximum = false;
  double input = 0.0;        ///< where the derivative vanishes (secant/bisection to 1e-12)
  double value = 0.0;        ///< the output there
  Eigen::VectorXd q;         ///< configuration there
  Eigen::VectorXd dq;        ///< dq/d(input) there: velocity ratios
};

/// A singular configuration the sweep crossed (or started on) where the driver does move the
/// mechanism on: usually a bifurcation, where two branches of the motion meet (the flat
/// position of a four-bar with s + l = p + q); the sweep goes on along the branch whose tangent
/// dq/d(input) continues the one before, unless SweepOptions::switch_branch. Also a position
/// where the Jacobian loses rank on the only branch (a triple parallelogram lying flat).
struct ChangePoint {
  double input = 0.0;        ///< located to SweepOptions::min_step
  Eigen::VectorXd q;         ///< the configuration there
  bool bifurcation = false;  ///< another branch passes here (else a singular position on the only one)
  bool switched = false;     ///< the sweep went on along the other branch
};

struct SweepResult {
  std::vector<SweepSample> samples;      ///< in sweep order; stops at a dead point
  std::vector<DeadPoint> dead_points;
  std::vector<ChangePoint> change_points;  ///< crossed, in sweep order
  std::vector<OutputExtreme> extremes;
  bool assembled = false;                ///< false if the first input could not be assembled
  bool complete = false;                 ///< true if the sweep reached `end`
  std::string message;                   ///< why it stopped early; empty if complete
};

/// Sweeps driver `options.driver` from start to end. The first position is assembled from
/// data.q (the drawn configuration or a user's guess, which picks the branch). Each next
/// position starts from a second-order prediction along the input sensitivity; a step that
/// does not converge, changes the sign of det(Phi_q), jumps more than 0.1 rad beyond the
/// prediction or whose tangent dq/d(input) departs from the predicted one by more than 10 %
/// (it landed on another branch) is halved, down to options.min_step. There the configuration
/// is singular. At a change point (a bifurcation) the sweep goes on (see ChangePoint): the
/// branch is re-solved a little past the point from a Hermite extrapolation of two regular
/// anchors before it and kept if its tangent continues theirs; a sample that falls on the
/// point is interpolated between the anchors either side (q to O(h^4), qd and qdd to O(h^2),
/// h <= 1e-2 of the step). Otherwise (a toggle or limit position: nothing lies beyond) a dead
/// point is declared and the sweep stops (it never jumps across a toggle to another branch).
/// A start on a change point is assembled just past it, nearest data.q. The other drivers keep
/// their data.inputs values. Bounded: at most ~60 halvings of max_iterations each per sample.
/// Numerical failure (no assembly, a dead point) is reported in the result, never thrown.
/// @param options  driver index, start/end/step [rad or m, the driver's input unit], solver
///   options, outputs whose extremes are located
/// @throws DataMismatch if `data` was not made for `model` as it is now; std::invalid_argument
///   if options.driver is not an index of Model::drivers() or options.step is not > 0.
SweepResult sweep(const Model& model, Data& data, const SweepOptions& options);

/// The same into `result`, whose samples are overwritten in place: sweeping the same model
/// again (an optimiser, an animation) then reuses their storage instead of allocating.
/// @throws as the function above.
void sweep(const Model& model, Data& data, const SweepOptions& options, SweepResult& result);

/// Receives each sample as the sweep reaches it, in sweep order. The sample (and its vectors)
/// is reused for the next one: copy what must outlive the call. The visitor must not touch the
/// sweep's Data (use a Data of its own to analyse the sample further).
using SampleVisitor = std::function<void(const SweepSample&)>;

/// The same sweep streamed: each sample goes to `visit` and none is kept (result.samples is
/// left as it was), so memory does not grow with the number of samples; dead points, extremes
/// and the outcome are in `result` as above.
/// @throws as the functions above, and whatever `visit` throws (the sweep stops there).
void sweep(const Model& model, Data& data, const SweepOptions& options, SweepResult& result, const SampleVisitor& visit);

/// How far from a change point the sweep takes its branch up again [input unit]: far enough
/// that Phi_q there is well conditioned (its smallest singular value grows with the distance),
/// near enough that the Hermite extrapolation across is exact to round-off, and within a quarter
/// of the step so that no sample is skipped: min(step / 4, max(step / 100, 1e-5)). A sweep that
/// starts on a change point assembles at twice this past the start (a caller that reaches the
/// start by continuation from a drawing should stop there to keep the drawing's branch).
/// Never throws.
double change_point_offset(const SweepOptions& options);

/// The number of samples the sweep plans: floor(|end - start| / step) + 1 (fewer if it stops at
/// a dead point). Requires options.step > 0 (not checked: the result is meaningless otherwise).
/// Never throws.
long sweep_sample_count(const SweepOptions& options);

/// Assembles at input `value` of driver `driver` (starting from data.q), then solves velocity
/// and acceleration. @returns the position report; qd/qdd are valid only if it converged and
/// the Jacobian is regular.
/// @param driver  index in Model::drivers()
/// @param value  the driver's input [rad or m]
/// @throws DataMismatch if `data` was not made for `model` as it is now; std::invalid_argument
///   if `driver` is not an index of Model::drivers().
PositionReport solve_at(const Model& model, Data& data, int driver, double value, const SolverOptions& options = {});

}  // namespace gearkit::kin
