// One-degree-of-freedom response of a flexible follower train, integrated exactly per step.
#include <gearkit/cam/follower_vibration.hpp>

#include "dynamics_terms.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace gearkit::cam {
namespace {

using Mat2 = std::array<double, 4>;  // row-major 2x2
using Vec = std::array<double, 2>;

Mat2 mul(const Mat2& a, const Mat2& b) {
  return {a[0] * b[0] + a[1] * b[2], a[0] * b[1] + a[1] * b[3], a[2] * b[0] + a[3] * b[2], a[2] * b[1] + a[3] * b[3]};
}
Vec mul(const Mat2& a, const Vec& x) { return {a[0] * x[0] + a[1] * x[1], a[2] * x[0] + a[3] * x[1]}; }

/// exp(A) of a 2x2 matrix by scaling and squaring with a Taylor series (Moler & Van Loan,
/// "Nineteen dubious ways...", method 3): exact to rounding for the norms met here.
Mat2 expm(Mat2 a) {
  const double norm = std::max(std::abs(a[0]) + std::abs(a[1]), std::abs(a[2]) + std::abs(a[3]));
  int squarings = 0;
  while (norm / std::ldexp(1.0, squarings) > 0.25) ++squarings;
  for (double& v : a) v = std::ldexp(v, -squarings);
  Mat2 result{1, 0, 0, 1}, term{1, 0, 0, 1};
  for (int k = 1; k <= 14; ++k) {
    term = mul(term, a);
    for (double& v : term) v /= k;
    for (int i = 0; i < 4; ++i) result[i] += term[i];
  }
  for (int i = 0; i < squarings; ++i) result = mul(result, result);
  return result;
}

/// m x'' + c x' + K x = p(t), advanced over steps of length h with p a cubic Hermite polynomial
/// from the values and slopes at the step's ends: the polynomial particular solution plus the
/// homogeneous solution through the matrix exponential, exact for such forcing.
class Oscillator {
 public:
  Oscillator(double m, double c, double K) : m_(m), c_(c), K_(K) {}

  /// exp(A h), kept while h stays the same step: the grid's even steps, differences of rounded
  /// angles, differ from each other in their last bits, and recomputing the exponential for a
  /// change of 1e-12 h (a relative change of Phi of at most |A| h 1e-12, far below anything the
  /// response reports) made it half the cost of the whole response.
  const Mat2& transition(double h) {
    if (std::abs(h - h_) > 1e-12 * h) h_ = h, phi_ = expm({0, h, -K_ / m_ * h, -c_ / m_ * h});
    return phi_;
  }

  Vec step(const Vec& x0, double h, double p0, double p1, double dp0, double dp1) {
    const double a0 = p0, a1 = dp0;
    const double a2 = (3 * (p1 - p0) / h - 2 * dp0 - dp1) / h;
    const double a3 = (2 * (p0 - p1) / h + dp0 + dp1) / (h * h);
    const double b3 = a3 / K_;
    const double b2 = (a2 - 3 * c_ * b3) / K_;
    const double b1 = (a1 - 2 * c_ * b2 - 6 * m_ * b3) / K_;
    const double b0 = (a0 - c_ * b1 - 2 * m_ * b2) / K_;
    const Vec y = mul(transition(h), Vec{x0[0] - b0, x0[1] - b1});
    return {y[0] + b0 + h * (b1 + h * (b2 + h * b3)), y[1] + b1 + h * (2 * b2 + 3 * b3 * h)};
  }

 private:
  double m_, c_, K_;
  double h_ = -1;
  Mat2 phi_{};
};

/// Cam angles of the response: `samples` evenly from the start, plus every break of the
/// program (segment ends, blends inside laws, table knots), where the forcing's derivatives jump.
std::vector<double> response_grid(const MotionProgram& program, int samples) {
  const double t0 = program.start(), turn = 2 * std::numbers::pi;
  std::vector<double> grid;
  for (int i = 0; i <= samples; ++i) grid.push_back(t0 + turn * i / samples);
  for (const MotionProgram::Break& b : program.breaks()) grid.push_back(b.theta);
  std::sort(grid.begin(), grid.end());
  grid.erase(std::unique(grid.begin(), grid.end(), [&](double a, double b) { return b - a < 1e-12; }), grid.end());
  grid.back() = t0 + turn;
  return grid;
}

/// Free-vibration amplitude from a deviation e and its rate de.
double amplitude(double e, double de, double omega_n, double zeta) {
  if (zeta >= 1) return std::abs(e);
  const double wd = omega_n * std::sqrt(1 - zeta * zeta);
  return std::hypot(e, (de + zeta * omega_n * e) / wd);
}

}  // namespace

