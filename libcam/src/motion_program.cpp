#include <gearkit/cam/motion_program.hpp>

#include "extremum.hpp"
#include "segment_curve.hpp"

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

/// The extreme value of a segment curve over [a, b]: the largest of sign * s.
detail::Peak curve_extreme(const SegmentCurve& c, double a, double b, double sign) {
  const int samples = 32 * static_cast<int>(c.inner_breaks().size() + 1);
  return detail::find_maximum([&](double t) { return sign * c.at(t).s; }, a, b, samples, 1e-10 * (b - a));
}

}  // namespace

MotionPerSecond per_second(const Motion& m, double omega) {
  return {m.s, m.ds * omega, m.d2s * omega * omega, m.d3s * omega * omega * omega};
}

MotionProgram::MotionProgram(std::vector<Segment> segments, ValueUnit unit)
    : segments_(std::move(segments)), unit_(std::move(unit)) {
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
    curves_.emplace_back();
    prepare_segment(i, level);
    max_s_ = std::max(max_s_, level);
  }
  const double total = segments_.back().end - segments_.front().start;
  if (std::abs(total - two_pi) > 1e-7) {
    throw ProgramError(-1, fmt::format("the segments must cover 360 deg, they cover {} deg", deg(total)));
  }
  if (std::abs(level - start_level) > 1e-9 * std::max(1.0, max_s_)) {
    throw ProgramError(-1, fmt::format("the follower must end the turn where it started (s = {}), it ends at s = {}",
                                       value_text(start_level), value_text(level)));
  }
}

std::string MotionProgram::value_text(double v) const {
  const double shown = v * unit_.scale;
  return unit_.symbol.empty() ? fmt::format("{:.6g}", shown) : fmt::format("{:.6g} {}", shown, unit_.symbol);
}

void MotionProgram::prepare_segment(std::size_t i, double& level) {
  Segment& seg = segments_[i];
  const int idx = static_cast<int>(i);
  switch (seg.kind) {
    case SegmentKind::dwell:
      return;
    case SegmentKind::rise:
    case SegmentKind::fall:
      if (!std::isfinite(seg.lift) || seg.lift <= 0) {
        throw ProgramError(idx, fmt::format("expected a lift > 0, found {}", value_text(seg.lift)));
      }
      level += seg.kind == SegmentKind::rise ? seg.lift : -seg.lift;
      if (level < -1e-12 * std::max(1.0, max_s_)) {
        throw ProgramError(idx, fmt::format("the return goes {} below the base circle (lift larger than the "
                                            "height reached)", value_text(-level)));
      }
      return;
    case SegmentKind::table:
      prepare_table(i, level);
      return;
    case SegmentKind::polynomial:
      prepare_polynomial(i, level);
      return;
  }
}

void MotionProgram::prepare_table(std::size_t i, double& level) {
  Segment& seg = segments_[i];
  const int idx = static_cast<int>(i);
  const auto& t = seg.table;
  const bool bspline = seg.interpolation == TableInterpolation::bspline;
  if (bspline && seg.table_ends == TableEnds::periodic)
    throw ProgramError(idx, "periodic ends are for pchip and cubic tables, not bspline");
  const std::size_t min_points = seg.table_ends == TableEnds::periodic || bspline ? 3 : 2;
  if (t.size() < min_points) {
    throw ProgramError(idx, fmt::format("expected a table of at least {} points, found {}", min_points, t.size()));
  }
  if (std::abs(t.front().theta - seg.start) > kAngleTol || std::abs(t.back().theta - seg.end) > kAngleTol) {
    throw ProgramError(idx, fmt::format("the table must run from the segment's start ({} deg) to its end "
                                        "({} deg), found {} deg to {} deg",
                                        deg(seg.start), deg(seg.end), deg(t.front().theta), deg(t.back().theta)));
  }
  std::vector<double> x, y;
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (!std::isfinite(t[k].s) || !std::isfinite(t[k].theta)) throw ProgramError(idx, "table values must be finite");
    if (k > 0 && t[k].theta <= t[k - 1].theta + kAngleTol) {
      throw ProgramError(idx, fmt::format("table angles must increase, found {} deg after {} deg", deg(t[k].theta),
                                          deg(t[k - 1].theta)));
    }
    if (t[k].s < 0)
      throw ProgramError(idx, fmt::format("table value {} is below the base circle (< 0)", value_text(t[k].s)));
    x.push_back(t[k].theta);
    y.push_back(t[k].s);
  }
  x.front() = seg.start, x.back() = seg.end;
  const double scale = std::max(1.0, std::abs(t.front().s));
  if (std::abs(t.front().s - level) > 1e-9 * scale) {
    throw ProgramError(idx, fmt::format("the table starts at s = {} but the follower is at {} there",
                                        value_text(t.front().s), value_text(level)));
  }
  if (seg.table_ends == TableEnds::periodic) {
    if (segments_.size() != 1) throw ProgramError(idx, "periodic table ends need a table that covers the whole turn alone");
    if (std::abs(t.back().s - t.front().s) > 1e-9 * scale)
      throw ProgramError(idx, "a periodic table must end at the value it starts with");
    y.back() = y.front();
  }
  switch (seg.interpolation) {
    case TableInterpolation::pchip: curves_[i] = pchip(x, y, seg.table_ends); break;
    case TableInterpolation::cubic: curves_[i] = cubic_spline(x, y, seg.table_ends); break;
    case TableInterpolation::bspline: curves_[i] = bspline_table(x, y, seg.table_ends); break;
  }
  check_curve_above_base(i, "the cubic spline through the table", "use interpolation: pchip, which stays between "
                         "the points");
  level = y.back();
}

