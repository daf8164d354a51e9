// Curves shared by the external and internal tooth forms: involute, sampling within a
// tolerance, fillet/involute crossing.
#include "tooth_form_detail.hpp"

#include <gearkit/gear/cylindrical_gear.hpp>
#include <gearkit/gear/involute.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gearkit::gear::detail {

Polar to_polar(Point2 p) { return {std::hypot(p.x, p.y), std::atan2(p.x, p.y)}; }

Point2 to_point(Polar q) { return {q.r * std::sin(q.eta), q.r * std::cos(q.eta)}; }

Section section_of(const ToothFormSpec& s) {
  if (s.z == 0 || !(s.m_n > 0.0)) throw std::invalid_argument("tooth form: expected z != 0 and m_n > 0");
  if (!(s.tolerance >= 1e-7 && s.tolerance <= 1.0)) {
    throw std::invalid_argument("tooth form: expected a tolerance from 1e-7 to 1 mm");
  }
  Section c;
  const double tan_n = std::tan(s.rack.alpha_P);
  c.x_e = s.x + s.A_sn / (2.0 * s.m_n * tan_n);
  c.m_t = transverse_module(s.m_n, s.beta);
  c.alpha_t = transverse_pressure_angle(s.rack.alpha_P, s.beta);
  c.r = 0.5 * std::fabs(s.z) * c.m_t;
  c.r_b = c.r * std::cos(c.alpha_t);
  c.r_a = 0.5 * std::fabs(s.d_a);
  const double s_t = reference_tooth_thickness(c.m_t, c.x_e, s.rack.alpha_P);
  c.e_over_d = (std::numbers::pi * c.m_t - s_t) / (2.0 * c.r);
  return c;
}

double involute_eta(const Section& c, bool ring, double r_y) {
  const double a_y = std::acos(std::min(1.0, c.r_b / r_y));
  const double d_inv = involute(a_y) - involute(c.alpha_t);
  return ring ? c.e_over_d - d_inv : c.e_over_d + d_inv;
}

Point2 InvoluteCurve::operator()(double xi) const {
  const double r_y = c.r_b * std::sqrt(1.0 + xi * xi);
  const double d_inv = (xi - std::atan(xi)) - involute(c.alpha_t);
  return to_point({r_y, ring ? c.e_over_d - d_inv : c.e_over_d + d_inv});
}

double InvoluteCurve::xi_at(const Section& c, double r) {
  return r <= c.r_b ? 0.0 : std::sqrt((r / c.r_b) * (r / c.r_b) - 1.0);
}

namespace {

double distance_to_chord(Point2 p, Point2 a, Point2 b) {
  const double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
  if (len == 0.0) return std::hypot(p.x - a.x, p.y - a.y);
  return std::fabs((p.x - a.x) * dy - (p.y - a.y) * dx) / len;
}

void sample_segment(const Curve& curve, double t0, Point2 p0, double t1, Point2 p1, double tol, int depth,
                    std::vector<Point2>& out) {
  const double tm = 0.5 * (t0 + t1);
  const Point2 pm = curve(tm);
  double dev = distance_to_chord(pm, p0, p1);
  dev = std::max(dev, distance_to_chord(curve(0.5 * (t0 + tm)), p0, p1));
  dev = std::max(dev, distance_to_chord(curve(0.5 * (tm + t1)), p0, p1));
  if (dev > 0.5 * tol && depth < 40) {
    sample_segment(curve, t0, p0, tm, pm, tol, depth + 1, out);
    sample_segment(curve, tm, pm, t1, p1, tol, depth + 1, out);
    return;
  }
  if (out.size() > 200000) throw std::runtime_error("tooth form: more than 200000 points for one flank");
  out.push_back(p1);
}

}  // namespace

void sample_within(const Curve& curve, double t0, double t1, double tolerance, std::vector<Point2>& out) {
  constexpr int kStart = 8;  // a first uniform split, so that no inflexion hides between probes
  Point2 prev = curve(t0);
  out.push_back(prev);
  for (int i = 1; i <= kStart; ++i) {
    const double ta = t0 + (t1 - t0) * (i - 1) / kStart, tb = i == kStart ? t1 : t0 + (t1 - t0) * i / kStart;
    const Point2 next = curve(tb);
    sample_segment(curve, ta, prev, tb, next, tolerance, 0, out);
    prev = next;
  }
}

double bisect(const std::function<double(double)>& f, double a, double b) {
  double fa = f(a);
  for (int i = 0; i < 200 && std::fabs(b - a) > 1e-15 * std::max(1.0, std::fabs(a)); ++i) {
    const double m = 0.5 * (a + b), fm = f(m);
    if ((fm > 0.0) == (fa > 0.0)) {
      a = m;
      fa = fm;
    } else {
      b = m;
    }
  }
  return 0.5 * (a + b);
}

double fillet_involute_crossing(const Curve& fillet, const Section& c, bool ring, double t0, double t1) {
  // Positive while the fillet lies on the space side of the involute (or where there is no involute).
  auto excess = [&](double t) {
    const Polar q = to_polar(fillet(t));
    if (q.r < c.r_b) return 1.0;
    return q.eta - involute_eta(c, ring, q.r);
  };
  constexpr int kScan = 512;
  double prev = t0;
  for (int i = 1; i <= kScan; ++i) {
    const double t = t0 + (t1 - t0) * i / kScan;
    if (excess(t) < 0.0 && excess(prev) > 0.0) return bisect(excess, prev, t);
    prev = t;
  }
  return t1;
}

std::vector<Polar> join_fillet_and_involute(const Curve& fillet, double t_root, double t_join, const Section& c,
                                            bool ring, double tolerance) {
  std::vector<Point2> pts;
  if (t_join > t_root) sample_within(fillet, t_root, t_join, tolerance, pts);
  else pts.push_back(fillet(t_root));
  const double r_join = std::max(to_polar(pts.back()).r, c.r_b);
  const double r_end = std::max(c.r_a, c.r_b);
  if (std::fabs(r_end - r_join) > 1e-12) {
    std::vector<Point2> inv;
    const InvoluteCurve curve{c, ring};
    sample_within(curve, InvoluteCurve::xi_at(c, r_join), InvoluteCurve::xi_at(c, r_end), tolerance, inv);
    // The fillet ends on the involute (tangent, or at the crossing): do not repeat that point.
    const bool repeated = std::hypot(inv.front().x - pts.back().x, inv.front().y - pts.back().y) < 1e-9;
    pts.insert(pts.end(), inv.begin() + (repeated ? 1 : 0), inv.end());
  }
  std::vector<Polar> out;
  out.reserve(pts.size() + 1);
  for (Point2 p : pts) out.push_back(to_polar(p));
  if (ring && c.r_a < c.r_b) out.push_back({c.r_a, out.back().eta});  // ring tip inside the base circle: radial edge
  return out;
}

}  // namespace gearkit::gear::detail
