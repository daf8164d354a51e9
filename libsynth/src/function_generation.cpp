#include <gearkit/synth/function_generation.hpp>

#include <Eigen/Dense>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace gearkit::synth {

namespace {

constexpr double pi = std::numbers::pi;

double wrap_pi(double a) { return a - 2 * pi * std::floor((a + pi) / (2 * pi)); }

// Solves rows [c1 c2 c3] K = rhs exactly (three rows) or in the least-squares sense.
Coefficients solve_linear(const Eigen::MatrixX3d& M, const Eigen::VectorXd& rhs) {
  const Eigen::ColPivHouseholderQR<Eigen::MatrixX3d> qr(M);
  if (qr.rank() < 3) throw NoSolution("the precision points give a singular system (repeated or degenerate points)");
  const Eigen::Vector3d K = qr.solve(rhs);
  if (!K.allFinite()) throw NoSolution("the precision points give a singular system");
  return {K[0], K[1], K[2]};
}

void check_pairs(std::span<const double> a, std::span<const double> b) {
  if (a.size() != b.size() || a.size() < 3)
    throw std::invalid_argument("function generation: need at least three (input, output) pairs of equal count");
}

struct Mapping {
  const FunctionTask& t;
  double y0, y1;
  double phi(double x) const { return t.input_start + (x - t.x_start) / (t.x_end - t.x_start) * t.input_range; }
  double out(double x) const { return t.output_start + (t.f(x) - y0) / (y1 - y0) * t.output_range; }
  double y_of(double out) const { return y0 + (out - t.output_start) / t.output_range * (y1 - y0); }
};

void validate(const FunctionTask& t) {
  const auto bad = [](const std::string& what) { throw std::invalid_argument("function generation: " + what); };
  if (!t.f) bad("no function given");
  for (double v : {t.x_start, t.x_end, t.input_start, t.input_range, t.output_start, t.output_range, t.ground})
    if (!std::isfinite(v)) bad("a range or scale is not finite");
  if (t.x_start == t.x_end) bad("the x range is empty");
  if (t.input_range == 0 || std::abs(t.input_range) >= 2 * pi) bad("the input range must be nonzero and under 360 deg");
  if (t.output_range == 0) bad("the output range must be nonzero");
  if (t.type == GeneratorType::four_bar && !(t.ground > 0)) bad("the ground length must be positive");
  if (t.fit_points < 3 || t.fit_points > 10000) bad("least-squares points must be 3..10000");
  if (t.error_samples < 2 || t.error_samples > 100000) bad("structural-error samples must be 2..100000");
  const double lo = std::min(t.x_start, t.x_end), hi = std::max(t.x_start, t.x_end);
  for (double x : t.precision_x)
    if (!(x >= lo && x <= hi)) bad(fmt::format("precision point x = {:g} lies outside the x range", x));
  if (t.method == FitMethod::precision_points && !t.precision_x.empty() && t.precision_x.size() != 3)
    bad("exactly three precision points (or none for Chebyshev spacing)");
}

double finite_f(const FunctionTask& t, double x) {
  const double y = t.f(x);
  if (!std::isfinite(y)) throw std::invalid_argument(fmt::format("function generation: f({:g}) is not finite", x));
  return y;
}

std::vector<double> fit_abscissae(const FunctionTask& t) {
  if (t.method == FitMethod::least_squares) return chebyshev_spacing(t.x_start, t.x_end, t.fit_points);
  if (!t.precision_x.empty()) return t.precision_x;
  return chebyshev_spacing(t.x_start, t.x_end, 3);
}

// Branch of the four-bar pose whose rocker angle is nearest the wanted one.
int nearest_branch(FourBar f, double theta2, double theta4_wanted) {
  double best = std::numeric_limits<double>::infinity();
  int branch = 1;
  for (int b : {1, -1}) {
    f.branch = b;
    const auto pose = pose_at(f, theta2);
    if (pose && std::abs(wrap_pi(pose->theta4 - theta4_wanted)) < best) {
      best = std::abs(wrap_pi(pose->theta4 - theta4_wanted));
      branch = b;
    }
  }
  return branch;
}

void sample_error(const Mapping& m, FunctionResult& r, const std::function<std::optional<double>(double)>& generated) {
  const FunctionTask& t = m.t;
  r.samples.clear();
  r.max_error = 0;
  for (int k = 0; k < t.error_samples; ++k) {
    ErrorSample s;
    s.x = t.x_start + (t.x_end - t.x_start) * k / (t.error_samples - 1);
    s.y_ideal = finite_f(t, s.x);
    const auto out = generated(s.x);
    s.y_generated = out ? m.y_of(*out) : std::numeric_limits<double>::quiet_NaN();
    s.error = s.y_generated - s.y_ideal;
    if (std::isfinite(s.error) && std::abs(s.error) > std::abs(r.max_error)) {
      r.max_error = std::abs(s.error);
      r.max_error_x = s.x;
    }
    r.samples.push_back(s);
  }
}

void synthesize_four_bar(const Mapping& m, const std::vector<double>& xs, FunctionResult& r) {
  std::vector<double> phi, psi;
  for (double x : xs) {
    phi.push_back(m.phi(x));
    psi.push_back(m.out(x));
  }
  r.K = freudenstein_coefficients(phi, psi);
  r.four_bar = four_bar_from_coefficients(r.K, m.t.ground);
  FourBar& f = r.four_bar.linkage;
  std::vector<int> branches;
  for (std::size_t j = 0; j < xs.size(); ++j) {
    r.precision_theta2.push_back(phi[j] + r.four_bar.crank_offset);
    branches.push_back(nearest_branch(f, r.precision_theta2.back(), psi[j] + r.four_bar.rocker_offset));
  }
  f.branch = branches[xs.size() / 2];
  // The whole input range must run on one branch, not only the precision points.
  std::vector<double> travel{m.phi(m.t.x_start) + r.four_bar.crank_offset};
  travel.insert(travel.end(), r.precision_theta2.begin(), r.precision_theta2.end());
  travel.push_back(m.phi(m.t.x_end) + r.four_bar.crank_offset);
  std::vector<int> travel_branches{f.branch};
  travel_branches.insert(travel_branches.end(), branches.begin(), branches.end());
  travel_branches.push_back(f.branch);
  r.defects = check_defects(f, travel, travel_branches, false);
  const double offset = r.four_bar.crank_offset, rocker_offset = r.four_bar.rocker_offset;
  sample_error(m, r, [&](double x) -> std::optional<double> {
    const auto pose = pose_at(f, m.phi(x) + offset);
    if (!pose) return std::nullopt;
    const double wanted = m.out(x);
    return wanted + wrap_pi(pose->theta4 - rocker_offset - wanted);
  });
  const double start = m.phi(m.t.x_start) + offset;
  r.transmission = transmission_range(f, start, std::abs(m.t.input_range), m.t.input_range > 0 ? 1 : -1);
}

// Branch and reachability of the slider-crank along the input range, sampled every 0.5 deg.
DefectReport slider_defects(const SliderCrank& k, double theta2_start, double travel, int direction,
                            std::span<const int> branches) {
  DefectReport d;
  d.direction = direction;
  d.travel = travel;
  if (std::any_of(branches.begin(), branches.end(), [&](int b) { return b != branches[0]; })) {
    d.branch_defect = true;
    d.notes.push_back("branch defect: the precision points lie on both sides of the crank pin along the guide");
  }
  const int n = std::max(2, static_cast<int>(std::ceil(travel / (pi / 360))));
  for (int i = 0; i <= n && !d.branch_defect; ++i)
    if (!slider_position(k, theta2_start + direction * travel * i / n)) {
      d.branch_defect = true;
      d.notes.push_back("branch defect: the rod cannot reach the guide (a toggle) within the input range");
    }
  return d;
}

void synthesize_slider_crank(const Mapping& m, const std::vector<double>& xs, FunctionResult& r) {
  std::vector<double> phi, s;
  for (double x : xs) {
    phi.push_back(m.phi(x));
    s.push_back(m.out(x));
  }
  r.K = slider_crank_coefficients(phi, s);
  r.slider_crank = slider_crank_from_coefficients(r.K);
  SliderCrank& k = r.slider_crank.linkage;
  std::vector<int> branches;
  for (std::size_t j = 0; j < xs.size(); ++j) {
    r.precision_theta2.push_back(phi[j] + r.slider_crank.crank_offset);
    branches.push_back(s[j] - k.crank * std::cos(r.precision_theta2.back()) >= 0 ? 1 : -1);
  }
  k.branch = branches[xs.size() / 2];
  const double offset = r.slider_crank.crank_offset;
  const int direction = m.t.input_range > 0 ? 1 : -1;
  r.defects = slider_defects(k, m.phi(m.t.x_start) + offset, std::abs(m.t.input_range), direction, branches);
  sample_error(m, r, [&](double x) { return slider_position(k, m.phi(x) + offset); });
}

}  // namespace