void MotionProgram::prepare_polynomial(std::size_t i, double& level) {
  Segment& seg = segments_[i];
  const int idx = static_cast<int>(i);
  EndConditions start = seg.at_start;
  if (!start.s) start.s = level;
  if (std::abs(*start.s - level) > 1e-9 * std::max(1.0, std::abs(level))) {
    throw ProgramError(idx, fmt::format("the polynomial starts at s = {} but the follower is at {} there",
                                        value_text(*start.s), value_text(level)));
  }
  if (!seg.at_end.s) throw ProgramError(idx, "a polynomial segment needs the end value s");
  if (*seg.at_end.s < 0)
    throw ProgramError(idx, fmt::format("the end value {} is below the base circle (< 0)", value_text(*seg.at_end.s)));
  try {
    curves_[i] = polynomial_from_conditions(seg.start, seg.end, start, seg.at_end);
  } catch (const std::invalid_argument& e) {
    throw ProgramError(idx, e.what());
  }
  check_curve_above_base(i, "the polynomial", "add conditions (v = 0, a = 0 at the ends) or change them");
  level = *seg.at_end.s;
}

void MotionProgram::check_curve_above_base(std::size_t i, const char* what, const char* advice) {
  const Segment& seg = segments_[i];
  const SegmentCurve& c = *curves_[i];
  const detail::Peak low = curve_extreme(c, seg.start, seg.end, -1);
  if (-low.value < -1e-9 * std::max(1.0, max_s_)) {
    throw ProgramError(static_cast<int>(i),
                       fmt::format("{} dips to s = {} at cam angle {} deg, below the base circle: {}", what,
                                   value_text(-low.value), deg(low.x), advice));
  }
  max_s_ = std::max(max_s_, curve_extreme(c, seg.start, seg.end, 1).value);
}

Motion MotionProgram::eval_segment(std::size_t i, double theta) const {
  const Segment& seg = segments_[i];
  const double beta = seg.end - seg.start;
  switch (seg.kind) {
    case SegmentKind::dwell:
      return {level_[i], 0, 0, 0};
    case SegmentKind::rise:
    case SegmentKind::fall:
      return law_motion(i, (theta - seg.start) / beta);
    case SegmentKind::table:
    case SegmentKind::polynomial:
      return curves_[i]->at(theta);
  }
  return {};
}

