// Jump speed and spring sizing of a force-closed follower.
#include <gearkit/cam/follower_dynamics.hpp>

#include "dynamics_terms.hpp"
#include "program_extremum.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace gearkit::cam {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kSamples = 3600;

/// The speed at which this angle's margin A w^2 + B w + C (C >= 0 at rest) first turns
/// negative: the smallest positive root, in the form without cancellation; infinity if none.
double separation_speed(double A, double B, double C) {
  if (C < 0) return 0;  // the spring does not hold the follower even at rest
  const double D = B * B - 4 * A * C;
  if (A < 0) return B <= 0 ? 2 * C / (-B + std::sqrt(D)) : (-B - std::sqrt(D)) / (2 * A);
  if (A == 0) return B < 0 ? -C / B : kInf;
  if (B >= 0 || D < 0) return kInf;  // A > 0: negative only between two positive roots
  return 2 * C / (-B + std::sqrt(D));
}

struct Margin {
  double A, B, C;  // Q - F_min h = A w^2 + B w + C
};

Margin margin_terms(const FollowerTrain& tr, const detail::Terms& t, double min_force) {
  return {tr.mass * t.d2q, tr.damping * t.dq, tr.spring_rate * t.q + tr.preload + tr.load - min_force * t.h};
}

/// What the spring must give at this angle, k q + F_0 >= R, for every speed in [0, omega].
double spring_need(const FollowerTrain& tr, const detail::Terms& t, double omega, double min_force) {
  const double a = tr.mass * t.d2q, b = tr.damping * t.dq;  // the inertia and damping force: a w^2 + b w
  double worst = std::max(0.0, -(a * omega * omega + b * omega));
  if (a > 0 && b < 0) {  // -(a w^2 + b w) peaks inside at w = -b / (2 a)
    const double w = -b / (2 * a);
    if (w < omega) worst = std::max(worst, b * b / (4 * a));
  }
  return min_force * t.h - tr.load + worst;
}

/// sup over the turn of f(theta), found.
template <class F>
detail::Peak supremum(const CamDesign& d, F&& f) {
  return detail::maximum_over_turn(d.program, f, kSamples);
}

/// The rate k >= 0 minimising the mean spring force k q_mean + F_0(k), F_0(k) = max(0, max(R_i -
/// k q_i)): a convex piecewise-linear function of k whose corners are the slopes of the upper
/// hull of the points (q_i, R_i).
double least_mean_force_rate(std::vector<std::pair<double, double>> pts) {
  std::sort(pts.begin(), pts.end());
  std::vector<std::pair<double, double>> hull;  // upper hull, Andrew's monotone chain
  for (const auto& p : pts) {
    while (hull.size() >= 2) {
      const auto& a = hull[hull.size() - 2];
      const auto& b = hull.back();
      if ((b.first - a.first) * (p.second - a.second) - (b.second - a.second) * (p.first - a.first) >= 0)
        hull.pop_back();
      else
        break;
    }
    hull.push_back(p);
  }
  double q_mean = 0;
  for (const auto& p : pts) q_mean += p.first / static_cast<double>(pts.size());
  auto objective = [&](double k) {
    double f0 = 0;
    for (const auto& p : hull) f0 = std::max(f0, p.second - k * p.first);
    return k * q_mean + f0;
  };
  double best_k = 0, best = objective(0);
  for (std::size_t i = 0; i + 1 < hull.size(); ++i) {
    const double dq = hull[i + 1].first - hull[i].first;
    if (dq <= 0) continue;
    const double k = (hull[i + 1].second - hull[i].second) / dq;
    if (k < 0) continue;
    const double f = objective(k);
    if (f < best - 1e-12 * std::abs(best)) best = f, best_k = k;
  }
  return best_k;
}

SpringSizing size_once(const CamDesign& d, const FollowerTrain& tr, const SizingRequest& rq) {
  auto need = [&](double theta) { return spring_need(tr, detail::terms_at(d, theta), rq.omega, rq.min_force); };
  auto q_at = [&](double theta) { return detail::terms_at(d, theta).q; };
  SpringSizing out;
  out.damping = tr.damping;
  if (rq.preload) {
    out.preload = *rq.preload;
    const double q_eps = 1e-12 * std::max(1e-12, d.program.max_s());
    auto rate = [&](double theta) {
      const double q = q_at(theta), r = need(theta) - out.preload;
      if (q > q_eps) return r / q;
      return r > 1e-12 * std::max(1.0, std::abs(out.preload)) ? kInf : -kInf;
    };
    const detail::Peak k = supremum(d, rate);
    if (std::isinf(k.value) && k.value > 0) {
      const char* unit = d.follower.motion == FollowerMotion::translating ? "N" : "N*m";
      throw std::invalid_argument(fmt::format(
          "the preload {:.6g} {} is too small: at cam angle {:.6g} deg, on the base circle, the follower needs {:.6g} {}",
          out.preload, unit, std::fmod(k.x * 180 / std::numbers::pi, 360.0), need(k.x), unit));
    }
    out.spring_rate = std::max(0.0, k.value);
    return out;
  }
  if (rq.spring_rate) {
    out.spring_rate = *rq.spring_rate;
  } else {
    std::vector<std::pair<double, double>> pts;
    for (int i = 0; i < kSamples; ++i) {
      const double theta = d.program.start() + 2 * std::numbers::pi * i / kSamples;
      const detail::Terms t = detail::terms_at(d, theta);
      pts.emplace_back(t.q, spring_need(tr, t, rq.omega, rq.min_force));
    }
    out.spring_rate = least_mean_force_rate(std::move(pts));
  }
  out.preload = std::max(0.0, supremum(d, [&](double theta) { return need(theta) - out.spring_rate * q_at(theta); }).value);
  return out;
}

}  // namespace

