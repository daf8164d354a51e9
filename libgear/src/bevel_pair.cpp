// The bevel pair's table and forces (libgear/include/gearkit/gear/bevel.hpp).
#include <gearkit/gear/bevel.hpp>

#include <gearkit/gear/cylindrical_gear.hpp>
#include <gearkit/gear/rack.hpp>

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace gearkit::gear {

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

// Gleason proportions at the outer end, in m_et: half the working depth h_a* and the clearance
// c* (whole depth 2 h_a* + c*): straight and Zerol 2.000 / 2.188 (KHK), spiral 1.700 / 1.888
// (Gleason spiral bevel system).
double gleason_addendum_coefficient(BevelType type) { return type == BevelType::spiral ? 0.85 : 1.0; }
constexpr double kGleasonClearance = 0.188;
// ISO 23509 basic proportions at the mean point, in m_mn (basic rack of ISO 53).
constexpr double kIsoAddendum = 1.0, kIsoDedendum = 1.25;

void validate(const BevelPairInput& in) {
  if (in.z1 < 1 || in.z1 > 10000) throw GeometryError("z1", fmt::format("expected 1 <= z1 <= 10000, found {}", in.z1));
  if (in.z2 < 1 || in.z2 > 10000) throw GeometryError("z2", fmt::format("expected 1 <= z2 <= 10000, found {}", in.z2));
  if (!(in.m_et > 0.0 && in.m_et < 1e4)) throw GeometryError("module", fmt::format("expected 0 < m_et < 10000 mm, found {:g} mm", in.m_et));
  if (!(in.Sigma > 0.0 && in.Sigma < std::numbers::pi))
    throw GeometryError("shaft_angle", fmt::format("expected 0 < Sigma < 180 deg, found {:g} deg", in.Sigma * kDeg));
  if (!(in.alpha_n > 0.0 && in.alpha_n < std::numbers::pi / 4.0))
    throw GeometryError("pressure_angle", fmt::format("expected 0 < alpha_n < 45 deg, found {:g} deg", in.alpha_n * kDeg));
  if (in.type == BevelType::spiral) {
    if (!(in.beta_m > 0.0 && in.beta_m < std::numbers::pi / 3.0))
      throw GeometryError("spiral_angle", fmt::format("a spiral bevel needs 0 < beta_m < 60 deg, found {:g} deg", in.beta_m * kDeg));
  } else if (in.beta_m != 0.0) {
    throw GeometryError("spiral_angle", fmt::format("a {} bevel has beta_m = 0, found {:g} deg (give --type spiral)", to_string(in.type), in.beta_m * kDeg));
  }
}

void check_cones(const BevelPairInput& in, double delta1, double delta2, double R_e) {
  for (const double delta : {delta1, delta2})
    if (!(delta < 0.5 * std::numbers::pi - 1e-9))
      throw GeometryError("shaft_angle", fmt::format("expected pitch cone angles below 90 deg, found {:.4f} deg: crown gears (90 deg) and "
                                                     "internal bevel gears (over 90 deg) are not covered", delta * kDeg));
  if (!(in.b > 0.0 && in.b < R_e))
    throw GeometryError("face_width", fmt::format("expected 0 < b < R_e = {:.3f} mm, found {:g} mm", R_e, in.b));
}

// Addenda, dedenda and their angles of both gears; fills h_ae, h_fe, h_am, h_fm, theta_a,
// theta_f and x_he/x_hm's input.
void depths(const BevelPairInput& in, BevelPairResult& r) {
  auto& g1 = r.gear[0];
  auto& g2 = r.gear[1];
  const double half_b = 0.5 * in.b;
  if (in.system == BevelSystem::gleason) {
    const double h_a = gleason_addendum_coefficient(in.type);
    const double x = in.x1 ? *in.x1 : gleason_addendum_shift(in.type, r.u_v);
    g1.h_ae = in.m_et * (h_a + x);
    g2.h_ae = in.m_et * (h_a - x);
    for (auto* g : {&g1, &g2}) g->h_fe = in.m_et * (2.0 * h_a + kGleasonClearance) - g->h_ae;
  } else {
    const double x = in.x1 ? *in.x1 : 0.0;
    g1.h_am = r.m_mn * (kIsoAddendum + x);
    g2.h_am = r.m_mn * (kIsoAddendum - x);
    g1.h_fm = r.m_mn * (kIsoDedendum - x);
    g2.h_fm = r.m_mn * (kIsoDedendum + x);
  }
  for (auto* g : {&g1, &g2})
    if (!((in.system == BevelSystem::gleason ? g->h_ae : g->h_am) > 0.0 && (in.system == BevelSystem::gleason ? g->h_fe : g->h_fm) > 0.0))
      throw GeometryError("x1", fmt::format("the addendum modification leaves gear {} without addendum or dedendum", g == &g1 ? 1 : 2));
  // Angles of cones through the apex, from the section where the depths are defined.
  const bool outer = in.system == BevelSystem::gleason;
  const double R = outer ? r.R_e : r.R_m;
  for (auto* g : {&g1, &g2}) {
    const double h_a = outer ? g->h_ae : g->h_am, h_f = outer ? g->h_fe : g->h_fm;
    g->theta_f = in.taper == DepthTaper::uniform ? 0.0 : cone_angle_of_depth(h_f, R);
    g->theta_a = in.taper == DepthTaper::standard ? cone_angle_of_depth(h_a, R) : 0.0;
  }
  if (in.taper == DepthTaper::constant_clearance) {
    g1.theta_a = g2.theta_f;
    g2.theta_a = g1.theta_f;
  }
  for (auto* g : {&g1, &g2}) {
    if (outer) {
      g->h_am = g->h_ae - half_b * std::tan(g->theta_a);
      g->h_fm = g->h_fe - half_b * std::tan(g->theta_f);
    } else {
      g->h_ae = g->h_am + half_b * std::tan(g->theta_a);
      g->h_fe = g->h_fm + half_b * std::tan(g->theta_f);
    }
    g->h_ai = g->h_ae - in.b * std::tan(g->theta_a);
    g->h_fi = g->h_fe - in.b * std::tan(g->theta_f);
  }
  r.c = g1.h_fe - g2.h_ae;
  r.h_mw = g1.h_am + g2.h_am;
  const double h_ew = g1.h_ae + g2.h_ae;
  for (auto* g : {&g1, &g2}) {
    g->x_he = (g->h_ae - 0.5 * h_ew) / in.m_et;
    g->x_hm = (g->h_am - 0.5 * r.h_mw) / r.m_mn;
  }
}

void gear_dimensions(const BevelPairInput& in, BevelPairResult& r, BevelGearResult& g) {
  g.d_e = g.z * in.m_et;
  g.d_m = g.d_e * r.R_m / r.R_e;
  g.d_i = g.d_e * r.R_i / r.R_e;
  g.delta_a = g.delta + g.theta_a;
  g.delta_f = g.delta - g.theta_f;
  g.d_ae = outer_tip_diameter(g.d_e, g.h_ae, g.delta);
  g.d_fe = g.d_e - 2.0 * g.h_fe * std::cos(g.delta);
  // Along the tip cone the face width b (measured on the pitch cone) spans b / cos theta_a.
  const double b_a = in.b / std::cos(g.theta_a);
  g.d_ai = g.d_ae - 2.0 * b_a * std::sin(g.delta_a);
  g.b_x = b_a * std::cos(g.delta_a);
  g.t_xo = crown_to_crossing_point(r.R_e, g.h_ae, g.delta);
  g.t_xi = g.t_xo - g.b_x;
  g.t_zm = r.R_m * std::cos(g.delta);
}

void virtual_gear(const BevelPairInput& in, const BevelPairResult& r, BevelGearResult& g) {
  g.z_v = virtual_teeth(g.z, g.delta);
  g.z_vn = virtual_teeth_normal(g.z_v, in.beta_m, in.alpha_n);
  g.d_v = g.d_m / std::cos(g.delta);
  g.d_va = g.d_v + 2.0 * g.h_am;
  g.d_vb = g.d_v * std::cos(r.alpha_vt);
  // The generating crown gear's straight flank reaches the mate's mean addendum: undercut when it
  // ends below the interference point of the virtual gear (ISO 53-type limit without tip radius).
  const double h_a = 0.5 * r.h_mw / r.m_mn;
  g.x_min = min_shift_no_undercut(g.d_v, r.m_mn, r.alpha_vt, Rack{in.alpha_n, h_a, h_a, 0.0});
}

void add_warnings(const BevelPairInput& in, BevelPairResult& r) {
  if (in.b > r.R_e / 3.0 + 1e-9)
    r.warnings.push_back(fmt::format("face width b = {:g} mm exceeds R_e/3 = {:.3f} mm (Gleason/KHK limit: longer teeth are hard to cut "
                                     "and carry poorly at the inner end)", in.b, r.R_e / 3.0));
  if (in.b > 10.0 * in.m_et + 1e-9)
    r.warnings.push_back(fmt::format("face width b = {:g} mm exceeds 10 m_et = {:g} mm (Gleason/KHK limit)", in.b, 10.0 * in.m_et));
  for (int i = 0; i < 2; ++i) {
    const auto& g = r.gear[i];
    if (g.x_hm < g.x_min - 1e-9)
      r.warnings.push_back(fmt::format("gear {} is undercut: x_hm = {:.4f} < x_min = {:.4f} on its virtual gear (z_vn = {:.2f}); "
                                       "raise x1 or the tooth count", i + 1, g.x_hm, g.x_min, g.z_vn));
    if (!(g.h_ai > 0.0 && g.h_fi > 0.0))
      r.warnings.push_back(fmt::format("gear {}: the tooth depth vanishes before the inner end (h_ai = {:.3f} mm, h_fi = {:.3f} mm); "
                                       "shorten the face width or use uniform depth", i + 1, g.h_ai, g.h_fi));
  }
  const double eps = in.type == BevelType::spiral ? r.eps_vg : r.eps_va;
  if (!(eps >= 1.0))
    r.warnings.push_back(fmt::format("the contact ratio of the virtual gears is {:.3f} < 1: the teeth lose contact", eps));
}

}  // namespace

