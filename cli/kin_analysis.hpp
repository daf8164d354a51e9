#pragma once
// `gearkit kin`: the analysis results of one run, independent of how they are printed.
#include <gearkit/mechanism/reader.hpp>
#include <gearkit/kin/dof.hpp>
#include <gearkit/kin/fourbar.hpp>
#include <gearkit/kin/kinetostatics.hpp>
#include <gearkit/kin/sweep.hpp>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace gearkit::cli {

/// Everything computed at one input value.
struct KinPosition {
  double input = 0.0;  ///< [rad or m]
  Eigen::VectorXd q, qd, qdd;
  std::vector<kin::OutputValue> outputs;
  std::vector<double> output_ratios;       ///< d(output)/d(input)
  std::optional<double> transmission_angle;  ///< [rad], four-bars only
  std::optional<kin::ForceAnalysis> forces;  ///< when the model has loads
  /// The sweep's last position, where it stopped at a dead point: the driver cannot move the
  /// mechanism there, so the effort (and the velocities) grow without bound as it is approached
  /// and the value computed at the located input (about 1e15 N m) means nothing. Tables and JSON
  /// keep the row (docs/kin.md); the plot leaves it out.
  bool at_dead_point = false;
  bool on_change_point = false;  ///< interpolated on a change point: Lagrange effort and reactions not given
};

/// What an analysis keeps. A sweep streams its positions (PositionSink) and keeps none here;
/// the single-position analysis keeps its one position, and the animation is handed its frames
/// in `positions`.
struct KinAnalysis {
  kin::DofReport dof;
  int driver = 0;
  std::vector<KinPosition> positions;
  std::vector<kin::DeadPoint> dead_points;
  std::vector<kin::ChangePoint> change_points;  ///< crossed by the sweep, or on the way to --at
  std::vector<kin::OutputExtreme> extremes;
  std::vector<std::string> warnings;
  std::vector<std::string> notes;  ///< change points crossed: not a problem, but worth saying
  std::vector<std::optional<Eigen::Vector2d>> instant_centres;  ///< per body, single position only
  bool single = false;
};

/// Fills `p` from a solved Data (q, qd, qdd set; factorised at q when `dq` is null or the model
/// has loads), reusing p's storage. `four_bar`: the model's four-bar (kin::find_four_bar), for the
/// transmission angle; `dq`: the input sensitivity when known (a sweep has it), else solved.
/// `on_change_point`: the position is a change point the sweep crossed (Phi_q singular): the
/// driving effort is then by virtual power along `dq` alone, the reactions are indeterminate.
void describe_position(const mechanism::Mechanism& mech, const std::optional<kin::FourBar>& four_bar, kin::Data& data,
                       int driver, double input, const Eigen::VectorXd* dq, KinPosition& p, bool on_change_point = false);

/// Receives each position of a sweep as it is solved, in order; the position is reused for the
/// next one (copy what must outlive the call).
using PositionSink = std::function<void(const KinPosition&)>;

/// One position at `at` (the drawn input when absent), reached by continuation from the drawn
/// configuration so that it stays on the drawing's assembly branch. `dof` is the mobility found
/// at the drawing. Problems (unreachable input, dead point) are warnings with no position.
/// `switch_branch`: at a change point on the way, go on along the other branch
/// (kin::SweepOptions::switch_branch).
KinAnalysis analyse_single(const mechanism::Mechanism& mech, kin::Data& data, int driver, std::optional<double> at,
                           const kin::DofReport& dof, bool switch_branch = false);

/// A sweep of the driver over `range`: each position goes to `sink` as it is solved, so memory
/// does not grow with the number of positions; the result holds dead points, extremes and
/// warnings, no positions.
KinAnalysis analyse_sweep(const mechanism::Mechanism& mech, kin::Data& data, int driver, const mechanism::DriverRange& range,
                          const kin::DofReport& dof, const PositionSink& sink, bool switch_branch = false);

/// The SVG animation of the mechanism through the positions (SMIL, loops forever): links, joints,
/// ground, slider blocks on their guides, names, output point traces (kin_animation_elements.hpp).
/// One loop takes the sweep at `input_speed` (rad/s or m/s, from --speed), else a stated default.
std::string animation_svg(const mechanism::Mechanism& mech, const KinAnalysis& analysis,
                          std::optional<double> input_speed = std::nullopt);

}  // namespace gearkit::cli
