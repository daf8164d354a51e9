#include <gearkit/synth/burmester.hpp>

#include "plane.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <optional>
#include <stdexcept>

namespace gearkit::synth {

namespace {

using cd = std::complex<double>;
constexpr double two_pi = 2 * std::numbers::pi;

cd c(const Vec2& v) { return {v.x(), v.y()}; }
Vec2 v(const cd& z) { return {z.real(), z.imag()}; }
cd e1(double a) { return std::polar(1.0, a) - 1.0; }

// The standard-form data of four (or more) poses: a_j = e^{i alpha_j} - 1, d_j = delta_j.
struct StandardForm {
  std::vector<cd> a, d;  // index j - 1 for pose j (index 0 unused: zeros)
  cd D1, D2, D3, D4;
  explicit StandardForm(std::span<const Pose> poses) {
    for (const Pose& p : poses) {
      a.push_back(e1(p.angle - poses[0].angle));
      d.push_back(c(p.point - poses[0].point));
    }
    D2 = a[2] * d[3] - a[3] * d[2];
    D3 = a[3] * d[1] - a[1] * d[3];
    D4 = a[1] * d[2] - a[2] * d[1];
    D1 = -(D2 + D3 + D4);
  }
};

// W and Z from two of the dyad equations (rows j, k), or nullopt when singular.
std::optional<std::pair<cd, cd>> solve_dyad(const StandardForm& s, const std::vector<double>& beta, int j, int k) {
  const cd a11 = e1(beta[j - 1]), a12 = s.a[j], a21 = e1(beta[k - 1]), a22 = s.a[k];
  const cd det = a11 * a22 - a12 * a21;
  if (std::abs(det) < 1e-9) return std::nullopt;
  return std::pair{(s.d[j] * a22 - a12 * s.d[k]) / det, (a11 * s.d[k] - a21 * s.d[j]) / det};
}

std::optional<BurmesterDyad> family_member(std::span<const Pose> poses, const StandardForm& s, double beta2,
                                           int closure) {
  const cd R = s.D1 + s.D2 * std::polar(1.0, beta2);
  const double p = std::abs(s.D3), q = std::abs(s.D4), r = std::abs(R);
  if (p == 0 || q == 0 || r == 0) return std::nullopt;
  const double cos_t = (p * p + r * r - q * q) / (2 * p * r);
  if (std::abs(cos_t) > 1) return std::nullopt;
  const double t = std::acos(cos_t) * (closure == 0 ? 1 : -1);
  const cd u = std::polar(p, std::arg(-R) + t), w = -R - u;
  BurmesterDyad b;
  b.closure = closure;
  b.beta = {beta2, std::arg(u) - std::arg(s.D3), std::arg(w) - std::arg(s.D4)};
  auto wz = solve_dyad(s, b.beta, 1, 2);
  if (!wz) wz = solve_dyad(s, b.beta, 1, 3);
  if (!wz) return std::nullopt;
  const cd P1 = c(poses[0].point);
  b.dyad = {v(P1 - wz->first - wz->second), v(P1 - wz->second)};
  return b;
}

void check_count(std::span<const Pose> poses, std::size_t n, int samples) {
  if (poses.size() != n || samples < 8 || samples > kMaxBurmesterSamples)
    throw std::invalid_argument(fmt::format("Burmester synthesis: needs {} poses and 8..{} samples", n,
                                            kMaxBurmesterSamples));
}

// Fifth-pose residual of a four-pose dyad: |delta_5 - Z a_5 + W| - |W|.
double fifth_residual(std::span<const Pose> poses, const BurmesterDyad& b) {
  const cd P1 = c(poses[0].point), G = c(b.dyad.ground_pivot), M = c(b.dyad.moving_pivot);
  const cd W = M - G, Z = P1 - M;
  return std::abs(c(poses[4].point - poses[0].point) - Z * e1(poses[4].angle - poses[0].angle) + W) - std::abs(W);
}

std::optional<BurmesterDyad> refine_root(std::span<const Pose> poses, const StandardForm& s, double lo, double hi,
                                         int closure) {
  const auto f = [&](double beta2) -> std::optional<double> {
    const auto b = family_member(poses, s, beta2, closure);
    return b ? std::optional(fifth_residual(poses, *b)) : std::nullopt;
  };
  auto flo = f(lo);
  for (int k = 0; k < 60 && hi - lo > 1e-12; ++k) {
    const double mid = (lo + hi) / 2;
    const auto fm = f(mid);
    if (!fm || !flo) return std::nullopt;
    if ((*fm < 0) == (*flo < 0)) {
      lo = mid;
      flo = fm;
    } else {
      hi = mid;
    }
  }
  return family_member(poses, s, (lo + hi) / 2, closure);
}

}  // namespace

std::vector<BurmesterDyad> burmester_curves(std::span<const Pose> poses, int samples) {
  check_count(poses, 4, samples);
  const StandardForm s(poses);
  std::vector<BurmesterDyad> out;
  for (int closure = 0; closure < 2; ++closure)
    for (int k = 0; k < samples; ++k)
      if (auto b = family_member(poses, s, two_pi * k / samples, closure)) out.push_back(std::move(*b));
  return out;
}

BurmesterDyad burmester_dyad(std::span<const Pose> poses, double beta2, int closure) {
  if (poses.size() != 4) throw std::invalid_argument("burmester_dyad: needs four poses");
  auto b = family_member(poses, StandardForm(poses), beta2, closure == 0 ? 0 : 1);
  if (!b) throw NoSolution(fmt::format("no Burmester dyad at beta2 = {:.6g} deg on closure {}", beta2 * 180 / std::numbers::pi, closure));
  return *b;
}

std::vector<BurmesterDyad> burmester_points(std::span<const Pose> poses, int samples) {
  check_count(poses, 5, samples);
  const StandardForm s(poses);
  double scale = 0;
  for (const Pose& p : poses) scale = std::max(scale, (p.point - poses[0].point).norm());
  std::vector<BurmesterDyad> found;
  for (int closure = 0; closure < 2; ++closure) {
    std::optional<BurmesterDyad> prev;
    double prev_beta = 0;
    for (int k = 0; k <= samples; ++k) {
      const double beta2 = two_pi * k / samples;
      auto b = family_member(poses.first(4), s, beta2, closure);
      if (b && prev && (fifth_residual(poses, *b) < 0) != (fifth_residual(poses, *prev) < 0)) {
        auto root = refine_root(poses, s, prev_beta, beta2, closure);
        if (root && dyad_error(poses, root->dyad) <= 1e-7 * std::max(scale, 1e-9)) {
          const bool seen = std::any_of(found.begin(), found.end(), [&](const BurmesterDyad& f) {
            return (f.dyad.ground_pivot - root->dyad.ground_pivot).norm() < 1e-6 * std::max(scale, 1e-9);
          });
          if (!seen) found.push_back(std::move(*root));
        }
      }
      prev = std::move(b);
      prev_beta = beta2;
    }
  }
  return found;
}

double dyad_error(std::span<const Pose> poses, const Dyad& d) {
  const double r1 = (d.moving_pivot - d.ground_pivot).norm();
  double e = 0;
  for (const Pose& p : poses) e = std::max(e, std::abs((carry(poses[0], p, d.moving_pivot) - d.ground_pivot).norm() - r1));
  return e;
}

}  // namespace gearkit::synth