std::optional<JumpSpeed> jump_speed(const CamDesign& d, const FollowerTrain& train, double min_force, double omega_max) {
  auto minus_speed = [&](double theta) {
    const Margin m = margin_terms(train, detail::terms_at(d, theta), min_force);
    return -separation_speed(m.A, m.B, m.C);
  };
  const detail::Peak worst = supremum(d, minus_speed);
  if (!(-worst.value <= omega_max)) return std::nullopt;
  return JumpSpeed{-worst.value, worst.x};
}

double least_contact_margin(const CamDesign& d, const FollowerTrain& train, double omega, double min_force) {
  auto minus_margin = [&](double theta) {
    const detail::Terms t = detail::terms_at(d, theta);
    return -(detail::generalised_force(train, t, omega) - min_force * t.h);
  };
  return -supremum(d, minus_margin).value;
}

namespace {

/// The margin's coefficients at kSamples angles, computed once for a sweep: the least margin at
/// any speed is then the least sampled value, refined by golden-section search around it.
class MarginTable {
 public:
  MarginTable(const CamDesign& d, const FollowerTrain& tr, double min_force) : d_(d), tr_(tr), min_force_(min_force) {
    for (int i = 0; i < kSamples; ++i) {
      const double theta = d.program.start() + 2 * std::numbers::pi * i / kSamples;
      terms_.push_back(margin_terms(tr, detail::terms_at(d, theta), min_force));
    }
  }

  double least(double w) const {
    std::size_t best = 0;
    double low = kInf;
    for (std::size_t i = 0; i < terms_.size(); ++i) {
      const Margin& m = terms_[i];
      const double v = (m.A * w + m.B) * w + m.C;
      if (v < low) low = v, best = i;
    }
    const double h = 2 * std::numbers::pi / kSamples, theta = d_.program.start() + h * best;
    auto minus = [&](double t) {
      const Margin m = margin_terms(tr_, detail::terms_at(d_, t), min_force_);
      return -((m.A * w + m.B) * w + m.C);
    };
    return -detail::golden_maximum(minus, theta - h, theta + h, 1e-12, {theta, -low}).value;
  }

 private:
  const CamDesign& d_;
  const FollowerTrain& tr_;
  double min_force_;
  std::vector<Margin> terms_;
};

}  // namespace

SpeedSweep sweep_speeds(const CamDesign& d, const FollowerTrain& train, double min_force,
                        const std::vector<double>& omegas) {
  SpeedSweep out;
  out.omega = omegas;
  const MarginTable table(d, train, min_force);
  for (double w : omegas) out.margin.push_back(table.least(w));
  double lo = 0, hi = -1;
  for (std::size_t i = 0; i < omegas.size(); ++i) {
    if (out.margin[i] < 0) {
      hi = omegas[i];
      break;
    }
    lo = omegas[i];
  }
  if (hi < 0) return out;
  if (table.least(0) < 0) {
    out.jump = 0;
    return out;
  }
  for (int k = 0; k < 100 && hi - lo > 1e-10 * hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    (table.least(mid) < 0 ? hi : lo) = mid;
  }
  out.jump = 0.5 * (lo + hi);
  return out;
}

SpringSizing size_spring(const CamDesign& d, const FollowerTrain& train, const SizingRequest& rq) {
  FollowerTrain tr = train;
  if (!rq.damping_ratio) return size_once(d, tr, rq);
  // The damping follows the rate (c = 2 zeta sqrt(k M)): fixed-point iteration, which converges
  // quickly as the damping term is small beside the inertia term.
  if (rq.spring_rate) tr.spring_rate = *rq.spring_rate;
  SpringSizing s;
  for (int i = 0; i < 60; ++i) {
    tr.damping = damping_for_ratio(tr, *rq.damping_ratio);
    s = size_once(d, tr, rq);
    const bool settled = std::abs(s.spring_rate - tr.spring_rate) <= 1e-12 * std::max(1.0, s.spring_rate);
    tr.spring_rate = s.spring_rate;
    if (settled && i > 0) break;
  }
  s.damping = damping_for_ratio(tr, *rq.damping_ratio);
  return s;
}

}  // namespace gearkit::cam