std::vector<double> chebyshev_spacing(double x0, double x1, int n) {
  if (n < 1 || x0 == x1) throw std::invalid_argument("chebyshev_spacing: need n >= 1 and x0 != x1");
  std::vector<double> x;
  for (int j = 1; j <= n; ++j) x.push_back((x0 + x1) / 2 - (x1 - x0) / 2 * std::cos((2 * j - 1) * pi / (2 * n)));
  return x;
}

Coefficients freudenstein_coefficients(std::span<const double> phi, std::span<const double> psi) {
  check_pairs(phi, psi);
  Eigen::MatrixX3d M(phi.size(), 3);
  Eigen::VectorXd rhs(phi.size());
  for (std::size_t j = 0; j < phi.size(); ++j) {
    M.row(static_cast<Eigen::Index>(j)) << std::cos(psi[j]), -std::cos(phi[j]), 1.0;
    rhs[static_cast<Eigen::Index>(j)] = std::cos(phi[j] - psi[j]);
  }
  return solve_linear(M, rhs);
}

Coefficients slider_crank_coefficients(std::span<const double> phi, std::span<const double> s) {
  check_pairs(phi, s);
  Eigen::MatrixX3d M(phi.size(), 3);
  Eigen::VectorXd rhs(phi.size());
  for (std::size_t j = 0; j < phi.size(); ++j) {
    M.row(static_cast<Eigen::Index>(j)) << s[j] * std::cos(phi[j]), std::sin(phi[j]), -1.0;
    rhs[static_cast<Eigen::Index>(j)] = s[j] * s[j];
  }
  return solve_linear(M, rhs);
}

