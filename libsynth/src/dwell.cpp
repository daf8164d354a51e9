#include <gearkit/synth/dwell.hpp>

#include <gearkit/synth/function_generation.hpp>

#include "plane.hpp"

#include <Eigen/Dense>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gearkit::synth {

namespace {

constexpr double pi = std::numbers::pi;

struct CircleFit {
  Vec2 centre{0, 0};
  double radius = 0, deviation = 0;
};

// Kasa's algebraic circle fit: x^2 + y^2 + D x + E y + F = 0 in the least-squares sense.
std::optional<CircleFit> kasa_fit(const std::vector<Vec2>& pts) {
  Eigen::MatrixX3d M(pts.size(), 3);
  Eigen::VectorXd rhs(pts.size());
  for (std::size_t k = 0; k < pts.size(); ++k) {
    M.row(static_cast<Eigen::Index>(k)) << pts[k].x(), pts[k].y(), 1.0;
    rhs[static_cast<Eigen::Index>(k)] = -pts[k].squaredNorm();
  }
  const Eigen::Vector3d s = M.colPivHouseholderQr().solve(rhs);
  CircleFit f;
  f.centre = Vec2(-s[0] / 2, -s[1] / 2);
  const double r2 = f.centre.squaredNorm() - s[2];
  if (!(r2 > 0) || !s.allFinite()) return std::nullopt;
  f.radius = std::sqrt(r2);
  for (const Vec2& p : pts) f.deviation = std::max(f.deviation, std::abs((p - f.centre).norm() - f.radius));
  return f;
}

std::vector<Vec2> coupler_curve(const FourBar& f, double start, int n) {
  std::vector<Vec2> pts;
  for (int k = 0; k < n; ++k) pts.push_back(pose_at(f, start + 2 * pi * k / n)->P);
  return pts;
}

// The window of `m` consecutive samples with the most circular arc of practical radius.
void find_arc(const DwellTask& t, DwellResult& r) {
  const FourBar& f = t.four_bar;
  const int n = t.samples;
  const int m = std::max(3, static_cast<int>(std::lround(t.dwell / (2 * pi) * n)) + 1);
  const double start = f.ground_angle();
  const std::vector<Vec2> curve = coupler_curve(f, start, n);
  const double size = std::max({f.ground(), f.crank, f.coupler, f.rocker, f.coupler_point.norm()});
  std::optional<CircleFit> best;
  std::vector<Vec2> window(static_cast<std::size_t>(m));
  for (int k = 0; k < n; ++k) {
    for (int i = 0; i < m; ++i) window[static_cast<std::size_t>(i)] = curve[static_cast<std::size_t>((k + i) % n)];
    const auto fit = kasa_fit(window);
    if (fit && fit->radius <= 5 * size && (!best || fit->deviation < best->deviation)) {
      best = fit;
      r.window_start = wrap_two_pi(start + 2 * pi * k / n);
    }
  }
  if (!best) throw NoSolution("no arc of the coupler curve is close enough to a circle of practical radius");
  r.D = best->centre;
  r.radius = best->radius;
  r.arc_deviation = best->deviation;
}

// Output swing and dwell motion of one output dyad; false if it does not close over the turn.
bool measure(DwellResult& r, double dwell) {
  const int n = 720;
  double lo = 1e9, hi = -1e9, dlo = 1e9, dhi = -1e9, previous = 0;
  for (int k = 0; k <= n; ++k) {
    const double theta2 = r.window_start + 2 * pi * k / n;
    const auto a = output_angle(r, theta2);
    if (!a) return false;
    const double unwrapped = k == 0 ? *a : previous + std::remainder(*a - previous, 2 * pi);
    previous = unwrapped;
    lo = std::min(lo, unwrapped);
    hi = std::max(hi, unwrapped);
    if (2 * pi * k / n <= dwell + 1e-12) {
      dlo = std::min(dlo, unwrapped);
      dhi = std::max(dhi, unwrapped);
    }
  }
  r.swing = hi - lo;
  r.dwell_motion = dhi - dlo;
  return true;
}

// Tries output pivots around D (or the given one) and keeps the largest swing.
void place_output(const DwellTask& t, DwellResult& r) {
  const Vec2 P_mid = pose_at(r.four_bar, r.window_start + t.dwell / 2)->P;
  const double toward_arc = plane::angle_of(P_mid - r.D);
  std::vector<std::pair<Vec2, double>> pivots;
  if (t.output_pivot) {
    pivots.push_back({*t.output_pivot, (*t.output_pivot - r.D).norm()});
  } else {
    for (double scale : {1.0, 1.5, 2.0, 3.0})
      for (double turn : {90.0, -90.0, 60.0, -60.0, 120.0, -120.0}) {
        const double r6 = t.output_rocker ? *t.output_rocker : scale * r.radius;
        pivots.push_back({r.D + r6 * Vec2(std::cos(toward_arc + turn * pi / 180), std::sin(toward_arc + turn * pi / 180)), r6});
      }
  }
  std::optional<DwellResult> best;
  for (const auto& [O6, r6] : pivots) {
    DwellResult c = r;
    c.O6 = O6;
    c.output_rocker = r6;
    c.output_branch = branch_of(P_mid, r.D, O6) >= 0 ? 1 : -1;
    if (r6 > 0 && measure(c, t.dwell) && (!best || c.swing > best->swing)) best = c;
  }
  if (!best) throw NoSolution("no output rocker closes the six-bar over the whole turn; give another output pivot");
  r = *best;
}

}  // namespace