BevelPairResult compute_bevel_pair(const BevelPairInput& in) {
  validate(in);
  BevelPairResult r;
  auto& g1 = r.gear[0];
  auto& g2 = r.gear[1];
  g1.z = in.z1;
  g2.z = in.z2;
  g1.delta = pitch_cone_angle1(in.z1, in.z2, in.Sigma);
  g2.delta = in.Sigma - g1.delta;
  r.u = static_cast<double>(in.z2) / in.z1;
  r.R_e = outer_cone_distance(in.z1 * in.m_et, g1.delta);
  check_cones(in, g1.delta, g2.delta, r.R_e);
  r.u_v = virtual_gear_ratio(in.z1, in.z2, g1.delta, g2.delta);
  r.R_m = mean_cone_distance(r.R_e, in.b);
  r.R_i = r.R_e - in.b;
  r.m_mt = mean_transverse_module(in.m_et, r.R_m, r.R_e);
  r.m_mn = mean_normal_module(r.m_mt, in.beta_m);
  r.m_it = in.m_et * r.R_i / r.R_e;
  r.p_et = std::numbers::pi * in.m_et;
  r.alpha_vt = std::atan(std::tan(in.alpha_n) / std::cos(in.beta_m));
  r.beta_vb = std::asin(std::sin(in.beta_m) * std::cos(in.alpha_n));
  depths(in, r);
  g1.hand = in.hand1;
  g2.hand = in.hand1 == SpiralHand::right ? SpiralHand::left : SpiralHand::right;
  for (auto* g : {&g1, &g2}) {
    gear_dimensions(in, r, *g);
    virtual_gear(in, r, *g);
  }
  r.a_v = 0.5 * (g1.d_v + g2.d_v);
  r.eps_va = virtual_contact_ratio(g1.d_v, g2.d_v, g1.h_am, g2.h_am, r.alpha_vt, r.m_mt);
  r.eps_vb = virtual_overlap_ratio(in.b, in.beta_m, r.m_mn);
  r.eps_vg = std::hypot(r.eps_va, r.eps_vb);
  add_warnings(in, r);
  return r;
}

