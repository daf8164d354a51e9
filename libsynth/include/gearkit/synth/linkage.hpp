#pragma once
// The linkages synthesis produces, in closed form: the four-bar O2-A-B-O4 with a coupler point
// and the offset slider-crank. Position analysis, the crank's assemblable range, transmission
// angles and the defect checks (branch, order, Grashof) every synthesised candidate goes through.
// SI units throughout (m, rad); angles are global, counter-clockwise from the x axis.
#include <Eigen/Core>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace gearkit::synth {

using Vec2 = Eigen::Vector2d;

/// A four-bar with ground pivots O2 (input crank) and O4 (output rocker) and a coupler point P.
/// The coupler's frame has its origin at A and its x axis along A -> B.
struct FourBar {
  Vec2 O2{0, 0}, O4{0, 0};   ///< ground pivots [m]
  double crank = 0;          ///< a = |O2 A| [m]
  double coupler = 0;        ///< b = |A B| [m]
  double rocker = 0;         ///< c = |O4 B| [m]
  Vec2 coupler_point{0, 0};  ///< P in the coupler frame [m]
  /// Assembly branch: +1 when B lies left of the directed line A -> O4, -1 when right. Driven by
  /// the crank, the linkage can only change branch through a toggle (coupler and rocker in line).
  int branch = 1;

  double ground() const { return (O4 - O2).norm(); }  ///< d = |O2 O4| [m]
  double ground_angle() const;                         ///< theta1, direction of O2 -> O4 [rad]
};

/// One assembled configuration of a FourBar.
struct FourBarPose {
  double theta2 = 0, theta3 = 0, theta4 = 0;  ///< crank, coupler (A -> B), rocker (O4 -> B) [rad]
  Vec2 A{0, 0}, B{0, 0}, P{0, 0};             ///< joint and coupler-point positions [m]
};

/// The configuration at crank angle `theta2` [rad] on the linkage's branch.
/// @returns nullopt where the loop cannot close (|A O4| outside [|b - c|, b + c]).
std::optional<FourBarPose> pose_at(const FourBar& linkage, double theta2);

/// Branch (+1 or -1) of the configuration with joints A, B and rocker pivot O4; 0 when B lies on
/// the line A O4 (a toggle).
int branch_of(const Vec2& A, const Vec2& B, const Vec2& O4);

/// Transmission angle [rad] in [0, pi/2]: the acute angle between coupler and rocker.
double transmission_angle(const FourBarPose& pose, const FourBar& linkage);

/// A counter-clockwise range of crank angles [rad]: from `start` through `start + length`.
struct AngleInterval {
  double start = 0, length = 0;  ///< length in (0, 2 pi]; 2 pi = the crank turns fully
};

/// Where the loop closes as the crank turns: one interval of length 2 pi for a crank that turns
/// fully, otherwise the one or two ranges between its toggle positions. Empty if nowhere.
std::vector<AngleInterval> crank_range(const FourBar& linkage);

/// True if the crank turns fully (Grashof, crank or ground the shortest link).
bool crank_turns_fully(const FourBar& linkage);

/// Angle `a` [rad] brought into [0, 2 pi).
double wrap_two_pi(double a);

/// The outcome of the defect checks of one candidate.
struct DefectReport {
  bool branch_defect = false;   ///< precision positions on different branches, or a toggle between them
  bool order_defect = false;    ///< the crank meets the positions out of order
  bool grashof_defect = false;  ///< a turning crank was required and the crank does not turn fully
  int direction = 1;            ///< +1 crank turns counter-clockwise from position 1 to N, -1 clockwise
  double travel = 0;            ///< crank rotation from the first to the last position [rad] (>= 0)
  std::vector<std::string> notes;  ///< one line per defect found, empty when none
  bool ok() const { return !branch_defect && !order_defect && !grashof_defect; }
};

/// Checks that the crank, turning one way, carries the linkage through the precision
/// configurations in order without changing branch or passing a toggle.
/// @param theta2  crank angle of each precision configuration [rad], in task order (>= 2)
/// @param branches branch_of() each precision configuration as constructed (same size)
/// @param require_crank also demand a crank that turns fully (a motor drives it)
/// @throws std::invalid_argument if the sizes differ or fewer than two positions are given.
DefectReport check_defects(const FourBar& linkage, std::span<const double> theta2, std::span<const int> branches,
                           bool require_crank);

/// Smallest and largest transmission angle [rad] while the crank turns from `theta2_start` by
/// `travel` [rad] in `direction` (+1 ccw, -1 cw), sampled every 0.5 deg and at both ends.
/// Positions where the loop does not close are skipped.
struct TransmissionRange {
  double min = 0, max = 0;
};
TransmissionRange transmission_range(const FourBar& linkage, double theta2_start, double travel, int direction);

/// An offset slider-crank: crank O2 A, connecting rod A B, slider pin B on a straight guide.
/// Slider position s is measured along the guide from the foot of O2; the pin runs at the signed
/// distance `offset` to the left of the guide line through O2.
struct SliderCrank {
  Vec2 O2{0, 0};            ///< crank pivot [m]
  double crank = 0;         ///< a = |O2 A| [m]
  double rod = 0;           ///< b = |A B| [m]
  double offset = 0;        ///< e [m]
  double axis_angle = 0;    ///< direction of the guide [rad]
  int branch = 1;           ///< +1: B ahead of A along the guide, -1: behind
};

/// Slider position s [m] at crank angle theta2 [rad], or nullopt where the rod cannot reach.
std::optional<double> slider_position(const SliderCrank& linkage, double theta2);

}  // namespace gearkit::synth
