#pragma once
// A cam's motion program: the follower coordinate s against the cam angle theta over one turn,
// as a chain of segments (rise, dwell, return, a table of points, or a polynomial from boundary
// conditions). s is a length [mm] for a
// translating follower and an angle [rad] for an oscillating one; theta is in radians and runs
// in the sense the cam turns. Derivatives are per radian of cam angle; per_second() turns them
// into velocity, acceleration and jerk for a cam speed omega [rad/s].
#include <gearkit/cam/motion_law.hpp>

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace gearkit::cam {

enum class SegmentKind { rise, dwell, fall, table, polynomial };

enum class TableEnds {
  zero_slope,  ///< ds/dtheta = 0 at both ends (joins dwells without a velocity jump); bspline:
               ///< velocity, acceleration and jerk 0 (joins dwells smoothly)
  natural,     ///< cubic: d2s/dtheta2 = 0 at both ends; pchip: the shape-preserving three-point
               ///< end slopes; bspline: the ends follow the first and last legs of the points
  periodic,    ///< s, v, a continuous across the ends (the table covers the whole turn)
};

/// How a table's points are joined.
enum class TableInterpolation {
  pchip,    ///< piecewise cubic Hermite with Fritsch-Carlson (Fritsch-Butland) slopes: through the
            ///< points, monotone where they are, never beyond them between two points (so never
            ///< below the base circle); C1: the acceleration jumps at the inner points
  cubic,    ///< interpolating cubic spline, C2; can overshoot between the points (checked)
  bspline,  ///< quintic B-spline with the points as its control polygon: C4 (jerk continuous),
            ///< stays within the points' range and follows their monotony (variation
            ///< diminishing), passes through the first and last point only
};

/// Boundary conditions of a polynomial segment at one end: s (absolute) and its derivatives
/// per radian of cam angle. Given conditions must be consecutive from s: {s}, {s, v},
/// {s, v, a} or {s, v, a, j}.
struct EndConditions {
  std::optional<double> s, v, a, j;
};

struct TablePoint {
  double theta = 0;  ///< cam angle [rad]
  double s = 0;      ///< follower coordinate [mm or rad], absolute
};

struct Segment {
  SegmentKind kind = SegmentKind::dwell;
  double start = 0, end = 0;      ///< cam angles [rad], end > start
  Law law = Law::cycloidal;       ///< rise and fall
  double lift = 0;                ///< rise and fall: change of s, > 0 (a fall goes down by lift)
  std::vector<TablePoint> table;  ///< table: points from start to end
  TableEnds table_ends = TableEnds::zero_slope;
  TableInterpolation interpolation = TableInterpolation::pchip;
  /// polynomial: the conditions at both ends; the degree is their number less one (3..7).
  /// A start without s starts at the level reached.
  EndConditions at_start, at_end;
};

/// How follower values are written in messages: `symbol` after the value times `scale`
/// ({"mm", 1} for translating followers in mm, {"deg", 180/pi} for oscillating ones in rad).
struct ValueUnit {
  std::string symbol;
  double scale = 1;
};

/// An invalid program; `segment` is the index of the offending segment (-1: the whole program).
class ProgramError : public std::invalid_argument {
 public:
  ProgramError(int segment, const std::string& message) : std::invalid_argument(message), segment_(segment) {}
  int segment() const { return segment_; }

 private:
  int segment_;
};

/// s and its derivatives per radian of cam angle.
struct Motion {
  double s = 0, ds = 0, d2s = 0, d3s = 0;
};

/// The same per second: velocity, acceleration and jerk for cam speed omega [rad/s].
struct MotionPerSecond {
  double s = 0, v = 0, a = 0, j = 0;
};
MotionPerSecond per_second(const Motion& m, double omega);

class SegmentCurve;

/// A validated motion program, ready to evaluate. Copies share the prepared segment curves
/// (immutable).
class MotionProgram {
 public:
  /// Checks and prepares the segments; `unit` only formats values in messages.
  /// @throws ProgramError if there is no segment; a segment has end <= start (zero duration);
  ///         segments leave a gap or overlap (each must start where the previous ended) or do not
  ///         cover exactly 360 deg; a rise or fall has lift <= 0 or non-finite; a fall goes below
  ///         the base level (s < 0); the program does not end at the level it started (s = 0);
  ///         a table has fewer than 2 points (bspline: 3; periodic: 3), angles not strictly
  ///         increasing from start to end, a value below 0, a first value different from the
  ///         level reached so far, periodic ends without covering the whole turn or with a
  ///         bspline; a cubic table or a polynomial that dips below the base circle (s < 0)
  ///         between its points (the message gives the lowest value and its cam angle); a
  ///         polynomial without an end value, with conditions that skip an order (a without v),
  ///         with a start value different from the level reached, or non-finite values.
  explicit MotionProgram(std::vector<Segment> segments, ValueUnit unit = {});

  /// s and derivatives at cam angle theta [rad] (any real; taken modulo one turn).
  Motion at(double theta) const;
  /// The limit from the left at a segment boundary (for continuity checks).
  Motion left_limit(std::size_t segment_end_of) const;

  const std::vector<Segment>& segments() const { return segments_; }
  double start() const { return segments_.front().start; }
  /// Largest s over the turn (the total lift).
  double max_s() const { return max_s_; }
  /// Every cam angle inside the turn where a derivative may jump: segment joins (the
  /// wrap-around included, as the end of the last segment), breaks inside laws (parabolic at
  /// half the rise, the modified trapezoid's and modified sine's blends) and a table's inner
  /// points; with the segment they belong to.
  struct Break {
    double theta = 0;      ///< [rad]
    std::size_t segment = 0;
    bool join = false;     ///< the end of the segment (the next one starts here)
    double u = -1;         ///< inside a law: the fraction of the segment; else -1
  };
  std::vector<Break> breaks() const;
  /// The motion just before and just after a break.
  std::pair<Motion, Motion> limits_at(const Break& b) const;
  const ValueUnit& unit() const { return unit_; }
  /// A follower value for messages, with the unit ("4.665 mm").
  std::string value_text(double s) const;

 private:
  Motion eval_segment(std::size_t i, double theta) const;
  Motion law_motion(std::size_t i, double u) const;
  void prepare_segment(std::size_t i, double& level);
  void prepare_table(std::size_t i, double& level);
  void prepare_polynomial(std::size_t i, double& level);
  void check_curve_above_base(std::size_t i, const char* what, const char* advice);

  std::vector<Segment> segments_;
  std::vector<double> level_;  // s at the start of each segment
  std::vector<std::shared_ptr<const SegmentCurve>> curves_;  // tables and polynomials, else null
  ValueUnit unit_;
  double max_s_ = 0;
};

/// A jump of s or of a derivative where two segments meet or inside a segment.
struct JoinJump {
  double theta = 0;         ///< cam angle [rad]
  std::string quantity;     ///< "displacement", "velocity", "acceleration" or "jerk"
  double before = 0, after = 0;  ///< per radian^n
  std::size_t segment = 0;  ///< the segment it ends or lies in
  bool join = true;         ///< at a segment join (else inside a law or a table)
};

/// Every discontinuity in s, ds/dtheta, d2s/dtheta2 and d3s/dtheta3 at the program's breaks
/// (joins, the wrap-around join included, breaks inside laws and tables), beyond a relative
/// tolerance of the program's scale.
std::vector<JoinJump> continuity_check(const MotionProgram& program);

/// The breaks where ds/dtheta jumps (the "velocity" jumps of continuity_check): there the pitch
/// curve has a corner.
std::vector<MotionProgram::Break> velocity_jumps(const MotionProgram& program);

/// Where a table's curve leaves the range of its points: the largest excess above the
/// highest point of the table (s_peak > max point), for interpolants that can overshoot
/// (cubic). Dips below the base circle are errors (see MotionProgram).
struct Overshoot {
  std::size_t segment = 0;
  double theta = 0;     ///< [rad]
  double s = 0;         ///< the curve's value there
  double limit = 0;     ///< the highest (or lowest) table value
};
std::vector<Overshoot> table_overshoots(const MotionProgram& program);

/// B-spline tables: the largest distance |s(theta_i) - s_i| from the table's points (the curve
/// only approximates them), per table segment; 0 for interpolating tables.
double table_fit_residual(const MotionProgram& program, std::size_t segment);

}  // namespace gearkit::cam
