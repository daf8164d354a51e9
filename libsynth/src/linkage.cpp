#include <gearkit/synth/linkage.hpp>

#include "plane.hpp"

#include <gearkit/kin/fourbar.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gearkit::synth {

namespace {

constexpr double two_pi = 2 * std::numbers::pi;

using plane::cross;
using plane::rotate;

// The interval of `intervals` holding angle `a`, or nullptr.
const AngleInterval* interval_holding(const std::vector<AngleInterval>& intervals, double a) {
  for (const AngleInterval& i : intervals)
    if (i.length >= two_pi || wrap_two_pi(a - i.start) <= i.length + 1e-12) return &i;
  return nullptr;
}

// Direction (+1/-1) in which the crank meets the positions in order, with the crank travel from
// the first to the last; 0 if neither direction works (order defect).
std::pair<int, double> crank_direction(std::span<const double> theta2) {
  int best = 0;
  double best_travel = 0;
  for (int direction : {1, -1}) {
    double previous = 0;
    bool ordered = true;
    for (std::size_t j = 1; j < theta2.size() && ordered; ++j) {
      const double offset = wrap_two_pi(direction * (theta2[j] - theta2[0]));
      ordered = offset > previous;
      previous = offset;
    }
    if (ordered && (best == 0 || previous < best_travel)) {
      best = direction;
      best_travel = previous;
    }
  }
  return {best, best_travel};
}

}  // namespace

double FourBar::ground_angle() const { return std::atan2(O4.y() - O2.y(), O4.x() - O2.x()); }

double wrap_two_pi(double a) {
  a = std::fmod(a, two_pi);
  return a < 0 ? a + two_pi : a;
}

int branch_of(const Vec2& A, const Vec2& B, const Vec2& O4) {
  const double c = cross(O4 - A, B - A);
  const double scale = (O4 - A).norm() * (B - A).norm();
  if (std::abs(c) <= 1e-12 * scale) return 0;
  return c > 0 ? 1 : -1;
}

std::optional<FourBarPose> pose_at(const FourBar& f, double theta2) {
  FourBarPose p;
  p.theta2 = theta2;
  p.A = f.O2 + f.crank * Vec2(std::cos(theta2), std::sin(theta2));
  const auto B = plane::circle_intersection(p.A, f.coupler, f.O4, f.rocker, f.branch);
  if (!B) return std::nullopt;
  p.B = *B;
  p.theta3 = std::atan2(p.B.y() - p.A.y(), p.B.x() - p.A.x());
  p.theta4 = std::atan2(p.B.y() - f.O4.y(), p.B.x() - f.O4.x());
  p.P = p.A + rotate(f.coupler_point, p.theta3);
  return p;
}

double transmission_angle(const FourBarPose& pose, const FourBar& f) {
  return kin::transmission_angle(pose.B - pose.A, pose.B - f.O4);
}

std::vector<AngleInterval> crank_range(const FourBar& f) {
  const double a = f.crank, b = f.coupler, c = f.rocker, d = f.ground();
  if (a <= 0 || d <= 0) return {};
  // |A O4|^2 = a^2 + d^2 - 2 a d cos(phi), phi = theta2 - theta1, must lie in [(b-c)^2, (b+c)^2].
  const double u_low = (a * a + d * d - (b + c) * (b + c)) / (2 * a * d);
  const double u_high = (a * a + d * d - (b - c) * (b - c)) / (2 * a * d);
  const double lo = std::max(u_low, -1.0), hi = std::min(u_high, 1.0);
  if (lo > hi) return {};
  const double theta1 = f.ground_angle();
  const double phi_near = std::acos(hi), phi_far = std::acos(lo);  // 0 <= near <= far <= pi
  const bool joins_at_zero = hi >= 1.0, joins_at_pi = lo <= -1.0;
  if (joins_at_zero && joins_at_pi) return {{wrap_two_pi(theta1), two_pi}};
  if (joins_at_zero) return {{wrap_two_pi(theta1 - phi_far), 2 * phi_far}};
  if (joins_at_pi) return {{wrap_two_pi(theta1 + phi_near), two_pi - 2 * phi_near}};
  return {{wrap_two_pi(theta1 + phi_near), phi_far - phi_near}, {wrap_two_pi(theta1 - phi_far), phi_far - phi_near}};
}

bool crank_turns_fully(const FourBar& f) {
  const auto r = crank_range(f);
  return r.size() == 1 && r[0].length >= two_pi;
}

DefectReport check_defects(const FourBar& f, std::span<const double> theta2, std::span<const int> branches,
                           bool require_crank) {
  if (theta2.size() != branches.size() || theta2.size() < 2)
    throw std::invalid_argument("check_defects: need as many branches as crank angles, at least two");
  DefectReport r;
  for (std::size_t j = 1; j < branches.size(); ++j)
    if (branches[j] != branches[0]) {
      r.branch_defect = true;
      r.notes.push_back(fmt::format("branch defect: position {} is assembled on the other branch than position 1", j + 1));
    }
  const auto [direction, travel] = crank_direction(theta2);
  if (direction == 0) {
    r.order_defect = true;
    r.notes.push_back("order defect: turning one way, the crank does not meet the positions in their order");
  } else {
    r.direction = direction;
    r.travel = travel;
    const auto intervals = crank_range(f);
    const AngleInterval* i = interval_holding(intervals, theta2[0]);
    const bool full = i && i->length >= two_pi;
    const double from_start = i ? wrap_two_pi(theta2[0] - i->start) : 0.0;
    const bool inside = full || (i && (direction > 0 ? from_start + travel <= i->length + 1e-9 : from_start >= travel - 1e-9));
    if (!inside) {
      r.branch_defect = true;
      r.notes.push_back("branch defect: the crank reaches a toggle (coupler and rocker in line) between the positions");
    }
  }
  if (require_crank && !crank_turns_fully(f)) {
    r.grashof_defect = true;
    r.notes.push_back("Grashof defect: the input link does not turn fully, so a motor cannot drive it as a crank");
  }
  return r;
}

TransmissionRange transmission_range(const FourBar& f, double theta2_start, double travel, int direction) {
  TransmissionRange r{std::numbers::pi, 0};
  const double step = std::numbers::pi / 360;
  const int n = std::max(1, static_cast<int>(std::ceil(travel / step)));
  for (int k = 0; k <= n; ++k) {
    const auto pose = pose_at(f, theta2_start + direction * travel * k / n);
    if (!pose) continue;
    const double mu = transmission_angle(*pose, f);
    r.min = std::min(r.min, mu);
    r.max = std::max(r.max, mu);
  }
  if (r.min > r.max) r.min = r.max = 0;
  return r;
}

std::optional<double> slider_position(const SliderCrank& s, double theta2) {
  const double phi = theta2 - s.axis_angle;
  const double h = s.offset - s.crank * std::sin(phi);
  const double root2 = s.rod * s.rod - h * h;
  if (root2 < -1e-12 * s.rod * s.rod) return std::nullopt;
  return s.crank * std::cos(phi) + s.branch * std::sqrt(std::max(root2, 0.0));
}

}  // namespace gearkit::synth