BevelForces bevel_forces(const BevelPairInput& in, const BevelPairResult& table, const BevelLoad& load) {
  if (!(load.T > 0.0 && std::isfinite(load.T))) throw GeometryError("torque", fmt::format("expected a torque > 0, found {:g} N m", load.T));
  if (load.driver != 1 && load.driver != 2) throw GeometryError("driver", fmt::format("expected gear 1 or 2 to drive, found {}", load.driver));
  BevelForces f;
  f.beta_s = spiral_sign(in.hand1, load.rotation1) * in.beta_m;
  const int d = load.driver - 1;
  const double F_t = bevel_tangential_force(load.T, table.gear[d].d_m);
  for (int i = 0; i < 2; ++i) {
    auto& g = f.gear[i];
    g.driving = i == d;
    g.rotation = (i == 0) == (load.rotation1 == Rotation::ccw) ? Rotation::ccw : Rotation::cw;
    g.T = F_t * table.gear[i].d_m / 2000.0;
    g.F_t = F_t;
    g.F_a = bevel_axial_force(F_t, in.alpha_n, f.beta_s, table.gear[i].delta, g.driving);
    g.F_r = bevel_radial_force(F_t, in.alpha_n, f.beta_s, table.gear[i].delta, g.driving);
    g.F_n = F_t / (std::cos(in.alpha_n) * std::cos(in.beta_m));
  }
  return f;
}

}  // namespace gearkit::gear
