#include <gearkit/synth/quick_return.hpp>

#include <gearkit/synth/function_generation.hpp>

#include "plane.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace gearkit::synth {

namespace {

constexpr double pi = std::numbers::pi;

struct Chord {
  Vec2 B1, B2, M, u, n;  // ends, midpoint, unit along B1 -> B2, unit normal
  double w = 0;          // length
};

Chord rocker_chord(const QuickReturnTask& t) {
  Chord c;
  c.B1 = t.rocker * Vec2(std::cos(pi / 2 + t.swing / 2), std::sin(pi / 2 + t.swing / 2));
  c.B2 = t.rocker * Vec2(std::cos(pi / 2 - t.swing / 2), std::sin(pi / 2 - t.swing / 2));
  c.M = (c.B1 + c.B2) / 2;
  c.w = (c.B2 - c.B1).norm();
  c.u = (c.B2 - c.B1) / c.w;
  c.n = Vec2(-c.u.y(), c.u.x());
  return c;
}

// Candidate positions of O2: on the arcs seeing the chord under delta (the line beyond the
// chord for delta = 0), either sampled or at distance `ground` from O4 (the origin).
std::vector<Vec2> locus(const Chord& c, double delta, const QuickReturnTask& t) {
  std::vector<Vec2> out;
  if (delta < 1e-12) {
    if (t.ground) {
      const double p = c.M.dot(c.u), q = c.M.squaredNorm() - *t.ground * *t.ground, disc = p * p - q;
      if (disc >= 0)
        for (double s : {-p - std::sqrt(disc), -p + std::sqrt(disc)}) out.push_back(c.M + s * c.u);
    } else {
      for (int k = 1; k <= t.samples / 2; ++k)
        for (int side : {-1, 1}) out.push_back(c.M + side * (c.w / 2 + 10.0 * t.rocker * k / (t.samples / 2)) * c.u);
    }
    return out;
  }
  const double R = c.w / (2 * std::sin(delta));
  for (int side : {-1, 1}) {
    const Vec2 C = c.M + side * R * std::cos(delta) * c.n;
    if (t.ground) {
      const double dist = C.norm(), g = *t.ground;
      const double x = (dist * dist + R * R - g * g) / (2 * dist), h2 = R * R - x * x;
      if (dist == 0 || h2 < 0) continue;
      const Vec2 e = -C / dist, f(-e.y(), e.x());
      for (int s : {-1, 1}) out.push_back(C + x * e + s * std::sqrt(h2) * f);
    } else {
      for (int k = 0; k < t.samples / 2; ++k) out.push_back(C + R * Vec2(std::cos(2 * pi * k / (t.samples / 2)), std::sin(2 * pi * k / (t.samples / 2))));
    }
  }
  return out;
}

// The crank-rocker with its crank pivot at X, or nullopt if X does not see the chord under delta.
std::optional<QuickReturnResult> candidate(const Chord& c, double delta, const Vec2& X, double rocker) {
  const Vec2 d1 = c.B1 - X, d2 = c.B2 - X;
  const double seen = std::acos(std::clamp(d1.dot(d2) / (d1.norm() * d2.norm()), -1.0, 1.0));
  if (std::abs(seen - delta) > 1e-7 || d1.norm() < 1e-12 || d2.norm() < 1e-12) return std::nullopt;
  const bool first_extended = d1.norm() > d2.norm();
  const Vec2 Bext = first_extended ? c.B1 : c.B2, Bfold = first_extended ? c.B2 : c.B1;
  QuickReturnResult r;
  r.delta = delta;
  FourBar& f = r.linkage;
  f.O2 = X;
  f.O4 = Vec2(0, 0);
  f.crank = std::abs(d1.norm() - d2.norm()) / 2;
  f.coupler = (d1.norm() + d2.norm()) / 2;
  f.rocker = rocker;
  f.coupler_point = Vec2(f.coupler, 0);
  if (f.crank < 1e-9 * rocker) return std::nullopt;
  r.theta2_extended = plane::angle_of(Bext - X);
  r.theta2_folded = plane::angle_of(X - Bfold);
  const Vec2 A = X + f.crank * (Bext - X).normalized();
  f.branch = branch_of(A, Bext, f.O4) >= 0 ? 1 : -1;
  if (!crank_turns_fully(f)) return std::nullopt;
  r.ccw_stroke = wrap_two_pi(r.theta2_folded - r.theta2_extended);
  r.min_transmission = transmission_range(f, r.theta2_extended, 2 * pi, 1).min;
  return r;
}

}  // namespace

QuickReturnResult synthesize_quick_return(const QuickReturnTask& t) {
  if (!(t.swing > 0 && t.swing < pi)) throw std::invalid_argument("quick return: the rocker swing must be between 0 and 180 deg");
  if (!(t.time_ratio >= 1 && t.time_ratio < 10)) throw std::invalid_argument("quick return: the time ratio must be 1 <= Q < 10");
  if (!(t.rocker > 0) || (t.ground && !(*t.ground > 0))) throw std::invalid_argument("quick return: lengths must be positive");
  if (t.samples < 100 || t.samples > 100000) throw std::invalid_argument("quick return: samples must be 100..100000");
  const double delta = pi * (t.time_ratio - 1) / (t.time_ratio + 1);
  const Chord c = rocker_chord(t);
  std::optional<QuickReturnResult> best;
  for (const Vec2& X : locus(c, delta, t)) {
    const auto r = candidate(c, delta, X, t.rocker);
    if (r && (!best || r->min_transmission > best->min_transmission)) best = r;
  }
  if (!best)
    throw NoSolution(t.ground ? fmt::format("no Grashof crank-rocker with a ground link of {:.6g} m gives this swing and "
                                            "time ratio", *t.ground)
                              : std::string("no Grashof crank-rocker gives this swing and time ratio"));
  return *best;
}

}  // namespace gearkit::synth
