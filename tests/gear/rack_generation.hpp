#pragma once
// An independent cutting simulation for the tooth-form tests: the gear space is the union of all
// positions of the tool tooth, so at a radius R its right boundary is the largest angle at which
// any position of the tool's right edge crosses the circle of radius R. No envelope formula, no
// law of gearing: the tool edge is a height function x(y) built from the normal-section basic rack
// (ISO 53) and stretched by 1/cos(beta) into the transverse section, the positions are scanned and
// the largest angle refined by golden-section search.
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

namespace rack_generation {

/// The right edge of the tool tooth (rack or shaper cutter) as x(y) in its own frame, y from
/// y_low (its tip) to y_high, and the transform of a tool point into the gear frame at position s.
struct Tool {
  std::function<double(double)> x_of_y;
  double y_low = 0, y_high = 0;
  std::function<void(double s, double& x, double& y)> to_gear;  // in place
  double s_min = 0, s_max = 0;  // positions scanned
  /// Optional: the largest angle at which the tool's tip land (from its centre line to x_of_y(y_low))
  /// crosses the circle R at position s (-inf: nowhere); the edge scan can miss its shallow crossings.
  std::function<double(double s, double R)> tip_land;
};

/// Angle from +y towards +x of the points where the tool's right edge at position s crosses the
/// circle of radius R (gear frame); -inf if it does not.
inline double crossing_eta(const Tool& tool, double s, double R) {
  auto radius_excess = [&](double y) {
    double gx = tool.x_of_y(y), gy = y;
    tool.to_gear(s, gx, gy);
    return std::hypot(gx, gy) - R;
  };
  constexpr int kScan = 24;
  double best = tool.tip_land ? tool.tip_land(s, R) : -std::numeric_limits<double>::infinity();
  double ya = tool.y_low, fa = radius_excess(ya);
  for (int i = 1; i <= kScan; ++i) {
    double yb = tool.y_low + (tool.y_high - tool.y_low) * i / kScan;
    const double fb = radius_excess(yb);
    if ((fa > 0.0) != (fb > 0.0)) {
      double lo = ya, hi = yb, flo = fa;
      for (int k = 0; k < 52; ++k) {
        const double mid = 0.5 * (lo + hi), fm = radius_excess(mid);
        if ((fm > 0.0) == (flo > 0.0)) { lo = mid; flo = fm; } else { hi = mid; }
      }
      double gx = tool.x_of_y(0.5 * (lo + hi)), gy = 0.5 * (lo + hi);
      tool.to_gear(s, gx, gy);
      best = std::max(best, std::atan2(gx, gy));
    }
    ya = yb;
    fa = fb;
  }
  return best;
}

/// Right boundary of the cut space at radius R: max over positions of crossing_eta.
inline double space_eta(const Tool& tool, double R) {
  constexpr int kScan = 240;
  const double step = (tool.s_max - tool.s_min) / kScan;
  double best_s = tool.s_min, best = -std::numeric_limits<double>::infinity();
  for (int i = 0; i <= kScan; ++i) {
    const double s = tool.s_min + step * i, e = crossing_eta(tool, s, R);
    if (e > best) { best = e; best_s = s; }
  }
  // Golden-section refinement around the best sample.
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = best_s - step, b = best_s + step;
  double c = b - g * (b - a), d = a + g * (b - a);
  double fc = crossing_eta(tool, c, R), fd = crossing_eta(tool, d, R);
  for (int k = 0; k < 60; ++k) {
    if (fc > fd) { b = d; d = c; fd = fc; c = b - g * (b - a); fc = crossing_eta(tool, c, R); }
    else { a = c; c = d; fc = fd; d = a + g * (b - a); fd = crossing_eta(tool, d, R); }
  }
  return std::max({best, fc, fd});
}

/// The basic rack (ISO 53, normal section: pressure angle alpha_n, dedendum h_fP*, tip radius
/// rho_fP*) cutting a gear of reference radius r (transverse) with generating shift x_e m_n:
/// the datum line at r + x_e m_n, tool tooth 0 centred on the +y axis at s = 0. The gear turns
/// by -s/r while the rack moves by s.
inline Tool rack(double r, double m_n, double beta, double x_e, double alpha_n, double h_fP, double rho_fP, double s_range) {
  const double y_d = r + x_e * m_n, y_tip = y_d - h_fP * m_n, rho = rho_fP * m_n;
  const double y_c = y_tip + rho;
  auto flank_x = [=](double y) { return std::numbers::pi * m_n / 4.0 - (y_d - y) * std::tan(alpha_n); };
  const double x_c = flank_x(y_c) - rho / std::cos(alpha_n);  // centre at distance rho from the flank
  const double y_t = y_c - rho * std::sin(alpha_n);               // tangent point with the flank
  Tool t;
  t.x_of_y = [=](double y) {
    const double x_n = y >= y_t ? flank_x(y) : x_c + std::sqrt(std::max(0.0, rho * rho - (y - y_c) * (y - y_c)));
    return x_n / std::cos(beta);
  };
  t.y_low = y_tip;
  t.y_high = y_d + 2.0 * m_n;
  t.to_gear = [=](double s, double& x, double& y) {
    const double phi = s / r, fx = x + s;
    x = fx * std::cos(phi) - y * std::sin(phi);
    y = fx * std::sin(phi) + y * std::cos(phi);
  };
  const double x_tip = t.x_of_y(y_tip);
  t.tip_land = [=, to_gear = t.to_gear](double s, double R) {
    double best = -std::numeric_limits<double>::infinity();
    if (R < y_tip) return best;
    for (double sign : {-1.0, 1.0}) {  // hypot(x + s, y_tip) = R
      double x = sign * std::sqrt(R * R - y_tip * y_tip) - s, y = y_tip;
      if (x < -x_tip || x > x_tip) continue;
      to_gear(s, x, y);
      best = std::max(best, std::atan2(x, y));
    }
    return best;
  };
  t.s_min = -s_range;
  t.s_max = s_range;
  return t;
}

}  // namespace rack_generation

