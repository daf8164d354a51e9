#include <gearkit/cam/motion_program.hpp>

#include <Eigen/Dense>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gearkit::cam {
namespace {

constexpr double two_pi = 2 * std::numbers::pi;
constexpr double kAngleTol = 1e-9;  // rad: joins closer than this are the same angle

/// An angle in degrees for messages: "300", not "300.00000000000006".
std::string deg(double rad) { return fmt::format("{:.6g}", rad * 180 / std::numbers::pi); }

/// Second derivatives M of the interpolating cubic spline through (x, y), from the continuity of
/// the first derivative at the inner knots plus the end conditions (de Boor, "A Practical Guide to
/// Splines", ch. IV). Small systems (tables have tens of points), so a dense LU is enough.
std::vector<double> spline_second_derivatives(const std::vector<double>& x, const std::vector<double>& y,
                                              TableEnds ends) {
  const int n = static_cast<int>(x.size());
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
  auto h = [&](int i) { return x[i + 1] - x[i]; };
  auto slope = [&](int i) { return (y[i + 1] - y[i]) / h(i); };
  for (int i = 1; i + 1 < n; ++i) {
    A(i, i - 1) = h(i - 1);
    A(i, i) = 2 * (h(i - 1) + h(i));
    A(i, i + 1) = h(i);
    b(i) = 6 * (slope(i) - slope(i - 1));
  }
  switch (ends) {
    case TableEnds::natural:
      A(0, 0) = 1;
      A(n - 1, n - 1) = 1;
      break;
    case TableEnds::zero_slope:
      A(0, 0) = 2 * h(0), A(0, 1) = h(0), b(0) = 6 * slope(0);
      A(n - 1, n - 2) = h(n - 2), A(n - 1, n - 1) = 2 * h(n - 2), b(n - 1) = -6 * slope(n - 2);
      break;
    case TableEnds::periodic:
      // M_0 = M_{n-1}, and the slope at the last knot equals the slope at the first.
      A(n - 1, 0) = 1, A(n - 1, n - 1) = -1;
      A(0, 0) = 2 * (h(0) + h(n - 2)), A(0, 1) = h(0), A(0, n - 2) = h(n - 2);
      b(0) = 6 * (slope(0) - slope(n - 2));
      break;
  }
  const Eigen::VectorXd m = A.partialPivLu().solve(b);
  return {m.data(), m.data() + n};
}

}  // namespace

MotionPerSecond per_second(const Motion& m, double omega) {
  return {m.s, m.ds * omega, m.d2s * omega * omega, m.d3s * omega * omega * omega};
}

MotionProgram::MotionProgram(std::vector<Segment> segments) : segments_(std::move(segments)) {
  if (segments_.empty()) throw ProgramError(-1, "the motion program has no segments");
  // s = 0 is the base circle; a program that opens with a table starts at the table's first value.
  const Segment& first = segments_.front();
  const double start_level = first.kind == SegmentKind::table && !first.table.empty() ? first.table.front().s : 0;
  double level = start_level;
  for (std::size_t i = 0; i < segments_.size(); ++i) {
    Segment& seg = segments_[i];
    const int idx = static_cast<int>(i);
    if (!std::isfinite(seg.start) || !std::isfinite(seg.end)) throw ProgramError(idx, "angles must be finite");
    if (seg.end - seg.start <= kAngleTol) {
      throw ProgramError(idx, fmt::format("expected a segment of positive duration, found {} deg to {} deg",
                                          deg(seg.start), deg(seg.end)));
    }
    if (i > 0) {
      const double prev_end = segments_[i - 1].end;
      if (std::abs(seg.start - prev_end) > kAngleTol) {
        throw ProgramError(idx, fmt::format("segment starts at {} deg but the previous one ends at {} deg ({})",
                                            deg(seg.start), deg(prev_end), seg.start > prev_end ? "a gap" : "an overlap"));
      }
      seg.start = prev_end;  // exactly contiguous from here on
    }
    level_.push_back(level);
    splines_.emplace_back();
    switch (seg.kind) {
      case SegmentKind::dwell:
        break;
      case SegmentKind::rise:
      case SegmentKind::fall:
        if (!std::isfinite(seg.lift) || seg.lift <= 0) {
          throw ProgramError(idx, fmt::format("expected a lift > 0, found {}", seg.lift));
        }
        level += seg.kind == SegmentKind::rise ? seg.lift : -seg.lift;
        if (level < -1e-12 * std::max(1.0, max_s_)) {
          throw ProgramError(idx, fmt::format("the return goes {} below the base circle (lift larger than the "
                                              "height reached)", -level));
        }
        break;
      case SegmentKind::table: {
        const auto& t = seg.table;
        const std::size_t min_points = seg.table_ends == TableEnds::periodic ? 3 : 2;
        if (t.size() < min_points) {
          throw ProgramError(idx, fmt::format("expected a table of at least {} points, found {}", min_points, t.size()));
        }
        if (std::abs(t.front().theta - seg.start) > kAngleTol || std::abs(t.back().theta - seg.end) > kAngleTol) {
          throw ProgramError(idx, fmt::format("the table must run from the segment's start ({} deg) to its end "
                                              "({} deg), found {} deg to {} deg",
                                              deg(seg.start), deg(seg.end), deg(t.front().theta), deg(t.back().theta)));
        }
        Spline sp;
        for (std::size_t k = 0; k < t.size(); ++k) {
          if (!std::isfinite(t[k].s) || !std::isfinite(t[k].theta)) throw ProgramError(idx, "table values must be finite");
          if (k > 0 && t[k].theta <= t[k - 1].theta + kAngleTol) {
            throw ProgramError(idx, fmt::format("table angles must increase, found {} deg after {} deg",
                                                deg(t[k].theta), deg(t[k - 1].theta)));
          }
          if (t[k].s < 0) throw ProgramError(idx, fmt::format("table value {} is below the base circle (< 0)", t[k].s));
          sp.x.push_back(t[k].theta);
          sp.y.push_back(t[k].s);
        }
        sp.x.front() = seg.start, sp.x.back() = seg.end;
        const double scale = std::max(1.0, std::abs(t.front().s));
        if (std::abs(t.front().s - level) > 1e-9 * scale) {
          throw ProgramError(idx, fmt::format("the table starts at s = {} but the follower is at {} there",
                                              t.front().s, level));
        }
        if (seg.table_ends == TableEnds::periodic) {
          if (segments_.size() != 1) {
            throw ProgramError(idx, "periodic table ends need a table that covers the whole turn alone");
          }
          if (std::abs(t.back().s - t.front().s) > 1e-9 * scale) {
            throw ProgramError(idx, "a periodic table must end at the value it starts with");
          }
          sp.y.back() = sp.y.front();
        }
        sp.m = spline_second_derivatives(sp.x, sp.y, seg.table_ends);
        level = sp.y.back();
        for (double s : sp.y) max_s_ = std::max(max_s_, s);
        splines_.back() = std::move(sp);
        break;
      }
    }
    max_s_ = std::max(max_s_, level);
  }
  const double total = segments_.back().end - segments_.front().start;
  if (std::abs(total - two_pi) > 1e-7) {
    throw ProgramError(-1, fmt::format("the segments must cover 360 deg, they cover {} deg", deg(total)));
  }
  if (std::abs(level - start_level) > 1e-9 * std::max(1.0, max_s_)) {
    throw ProgramError(-1, fmt::format("the follower must end the turn where it started (s = {}), it ends at s = {}",
                                       start_level, level));
  }
}