FreudensteinLinkage four_bar_from_coefficients(const Coefficients& K, double d) {
  if (K.K1 == 0 || K.K2 == 0) throw NoSolution("K1 or K2 is zero: the crank or rocker would be infinitely long");
  const double a = d / K.K1, c = d / K.K2;
  const double b2 = a * a + c * c + d * d - 2 * a * c * K.K3;
  if (!(b2 > 0))
    throw NoSolution(fmt::format("no four-bar satisfies these points: the coupler length squared b^2 = {:.4g} m^2 "
                                 "is not positive", b2));
  FreudensteinLinkage r;
  r.linkage.O2 = Vec2(0, 0);
  r.linkage.O4 = Vec2(d, 0);
  r.linkage.crank = std::abs(a);
  r.linkage.rocker = std::abs(c);
  r.linkage.coupler = std::sqrt(b2);
  r.crank_offset = a < 0 ? pi : 0.0;
  r.rocker_offset = c < 0 ? pi : 0.0;
  return r;
}

SliderCrankLinkage slider_crank_from_coefficients(const Coefficients& K) {
  if (K.K1 == 0) throw NoSolution("K1 is zero: the crank would have no length");
  const double a = K.K1 / 2, e = K.K2 / K.K1;
  const double b2 = a * a + e * e - K.K3;
  if (!(b2 > 0))
    throw NoSolution(fmt::format("no slider-crank satisfies these points: the rod length squared b^2 = {:.4g} m^2 "
                                 "is not positive", b2));
  SliderCrankLinkage r;
  r.linkage.crank = std::abs(a);
  r.linkage.offset = e;
  r.linkage.rod = std::sqrt(b2);
  r.crank_offset = a < 0 ? pi : 0.0;
  return r;
}

FunctionResult synthesize_function(const FunctionTask& t) {
  validate(t);
  const Mapping m{t, finite_f(t, t.x_start), finite_f(t, t.x_end)};
  if (m.y0 == m.y1) throw std::invalid_argument("function generation: f(x_start) == f(x_end), so y has no range to map");
  FunctionResult r;
  r.type = t.type;
  r.y_start = m.y0;
  r.y_end = m.y1;
  r.precision_x = fit_abscissae(t);
  for (double x : r.precision_x) finite_f(t, x);
  if (t.type == GeneratorType::four_bar)
    synthesize_four_bar(m, r.precision_x, r);
  else
    synthesize_slider_crank(m, r.precision_x, r);
  return r;
}

}  // namespace gearkit::synth