Motion MotionProgram::law_motion(std::size_t i, double u) const {
  const Segment& seg = segments_[i];
  const double beta = seg.end - seg.start;
  const LawValue y = evaluate(seg.law, u);
  const double L = (seg.kind == SegmentKind::rise ? 1 : -1) * seg.lift;
  return {level_[i] + L * y.y, L * y.dy / beta, L * y.d2y / (beta * beta), L * y.d3y / (beta * beta * beta)};
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

std::vector<MotionProgram::Break> MotionProgram::breaks() const {
  std::vector<Break> out;
  for (std::size_t i = 0; i < segments_.size(); ++i) {
    const Segment& seg = segments_[i];
    if (seg.kind == SegmentKind::rise || seg.kind == SegmentKind::fall)
      for (double u : law_breaks(seg.law)) out.push_back({seg.start + u * (seg.end - seg.start), i, false, u});
    if (curves_[i])
      for (double theta : curves_[i]->inner_breaks()) out.push_back({theta, i, false, -1});
    out.push_back({seg.end, i, true, 1});
  }
  return out;
}

std::pair<Motion, Motion> MotionProgram::limits_at(const Break& b) const {
  if (b.join) return {left_limit(b.segment), at(b.theta)};
  if (b.u >= 0) {  // inside a law: the pieces on either side of u
    return {law_motion(b.segment, std::nextafter(b.u, 0.0)), law_motion(b.segment, std::nextafter(b.u, 1.0))};
  }
  return {curves_[b.segment]->left_at(b.theta), curves_[b.segment]->at(b.theta)};
}

namespace {

/// Whether a derivative of order n jumps from x to y, beyond the tolerance of a program whose
/// largest value is `scale` (rounding of the laws' formulas, 10^n times larger per order).
bool jumps(double x, double y, int order, double scale) {
  const double t = 1e-9 * scale * std::pow(10.0, order);
  return std::abs(x - y) > t + 1e-9 * std::max(std::abs(x), std::abs(y));
}

double jump_scale(const MotionProgram& program) { return std::max(program.max_s(), 1e-12); }

}  // namespace

std::vector<JoinJump> continuity_check(const MotionProgram& program) {
  std::vector<JoinJump> jumps_found;
  const double scale = jump_scale(program);
  for (const MotionProgram::Break& b : program.breaks()) {
    const auto [before, after] = program.limits_at(b);
    const double theta = std::fmod(b.theta, two_pi);
    const std::pair<const char*, std::pair<double, double>> checks[4] = {
        {"displacement", {before.s, after.s}}, {"velocity", {before.ds, after.ds}},
        {"acceleration", {before.d2s, after.d2s}}, {"jerk", {before.d3s, after.d3s}}};
    for (int order = 0; order < 4; ++order) {
      const auto& [what, values] = checks[order];
      if (jumps(values.first, values.second, order, scale))
        jumps_found.push_back({theta, what, values.first, values.second, b.segment, b.join});
    }
  }
  return jumps_found;
}

std::vector<MotionProgram::Break> velocity_jumps(const MotionProgram& program) {
  std::vector<MotionProgram::Break> out;
  for (const MotionProgram::Break& b : program.breaks()) {
    const auto [before, after] = program.limits_at(b);
    if (jumps(before.ds, after.ds, 1, jump_scale(program))) out.push_back(b);
  }
  return out;
}

std::vector<Overshoot> table_overshoots(const MotionProgram& program) {
  std::vector<Overshoot> out;
  const auto& segs = program.segments();
  for (std::size_t i = 0; i < segs.size(); ++i) {
    const Segment& seg = segs[i];
    if (seg.kind != SegmentKind::table || seg.interpolation != TableInterpolation::cubic) continue;
    double lo = INFINITY, hi = -INFINITY;
    for (const TablePoint& p : seg.table) lo = std::min(lo, p.s), hi = std::max(hi, p.s);
    const double tol = 1e-9 * std::max(1.0, hi);
    auto s_at = [&](double t) { return program.at(t).s; };
    const detail::Peak top = detail::find_maximum(s_at, seg.start, seg.end, 32 * static_cast<int>(seg.table.size()),
                                                  1e-10 * (seg.end - seg.start));
    if (top.value > hi + tol) out.push_back({i, top.x, top.value, hi});
    const detail::Peak bottom = detail::find_maximum([&](double t) { return -s_at(t); }, seg.start, seg.end,
                                                     32 * static_cast<int>(seg.table.size()), 1e-10 * (seg.end - seg.start));
    if (-bottom.value < lo - tol) out.push_back({i, bottom.x, -bottom.value, lo});
  }
  return out;
}

double table_fit_residual(const MotionProgram& program, std::size_t segment) {
  const Segment& seg = program.segments().at(segment);
  double worst = 0;
  if (seg.kind != SegmentKind::table) return worst;
  for (std::size_t k = 0; k < seg.table.size(); ++k) {
    const double theta = k + 1 == seg.table.size() ? seg.end : seg.table[k].theta;
    const Motion m = k + 1 == seg.table.size() ? program.left_limit(segment) : program.at(theta);
    worst = std::max(worst, std::abs(m.s - seg.table[k].s));
  }
  return worst;
}

}  // namespace gearkit::cam