Motion MotionProgram::eval_segment(std::size_t i, double theta) const {
  const Segment& seg = segments_[i];
  const double beta = seg.end - seg.start;
  switch (seg.kind) {
    case SegmentKind::dwell:
      return {level_[i], 0, 0, 0};
    case SegmentKind::rise:
    case SegmentKind::fall: {
      const LawValue y = evaluate(seg.law, (theta - seg.start) / beta);
      const double sign = seg.kind == SegmentKind::rise ? 1 : -1;
      const double L = sign * seg.lift;
      return {level_[i] + L * y.y, L * y.dy / beta, L * y.d2y / (beta * beta), L * y.d3y / (beta * beta * beta)};
    }
    case SegmentKind::table: {
      const Spline& sp = splines_[i];
      const auto it = std::upper_bound(sp.x.begin(), sp.x.end(), theta);
      const std::size_t k = std::clamp<std::size_t>(static_cast<std::size_t>(it - sp.x.begin()), 1, sp.x.size() - 1) - 1;
      const double h = sp.x[k + 1] - sp.x[k];
      const double a = sp.x[k + 1] - theta, b = theta - sp.x[k];
      const double m0 = sp.m[k], m1 = sp.m[k + 1];
      const double c0 = sp.y[k] / h - m0 * h / 6, c1 = sp.y[k + 1] / h - m1 * h / 6;
      return {m0 * a * a * a / (6 * h) + m1 * b * b * b / (6 * h) + c0 * a + c1 * b,
              -m0 * a * a / (2 * h) + m1 * b * b / (2 * h) - c0 + c1, (m0 * a + m1 * b) / h, (m1 - m0) / h};
    }
  }
  return {};
}

Motion MotionProgram::at(double theta) const {
  const double t0 = start();
  double t = t0 + std::fmod(theta - t0, two_pi);
  if (t < t0) t += two_pi;
  std::size_t i = 0;
  while (i + 1 < segments_.size() && t >= segments_[i].end) ++i;
  return eval_segment(i, std::min(t, segments_[i].end));
}

Motion MotionProgram::left_limit(std::size_t i) const { return eval_segment(i, segments_[i].end); }

std::vector<JoinJump> continuity_check(const MotionProgram& program) {
  std::vector<JoinJump> jumps;
  const auto& segs = program.segments();
  const double scale = std::max(program.max_s(), 1e-12);
  for (std::size_t i = 0; i < segs.size(); ++i) {
    const Motion before = program.left_limit(i);
    const Motion after = program.at(segs[i].end);
    const double tol = 1e-9 * scale;
    const double theta = std::fmod(segs[i].end, two_pi);
    auto check = [&](const char* what, double b, double a, double t) {
      if (std::abs(b - a) > t) jumps.push_back({theta, what, b, a});
    };
    check("displacement", before.s, after.s, tol);
    check("velocity", before.ds, after.ds, tol * 10);
    check("acceleration", before.d2s, after.d2s, tol * 100);
  }
  return jumps;
}

}  // namespace gearkit::cam
