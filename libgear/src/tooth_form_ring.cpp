// Rings cut by a pinion-type (shaper) cutter: the generating mesh, the root fillet as the
// envelope of the cutter's tip rounding, and the cutter's interference with the ring.
//
// Ring frame: ring centre at the origin, space 0 centred on +y. The cutter, an external gear of
// z_0 teeth, rolls inside the ring: its centre at angle delta (counter-clockwise from +y) on the
// circle of radius a_0 and its tooth 0 turned by psi = -(|z| - z_0)/z_0 delta (its working pitch
// circle rolls without slip on the ring's). At delta = 0 cutter tooth 0 is centred in space 0.
#include "tooth_form_detail.hpp"

#include <gearkit/gear/cylindrical_gear.hpp>
#include <gearkit/gear/involute.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

namespace gearkit::gear {

namespace {

constexpr double kPi = std::numbers::pi;
using detail::Polar;
using detail::Section;

Point2 rotated(Point2 p, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * p.x - s * p.y, s * p.x + c * p.y};
}

// The cutter in its own frame (tooth 0 along +y, eta measured from +y towards +x) and in mesh.
struct Cutter {
  RingCutting cut;
  int z_ring = 0;
  double r_0 = 0, r_b0 = 0, s_over_d0 = 0;  // reference and base radius, s_t0 / d_0
  double r_w2 = 0;                           // ring working pitch radius of the generating mesh
  double alpha_t = 0;
  Point2 centre_0;                           // tip rounding centre, cutter frame
  double tau_tip = 0, tau_flank = 0;         // outward normal directions at the two ends of the rounding

