#pragma once
// A cam's motion program: the follower coordinate s against the cam angle theta over one turn,
// as a chain of segments (rise, dwell, return, or a table of points). s is a length [mm] for a
// translating follower and an angle [rad] for an oscillating one; theta is in radians and runs
// in the sense the cam turns. Derivatives are per radian of cam angle; per_second() turns them
// into velocity, acceleration and jerk for a cam speed omega [rad/s].
#include <gearkit/cam/motion_law.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace gearkit::cam {

enum class SegmentKind { rise, dwell, fall, table };

enum class TableEnds {
  zero_slope,  ///< ds/dtheta = 0 at both ends (joins dwells without a velocity jump)
  natural,     ///< d2s/dtheta2 = 0 at both ends
  periodic,    ///< s, v, a continuous across the ends (the table covers the whole turn)
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
  std::vector<TablePoint> table;  ///< table: points from start to end, interpolated by a cubic spline
  TableEnds table_ends = TableEnds::zero_slope;
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

/// A validated motion program, ready to evaluate.
class MotionProgram {
 public:
  /// Checks and prepares the segments.
  /// @throws ProgramError if there is no segment; a segment has end <= start (zero duration);
  ///         segments leave a gap or overlap (each must start where the previous ended) or do not
  ///         cover exactly 360 deg; a rise or fall has lift <= 0 or non-finite; a fall goes below
  ///         the base level (s < 0); the program does not end at the level it started (s = 0);
  ///         a table has fewer than 2 points, angles not strictly increasing from start to end,
  ///         a first value different from the level reached so far, or periodic ends without
  ///         covering the whole turn.
  explicit MotionProgram(std::vector<Segment> segments);

  /// s and derivatives at cam angle theta [rad] (any real; taken modulo one turn).
  Motion at(double theta) const;
  /// The limit from the left at a segment boundary (for continuity checks).
  Motion left_limit(std::size_t segment_end_of) const;

  const std::vector<Segment>& segments() const { return segments_; }
  double start() const { return segments_.front().start; }
  /// Largest s over the turn (the total lift).
  double max_s() const { return max_s_; }

 private:
  Motion eval_segment(std::size_t i, double theta) const;

  std::vector<Segment> segments_;
  std::vector<double> level_;  // s at the start of each segment
  struct Spline {
    std::vector<double> x, y, m;  // knots and second derivatives
  };
  std::vector<Spline> splines_;   // one per segment (empty unless a table)
  double max_s_ = 0;
};

/// A jump of s, velocity or acceleration where two segments meet.
struct JoinJump {
  double theta = 0;         ///< cam angle of the join [rad]
  std::string quantity;     ///< "displacement", "velocity" or "acceleration"
  double before = 0, after = 0;  ///< per radian (or per radian^2)
};

/// Every discontinuity in s, ds/dtheta, d2s/dtheta2 at the joins (the wrap-around join included),
/// beyond a relative tolerance of the program's scale.
std::vector<JoinJump> continuity_check(const MotionProgram& program);

}  // namespace gearkit::cam