namespace rack_generation {

/// A pinion-type cutter (transverse section: z_0 teeth, module m_t, pressure angle alpha_t, tooth
/// thickness s_t0 on its reference circle, tip radius r_a0, tip rounding rho) cutting a ring of
/// |z| teeth at centre distance a_0: its centre at angle delta from +y on the circle a_0, turned
/// by -(|z| - z_0)/z_0 delta. The edge parameter y is the depth below the cutter's tip circle.
inline Tool shaper(int z_ring, int z_0, double m_t, double alpha_t, double s_t0, double r_a0, double rho, double a_0) {
  const double r_0 = 0.5 * z_0 * m_t, r_b0 = r_0 * std::cos(alpha_t);
  auto inv = [](double a) { return std::tan(a) - a; };
  // Half tooth angle of the involute flank at radius R (ISO 21771 tooth thickness at a diameter).
  auto psi = [=](double R) { return s_t0 / (2.0 * r_0) + inv(alpha_t) - inv(std::acos(r_b0 / R)); };
  // Rounding: the circle of radius rho inside the tooth touching the tip circle and the flank;
  // its centre found by bisection on the distance to the flank (sampled involute, no offset formula).
  const double R_c = r_a0 - rho;
  auto flank_distance = [=](double eta_c) {
    double best = 1e9;
    for (int i = 0; i <= 4000; ++i) {
      const double R = r_b0 + (r_a0 - r_b0) * i / 4000.0, e = psi(R);
      best = std::min(best, std::hypot(R * std::sin(e) - R_c * std::sin(eta_c), R * std::cos(e) - R_c * std::cos(eta_c)));
    }
    return best - rho;
  };
  double lo = 0.0, hi = psi(R_c);
  for (int k = 0; k < 50; ++k) (flank_distance(0.5 * (lo + hi)) > 0.0 ? lo : hi) = 0.5 * (lo + hi);
  const double eta_c = 0.5 * (lo + hi);
  auto round = [=](double R) {  // the rounding's outer point at radius R
    const double c = (R * R + R_c * R_c - rho * rho) / (2.0 * R * R_c);
    return eta_c + std::acos(std::clamp(c, -1.0, 1.0));
  };
  double R_P = R_c, gap = 1e9;  // tangent point: where the rounding comes closest to the flank
  for (int i = 0; i <= 20000; ++i) {
    const double R = std::max(R_c, r_b0) + (r_a0 - std::max(R_c, r_b0)) * i / 20000.0;
    if (psi(R) - round(R) < gap) { gap = psi(R) - round(R); R_P = R; }
  }
  Tool t;
  t.x_of_y = [=](double y) {  // angle of the right edge at radius r_a0 - y
    const double R = r_a0 - y;
    return R >= R_P ? round(R) : psi(std::max(R, r_b0));
  };
  t.y_low = 0.0;
  t.y_high = r_a0 - r_b0;
  t.to_gear = [=](double delta, double& x, double& y) {
    const double R = r_a0 - y, eta = x, turn = -(z_ring - z_0) / static_cast<double>(z_0) * delta;
    const double px = R * std::sin(eta), py = R * std::cos(eta);
    x = std::cos(turn) * px - std::sin(turn) * py - a_0 * std::sin(delta);
    y = std::sin(turn) * px + std::cos(turn) * py + a_0 * std::cos(delta);
  };
  t.tip_land = [=, to_gear = t.to_gear](double delta, double R) {
    auto excess = [&](double eta) { double x = eta, y = 0.0; to_gear(delta, x, y); return std::hypot(x, y) - R; };
    double best = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < 32; ++i) {
      double a = eta_c * i / 32.0, b = eta_c * (i + 1) / 32.0;
      if ((excess(a) > 0.0) == (excess(b) > 0.0)) continue;
      for (int k = 0; k < 52; ++k) ((excess(0.5 * (a + b)) > 0.0) == (excess(a) > 0.0) ? a : b) = 0.5 * (a + b);
      double x = 0.5 * (a + b), y = 0.0;
      to_gear(delta, x, y);
      best = std::max(best, std::atan2(x, y));
    }
    return best;
  };
  const double span = 2.0 * std::numbers::pi / z_ring;
  t.s_min = -1.5 * span;
  t.s_max = 1.5 * span;
  return t;
}

}  // namespace rack_generation