  // Half tooth angle of the cutter at radius R (its right flank).
  double psi0(double R) const { return s_over_d0 + involute(alpha_t) - involute(std::acos(std::min(1.0, r_b0 / R))); }
  double turn(double delta) const { return -(z_ring - cut.z_0) / static_cast<double>(cut.z_0) * delta; }
  Point2 to_ring(Point2 p, double delta) const {
    const Point2 q = rotated(p, turn(delta));
    return {q.x - cut.a_0 * std::sin(delta), q.y + cut.a_0 * std::cos(delta)};
  }
};

Point2 from_eta(double r, double eta) { return {r * std::sin(eta), r * std::cos(eta)}; }

void generating_mesh(const ToothFormSpec& s, const Section& c, Cutter& k) {
  const double alpha_n = s.rack.alpha_P;
  k.alpha_t = c.alpha_t;
  k.r_0 = 0.5 * k.cut.z_0 * c.m_t;
  k.r_b0 = k.r_0 * std::cos(c.alpha_t);
  const double s_t0 = reference_tooth_thickness(c.m_t, k.cut.x_0, alpha_n);
  k.s_over_d0 = s_t0 / (2.0 * k.r_0);
  // Zero backlash: cutter tooth on its working circle = ring space on the ring's (ISO 21771
  // internal pair with x_0 and the ring's x): inv alpha_w0 = inv alpha_t + (e_t2 - s_t0) / (2 (r_2 - r_0)).
  const double e_t2 = 2.0 * c.r * c.e_over_d;
  const double inv_alpha_w0 = involute(c.alpha_t) + (e_t2 - s_t0) / (2.0 * (c.r - k.r_0));
  if (!(inv_alpha_w0 > 0.0))
    throw std::invalid_argument(fmt::format(
        "ring cutter: the z_0 = {} cutter's teeth (s_t0 = {:.4f} mm) are too thick for the ring's spaces (e_t2 = {:.4f} mm) "
        "at a tooth difference of {}: no generating mesh without backlash (inv alpha_w0 = {:.4g}); use fewer cutter teeth",
        k.cut.z_0, s_t0, e_t2, k.z_ring - k.cut.z_0, inv_alpha_w0));
  k.cut.alpha_w0 = inverse_involute(inv_alpha_w0);
  k.cut.a_0 = (c.r - k.r_0) * std::cos(c.alpha_t) / std::cos(k.cut.alpha_w0);
  k.r_w2 = c.r * std::cos(c.alpha_t) / std::cos(k.cut.alpha_w0);
  const double r_f2 = c.r + (s.rack.h_fP - c.x_e) * s.m_n;
  k.cut.d_a0 = 2.0 * (r_f2 - k.cut.a_0);
}

// Angle of the tip rounding's centre from the tooth centre line; negative if the rounding does not
// fit (the two roundings would overlap) or its centre lies inside the base circle. The centre is on
// the flank's inward offset by rho, which is the involute turned by rho / r_b0.
double rounding_centre_eta(const Cutter& k, double rho) {
  const double R_c = 0.5 * k.cut.d_a0 - rho;
  if (R_c < k.r_b0) return -1.0;
  return k.psi0(R_c) - rho / k.r_b0;
}

// The largest tip rounding the cutter tooth takes (full-radius tip), by bisection.
double largest_tip_rounding(const Cutter& k) {
  double lo = 0.0, hi = 0.5 * k.cut.d_a0 - k.r_b0;
  for (int i = 0; i < 100; ++i) (rounding_centre_eta(k, 0.5 * (lo + hi)) >= 0.0 ? lo : hi) = 0.5 * (lo + hi);
  return lo;
}

void tip_rounding(Cutter& k, double rho_asked) {
  const double r_a0 = 0.5 * k.cut.d_a0;
  if (!(r_a0 > k.r_b0))
    throw std::invalid_argument(fmt::format("ring cutter: the z_0 = {} cutter's tip circle (d_a0 = {:.4f} mm) lies inside its "
                                            "base circle (d_b0 = {:.4f} mm): more cutter teeth or a larger x_0",
                                            k.cut.z_0, k.cut.d_a0, 2.0 * k.r_b0));
  const double rho_max = largest_tip_rounding(k);
  // Default: the rack's rho_fP m_n, or 3/4 of the full-radius rounding where that does not fit
  // (a 20 deg cutter with 1.25 m_n addendum has a tip about 0.4 m_n thick).
  k.cut.rho_a0 = rho_asked >= 0.0 ? rho_asked : std::min(k.cut.rho_a0, 0.75 * rho_max);
  const double rho = k.cut.rho_a0;
  if (rho > rho_max) {
    throw std::invalid_argument(fmt::format("ring cutter: a tip rounding of {:.4g} mm does not fit the z_0 = {} cutter's tooth "
                                            "(at most {:.4g} mm)", rho, k.cut.z_0, rho_max));
  }
  const double R_c = r_a0 - rho;
  const double eta_c = rounding_centre_eta(k, rho);
  k.centre_0 = from_eta(R_c, eta_c);
  k.tau_tip = eta_c;
  // Tangent point on the flank: roll length of the centre + rho; the flank normal there points
  // 90 deg clockwise from the base-circle tangent point T (eta_T = eta_P - alpha_P).
  const double roll = std::sqrt(R_c * R_c - k.r_b0 * k.r_b0) + rho;
  const double R_P = std::hypot(k.r_b0, roll);
  const double alpha_P = std::atan(roll / k.r_b0);
  k.tau_flank = k.psi0(R_P) - alpha_P + kPi / 2.0;
}

Cutter cutter_of(const ToothFormSpec& s, const Section& c, int z_0) {
  Cutter k;
  k.z_ring = -s.z;
  k.cut.z_0 = z_0;
  if (k.cut.z_0 < 5 || k.cut.z_0 >= k.z_ring)
    throw std::invalid_argument(fmt::format("ring cutter: expected 5 <= z_0 < |z| = {} teeth, found {}", k.z_ring, z_0));
  k.cut.x_0 = s.cutter.x_0;
  k.cut.rho_a0 = s.rack.rho_fP * s.m_n;
  generating_mesh(s, c, k);
  tip_rounding(k, s.cutter.rho_a0);
  return k;
}

// The point of the rounding that touches the ring at delta: on the line from the pitch point
// through the rounding's centre (law of gearing), on the outer side of the rounding.
Point2 fillet_point(const Cutter& k, double delta) {
  const Point2 cc = k.to_ring(k.centre_0, delta);
  const Point2 pitch{-k.r_w2 * std::sin(delta), k.r_w2 * std::cos(delta)};
  double ux = cc.x - pitch.x, uy = cc.y - pitch.y;
  const double len = std::hypot(ux, uy);
  ux /= len;
  uy /= len;
  const double tau_mid = 0.5 * (k.tau_tip + k.tau_flank);
  const Point2 n_mid = rotated(from_eta(1.0, tau_mid), k.turn(delta));
  const double side = ux * n_mid.x + uy * n_mid.y >= 0.0 ? 1.0 : -1.0;
  return {cc.x + side * k.cut.rho_a0 * ux, cc.y + side * k.cut.rho_a0 * uy};
}

// Direction (cutter frame, eta convention) of the rounding's normal at the touching point, minus `target`.
double normal_offset(const Cutter& k, double delta, double target) {
  const Point2 cc = k.to_ring(k.centre_0, delta);
  const Point2 p = fillet_point(k, delta);
  const Point2 n = rotated({p.x - cc.x, p.y - cc.y}, -k.turn(delta));
  return std::remainder(std::atan2(n.x, n.y) - target, 2.0 * kPi);
}

// The sign change of normal_offset nearest to delta = 0 over +-span, scanned in `steps`; NaN if none.
double nearest_normal(const Cutter& k, double target, double span, int steps) {
  double best = NAN;
  for (int i = 0; i < steps; ++i) {
    const double a = -span + 2.0 * span * i / steps, b = a + 2.0 * span / steps;
    const double fa = normal_offset(k, a, target), fb = normal_offset(k, b, target);
    if ((fa > 0.0) == (fb > 0.0) || std::fabs(fa - fb) > 1.0) continue;
    const double root = detail::bisect([&](double d) { return normal_offset(k, d, target); }, a, b);
    if (std::isnan(best) || std::fabs(root) < std::fabs(best)) best = root;
  }
  return best;
}

// The cutter turn delta at which the rounding's normal points along `target`: the sign change
// nearest to delta = 0, over +-2 ring pitches, else over half a turn of the cutter either way
// (a cutter of nearly the ring's size rolls slowly: |z| - z_0 = 10 at alpha_w0 = 6 deg needs
// about 5 ring pitches), at the same density.
double delta_for_normal(const Cutter& k, double target) {
  const double near = 4.0 * kPi / k.z_ring;
  constexpr int kScan = 2000;
  double best = nearest_normal(k, target, near, kScan);
  const double wide = std::max(near, kPi * k.cut.z_0 / k.z_ring);
  if (std::isnan(best) && wide > near) best = nearest_normal(k, target, wide, static_cast<int>(std::ceil(kScan * wide / near)));
  if (std::isnan(best))
    throw std::invalid_argument(fmt::format("ring cutter: the z_0 = {} cutter's tip rounding never touches the ring's flank "
                                            "within half a turn of the generating mesh (alpha_w0 = {:.3f} deg); use fewer "
                                            "cutter teeth", k.cut.z_0, k.cut.alpha_w0 * 180.0 / kPi));
  return best;
}

// Deepest cut of the rounding into a ring tooth between the tip circle and the form radius over a
// half turn of the cutter either way (distance normal to the involute = r_b2 times the angle).
double tip_interference(const Cutter& k, const Section& c, double r_form) {
  const double pitch = 2.0 * kPi / k.z_ring;
  const double range = kPi * k.cut.z_0 / k.z_ring;
  constexpr int kSteps = 4000, kArc = 12;
  double worst = 0.0;
  for (int i = 0; i <= kSteps; ++i) {
    const double delta = -range + 2.0 * range * i / kSteps;
    for (int j = 0; j <= kArc; ++j) {
      const double tau = k.tau_tip + (k.tau_flank - k.tau_tip) * j / kArc;
      const Point2 e = from_eta(k.cut.rho_a0, tau);
      const Polar q = detail::to_polar(k.to_ring({k.centre_0.x + e.x, k.centre_0.y + e.y}, delta));
      if (q.r <= std::max(c.r_a, c.r_b) || q.r >= r_form) continue;
      const double eta_i = detail::involute_eta(c, true, q.r);
      const double eta = q.eta - pitch * std::floor(q.eta / pitch);  // into [0, pitch)
      worst = std::max(worst, c.r_b * std::min(eta - eta_i, pitch - eta_i - eta));
    }
  }
  return worst;
}

// The interference numbers of ring_cutting for cutter k.
RingCutting cutting_of(const Cutter& k, const Section& c) {
  RingCutting out = k.cut;
  const double reach = std::sqrt(std::max(0.0, c.r_a * c.r_a - c.r_b * c.r_b));
  out.involute_interference = std::max(0.0, out.a_0 * std::sin(out.alpha_w0) - reach);
  const double d_form = delta_for_normal(k, k.tau_flank);
  out.tip_interference = tip_interference(k, c, detail::to_polar(fillet_point(k, d_form)).r);
  return out;
}

// The default cutter: from default_cutter_teeth downwards, the first that cuts the ring cleanly
// (no involute interference, tip interference below 1e-7 mm, the finest outline tolerance), so
// the report never warns about a cutter the user did not choose; if none does, the largest
// that cuts at all (the report warns), else the nominal cutter's reason.
Cutter make_cutter(const ToothFormSpec& s, const Section& c) {
  if (s.z >= 0) throw std::invalid_argument("ring cutting: expected a ring (z < 0)");
  if (s.cutter.z_0 > 0) return cutter_of(s, c, s.cutter.z_0);
  const int nominal = default_cutter_teeth(s.z, c.m_t);
  std::optional<Cutter> usable;
  std::string reason;
  for (int z_0 = nominal; z_0 >= 5; --z_0) {
    try {
      const Cutter k = cutter_of(s, c, z_0);
      const RingCutting r = cutting_of(k, c);
      if (r.involute_interference == 0.0 && r.tip_interference <= 1e-7) return k;
      if (!usable) usable = k;
    } catch (const std::invalid_argument& e) {
      if (reason.empty()) reason = e.what();
    }
  }
  if (usable) return *usable;
  throw std::invalid_argument(fmt::format("{} (the default cutter; none of 5 to {} teeth cuts this ring)", reason, nominal));
}

}  // namespace

int default_cutter_teeth(int z_ring, double m_t) {
  const int z = std::abs(z_ring);
  if (z < 8) throw std::invalid_argument("ring cutter: a ring needs at least 8 teeth for a default cutter");
  const int upper = z >= 20 ? z - 10 : z - 3;
  return std::clamp(static_cast<int>(std::lround(100.0 / m_t)), std::min(10, upper), upper);
}

std::vector<detail::Polar> detail::ring_flank(const ToothFormSpec& s, const Section& c) {
  const Cutter k = make_cutter(s, c);
  const double d_root = delta_for_normal(k, k.tau_tip);
  const double d_form = delta_for_normal(k, k.tau_flank);
  const Curve fillet = [&](double delta) { return fillet_point(k, delta); };
  const double d_join = fillet_involute_crossing(fillet, c, true, d_root, d_form);
  return join_fillet_and_involute(fillet, d_root, d_join, c, true, s.tolerance);
}

RingCutting ring_cutting(const ToothFormSpec& s) {
  const Section c = detail::section_of(s);
  return cutting_of(make_cutter(s, c), c);
}

}  // namespace gearkit::gear