FlexibleResponse flexible_response(const CamDesign& d, const FollowerTrain& tr, double omega, int samples) {
  FlexibleResponse out;
  const double K = tr.spring_rate + tr.stiffness;
  out.natural_frequency = std::sqrt(K / tr.mass);
  out.damping_ratio = tr.damping / (2 * std::sqrt(K * tr.mass));
  out.static_ratio = tr.stiffness / K;
  const std::vector<double> grid = response_grid(d.program, samples);
  std::vector<double> p, dp, q;
  for (double theta : grid) {
    const detail::Terms t = detail::terms_at(d, theta);
    q.push_back(t.q);
    p.push_back(tr.stiffness * t.q - tr.preload - tr.load);
    dp.push_back(tr.stiffness * t.dq * omega);
  }
  Oscillator osc(tr.mass, tr.damping, K);
  // One turn from rest gives the affine part of the turn's map; its linear part is the product
  // of the steps' transitions. The periodic start solves x* = Phi x* + x_N.
  Vec x{0, 0};
  Mat2 phi_turn{1, 0, 0, 1};
  for (std::size_t i = 0; i + 1 < grid.size(); ++i) {
    const double h = (grid[i + 1] - grid[i]) / omega;
    x = osc.step(x, h, p[i], p[i + 1], dp[i], dp[i + 1]);
    phi_turn = mul(osc.transition(h), phi_turn);
  }
  const Mat2 I_minus{1 - phi_turn[0], -phi_turn[1], -phi_turn[2], 1 - phi_turn[3]};
  const double det = I_minus[0] * I_minus[3] - I_minus[1] * I_minus[2];
  Vec start{p[0] / K, 0};  // the static position, if no periodic response exists
  if (std::abs(det) > 1e-12) {
    start = {(I_minus[3] * x[0] - I_minus[1] * x[1]) / det, (-I_minus[2] * x[0] + I_minus[0] * x[1]) / det};
  } else {
    out.periodic = false;
  }
  x = start;
  for (std::size_t i = 0; i + 1 < grid.size(); ++i) {
    out.theta.push_back(grid[i]);
    out.x.push_back(x[0]);
    out.v.push_back(x[1]);
    out.force.push_back(tr.stiffness * (q[i] - x[0]));
    x = osc.step(x, (grid[i + 1] - grid[i]) / omega, p[i], p[i + 1], dp[i], dp[i + 1]);
  }
  return out;
}

std::vector<ResidualVibration> residual_vibrations(const CamDesign& d, const FollowerTrain& tr,
                                                   const FlexibleResponse& r) {
  std::vector<ResidualVibration> out;
  const auto& segs = d.program.segments();
  const double K = tr.spring_rate + tr.stiffness;
  for (std::size_t i = 0; i < segs.size(); ++i) {
    const bool moves = segs[i].kind == SegmentKind::rise || segs[i].kind == SegmentKind::fall;
    if (!moves || segs[(i + 1) % segs.size()].kind != SegmentKind::dwell) continue;
    // The end of the last segment is the start of the turn (index 0).
    const double end = i + 1 == segs.size() ? d.program.start() : segs[i].end;
    const auto it = std::lower_bound(r.theta.begin(), r.theta.end(), end - 1e-12);
    const std::size_t k = static_cast<std::size_t>(it - r.theta.begin());
    const double q = detail::terms_at(d, end).q;
    const double x_static = (tr.stiffness * q - tr.preload - tr.load) / K;
    out.push_back({i, segs[i].end, amplitude(r.x[k] - x_static, r.v[k], r.natural_frequency, r.damping_ratio)});
  }
  return out;
}

double residual_vibration_of_law(Law law, double lift, double beta, double omega, double omega_n, double zeta,
                                 double static_ratio) {
  // z'' + 2 zeta omega_n z' + omega_n^2 z = omega_n^2 L y(t / T), x = r z.
  const double T = beta / omega, w2 = omega_n * omega_n;
  Oscillator osc(1, 2 * zeta * omega_n, w2);
  const int steps = 2000;
  const double h = T / steps;
  Vec z{0, 0};
  LawValue prev = evaluate(law, 0);
  for (int i = 1; i <= steps; ++i) {
    const LawValue next = evaluate(law, static_cast<double>(i) / steps);
    z = osc.step(z, h, w2 * lift * prev.y, w2 * lift * next.y, w2 * lift * prev.dy / T, w2 * lift * next.dy / T);
    prev = next;
  }
  return static_ratio * amplitude(z[0] - lift, z[1], omega_n, zeta);
}

}  // namespace gearkit::cam