std::optional<double> output_angle(const DwellResult& s, double theta2) {
  const auto pose = pose_at(s.four_bar, theta2);
  if (!pose) return std::nullopt;
  const auto D = plane::circle_intersection(pose->P, s.radius, s.O6, s.output_rocker, s.output_branch);
  if (!D) return std::nullopt;
  return plane::angle_of(*D - s.O6);
}

DwellResult synthesize_dwell(const DwellTask& t) {
  if (!(t.dwell >= 5 * pi / 180 && t.dwell <= pi)) throw std::invalid_argument("dwell: the dwell must be 5..180 deg of crank");
  if (t.samples < 72 || t.samples > 7200) throw std::invalid_argument("dwell: samples must be 72..7200");
  const FourBar& f = t.four_bar;
  if (!(f.crank > 0 && f.coupler > 0 && f.rocker > 0 && f.ground() > 0) || (t.output_rocker && !(*t.output_rocker > 0)))
    throw std::invalid_argument("dwell: link lengths must be positive");
  if (!crank_turns_fully(f)) throw NoSolution("dwell: the four-bar's crank does not turn fully (not a Grashof crank)");
  DwellResult r;
  r.four_bar = f;
  find_arc(t, r);
  place_output(t, r);
  return r;
}

MechanismSketch dwell_sketch(const DwellResult& s, std::string title) {
  MechanismSketch k = four_bar_sketch(s.four_bar, s.window_start, 2 * pi, 1, std::move(title));
  const FourBarPose pose = *pose_at(s.four_bar, s.window_start);
  const Vec2 D = *plane::circle_intersection(pose.P, s.radius, s.O6, s.output_rocker, s.output_branch);
  k.ground.push_back({"O6", s.O6});
  k.links.push_back({"link5", {{"P", {0, 0}}, {"D", {s.radius, 0}}}, plane::angle_of(D - pose.P), pose.P});
  k.links.push_back({"rocker6", {{"O6", {0, 0}}, {"D", {s.output_rocker, 0}}}, plane::angle_of(D - s.O6), s.O6});
  k.joints.push_back({"P", "coupler.P", "link5.P"});
  k.joints.push_back({"D", "link5.D", "rocker6.D"});
  k.joints.push_back({"O6", "rocker6.O6", "ground.O6"});
  k.outputs.push_back({"theta6", "angle", "rocker6"});
  return k;
}

}  // namespace gearkit::synth
