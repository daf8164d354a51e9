// Tests of libgear/include/gearkit/gear/bevel.hpp: bevel gear geometry and forces.
// Independent values: the Gleason straight bevel table of KHK's gear technical reference (its
// formulas), the ISO 23509 spiral bevel example as reproduced by BevGear (dsoftcon.be), the
// straight bevel force example of Bhandari, the cone geometry recomputed by 3-D vectors, and the
// tooth force recomputed as a vector normal to the flank and resolved on each gear's cone.
#include <gearkit/gear/bevel.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace gg = gearkit::gear;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

using V = std::array<double, 3>;
V add(V a, V b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
V sub(V a, V b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V mul(double s, V a) { return {s * a[0], s * a[1], s * a[2]}; }
double dot(V a, V b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V cross(V a, V b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double norm(V a) { return std::sqrt(dot(a, a)); }
V unit(V a) { return mul(1.0 / norm(a), a); }
double distance_to_axis(V p, V a) { return norm(sub(p, mul(dot(p, a), a))); }
double angle_between(V a, V b) { return std::acos(std::clamp(dot(unit(a), unit(b)), -1.0, 1.0)); }

// KHK gear technical reference, "Calculations for Gleason straight bevel gears": m = 3,
// alpha = 20 deg, z = 20 / 40, Sigma = 90 deg, b = 22 mm. The printed table was not reachable in
// the stored references; its formulas are (KHK-based bevel programs: the Scheme `bevel-gears`
// of a KHK-citing repository and a KHK-citing calculator): h_a2 = 0.54 m + 0.46 m / (z2 cos d1 /
// (z1 cos d2)), h_a1 = 2 m - h_a2, h_f = 2.188 m - h_a, theta_f = atan(h_f / R), theta_a1 =
// theta_f2, d_a = d + 2 h_a cos d, X = R cos d - h_a sin d, X_b = b cos d_a / cos theta_a,
// d_i = d_a - 2 b sin d_a / cos theta_a. The values below are those formulas evaluated by hand
// (Python, 2026-11-29), rounded as KHK prints them.
gg::BevelPairInput khk_example() {
  gg::BevelPairInput in;
  in.z1 = 20;
  in.z2 = 40;
  in.m_et = 3.0;
  in.b = 22.0;
  return in;
}

TEST(Bevel, KhkGleasonStraightBevelTable) {
  const auto r = gg::compute_bevel_pair(khk_example());
  const auto& p = r.gear[0];
  const auto& g = r.gear[1];
  EXPECT_NEAR(p.delta / kDeg, 26.56505, 5e-6);
  EXPECT_NEAR(g.delta / kDeg, 63.43495, 5e-6);
  EXPECT_NEAR(r.R_e, 67.08204, 5e-6);
  EXPECT_NEAR(p.h_ae, 4.035, 5e-4);
  EXPECT_NEAR(g.h_ae, 1.965, 5e-4);
  EXPECT_NEAR(p.h_fe, 2.529, 5e-4);
  EXPECT_NEAR(g.h_fe, 4.599, 5e-4);
  EXPECT_NEAR(p.theta_f / kDeg, 2.15903, 5e-6);
  EXPECT_NEAR(g.theta_f / kDeg, 3.92194, 5e-6);
  EXPECT_NEAR(p.theta_a / kDeg, 3.92194, 5e-6);
  EXPECT_NEAR(g.theta_a / kDeg, 2.15903, 5e-6);
  EXPECT_NEAR(p.delta_a / kDeg, 30.48699, 5e-6);
  EXPECT_NEAR(g.delta_a / kDeg, 65.59398, 5e-6);
  EXPECT_NEAR(p.delta_f / kDeg, 24.40602, 5e-6);
  EXPECT_NEAR(g.delta_f / kDeg, 59.51301, 5e-6);
  EXPECT_NEAR(p.d_ae, 67.2180, 5e-5);
  EXPECT_NEAR(g.d_ae, 121.7575, 5e-5);
  EXPECT_NEAR(p.t_xo, 58.1955, 5e-5);
  EXPECT_NEAR(g.t_xo, 28.2425, 5e-5);
  EXPECT_NEAR(p.b_x, 19.0029, 5e-5);
  EXPECT_NEAR(g.b_x, 9.0969, 5e-5);
  EXPECT_NEAR(p.d_ai, 44.8425, 5e-5);
  EXPECT_NEAR(g.d_ai, 81.6609, 5e-5);
  // Hand: the clearance is 0.188 m at the outer end, and constant along the face.
  EXPECT_NEAR(r.c, 0.188 * 3.0, 1e-12);
  EXPECT_NEAR(p.h_fi - g.h_ai, 0.188 * 3.0, 1e-12);
}

// ISO 23509 sample (Gleason face-milled spiral bevel, m_et = 5, z = 14/45, b = 36 mm, beta_m =
// 35 deg, Sigma = 90 deg, x_hm1 = 0.25) as printed by BevGear's calculation protocol
// (dsoftcon.be/BevGear/en/GeometryOutputHtml.htm, "Portal Crane, Stage I"): the mean-cone data
// with the ISO 53 proportions h_aP* = 1, h_fP* = 1.25 at the mean normal module.
TEST(Bevel, Iso23509MeanConeOfTheBevGearSample) {
  gg::BevelPairInput in;
  in.z1 = 14;
  in.z2 = 45;
  in.m_et = 5.0;
  in.b = 36.0;
  in.type = gg::BevelType::spiral;
  in.beta_m = 35.0 * kDeg;
  in.system = gg::BevelSystem::iso23509;
  in.x1 = 0.25;
  const auto r = gg::compute_bevel_pair(in);
  EXPECT_NEAR(r.u, 3.2143, 5e-5);
  EXPECT_NEAR(r.gear[0].delta / kDeg, 17.2815, 5e-5);
  EXPECT_NEAR(r.gear[1].delta / kDeg, 72.7185, 5e-5);
  EXPECT_NEAR(r.R_m, 99.819, 5e-4);
  EXPECT_NEAR(r.gear[0].d_m, 59.306, 5e-4);
  // Printed 190.626; exactly z2 m_et R_m / R_e = 190.62516. The print matches 2 R_m sin delta_2
  // with R_m rounded to its printed 99.819 (190.6257), so it carries that rounding.
  EXPECT_NEAR(r.gear[1].d_m, 190.626, 1e-3);
  EXPECT_NEAR(r.m_mt, 4.2361, 5e-5);
  EXPECT_NEAR(r.m_mn, 3.4700, 5e-5);
  EXPECT_NEAR(r.gear[0].h_am, 4.338, 5e-4);
  EXPECT_NEAR(r.gear[1].h_am, 2.603, 5e-4);
  EXPECT_NEAR(r.gear[0].h_fm, 3.470, 5e-4);
  EXPECT_NEAR(r.gear[1].h_fm, 5.205, 5e-4);
  EXPECT_NEAR(r.gear[0].h_fm - r.gear[1].h_am, 0.868, 5e-4);  // clearance c
  EXPECT_NEAR(r.c, 0.868, 5e-4);                              // constant along the face
  EXPECT_NEAR(r.gear[0].t_zm, 95.313, 5e-4);
  EXPECT_NEAR(r.gear[1].t_zm, 29.653, 5e-4);
  EXPECT_NEAR(r.gear[0].x_hm, 0.25, 1e-12);
}

// The pitch cones found by 3-D vectors: the generator g in the plane of the axes that divides
// Sigma so that the distances of one point of g from the two axes are as z1 : z2 (rolling
// without slip), found by bisection; then the outer tip point and the inner tip point of each
// gear built as points, measured against the closed formulas.
struct Cones {
  V a1, a2, g, c1;  // axes, pitch generator, unit normal of g in the axes' plane pointing away from axis 1
};

Cones cones_by_vectors(int z1, int z2, double Sigma) {
  Cones k;
  k.a1 = {1, 0, 0};
  k.a2 = {std::cos(Sigma), std::sin(Sigma), 0};
  double lo = 0.0, hi = Sigma;
  for (int i = 0; i < 200; ++i) {
    const double phi = 0.5 * (lo + hi);
    const V g = {std::cos(phi), std::sin(phi), 0};
    (distance_to_axis(g, k.a1) / distance_to_axis(g, k.a2) < static_cast<double>(z1) / z2 ? lo : hi) = phi;
  }
  const double phi = 0.5 * (lo + hi);
  k.g = {std::cos(phi), std::sin(phi), 0};
  k.c1 = {-std::sin(phi), std::cos(phi), 0};
  return k;
}

void expect_matches_vectors(const gg::BevelPairInput& in) {
  SCOPED_TRACE(testing::Message() << "z " << in.z1 << "/" << in.z2 << ", Sigma " << in.Sigma / kDeg << " deg");
  const auto r = gg::compute_bevel_pair(in);
  const Cones k = cones_by_vectors(in.z1, in.z2, in.Sigma);
  EXPECT_NEAR(r.gear[0].delta, angle_between(k.g, k.a1), 1e-12);
  EXPECT_NEAR(r.gear[1].delta, angle_between(k.g, k.a2), 1e-12);
  // The outer pitch point lies where gear 1's pitch circle has diameter z1 m_et.
  const double R_e = 0.5 * in.z1 * in.m_et / distance_to_axis(k.g, k.a1);
  EXPECT_NEAR(r.R_e, R_e, 1e-9);
  EXPECT_NEAR(r.gear[1].d_e, 2.0 * distance_to_axis(mul(R_e, k.g), k.a2), 1e-9);
  for (int i = 0; i < 2; ++i) {
    const auto& gr = r.gear[i];
    const V a = i == 0 ? k.a1 : k.a2;
    const V c = i == 0 ? k.c1 : mul(-1.0, k.c1);  // towards the tooth tips of gear i
    // Outer tip point: the back cone is normal to the pitch generator g, so the tip lies at
    // R_e g + h_ae c (and the inner one at R_i g + h_ai c).
    const V tip_o = add(mul(R_e, k.g), mul(gr.h_ae, c));
    const V tip_i = add(mul(R_e - in.b, k.g), mul(gr.h_ai, c));
    EXPECT_NEAR(gr.d_ae, 2.0 * distance_to_axis(tip_o, a), 1e-9);
    EXPECT_NEAR(gr.t_xo, dot(tip_o, a), 1e-9);
    EXPECT_NEAR(gr.delta_a, angle_between(sub(tip_o, tip_i), a), 1e-9);
    // The inner end of the tooth is on the inner back cone, normal to g at R_i: along the tip
    // line the face width b appears as b / cos theta_a; d_ai and the axial length b_x follow.
    const V tip_inner_on_cone = add(tip_o, mul(-in.b / std::cos(gr.theta_a), unit(sub(tip_o, tip_i))));
    EXPECT_NEAR(gr.d_ai, 2.0 * distance_to_axis(tip_inner_on_cone, a), 1e-9);
    EXPECT_NEAR(gr.b_x, dot(sub(tip_o, tip_inner_on_cone), a), 1e-9);
    const V root_o = add(mul(R_e, k.g), mul(-gr.h_fe, c));
    EXPECT_NEAR(gr.d_fe, 2.0 * distance_to_axis(root_o, a), 1e-9);
    EXPECT_NEAR(gr.t_zm, dot(mul(r.R_m, k.g), a), 1e-9);
  }
}

TEST(Bevel, ConeGeometryMatchesVectorsAtAnyShaftAngle) {
  for (const double Sigma : {90.0, 60.0, 120.0, 35.0}) {
    for (const auto taper : {gg::DepthTaper::standard, gg::DepthTaper::constant_clearance, gg::DepthTaper::uniform}) {
      gg::BevelPairInput in = khk_example();
      in.z1 = 17;
      in.z2 = 31;
      in.Sigma = Sigma * kDeg;
      in.taper = taper;
      in.b = 15.0;
      expect_matches_vectors(in);
    }
  }
}

// Depth tapers by hand: standard puts both the tip and the root cone through the pitch apex
// (h / R constant along the face), uniform keeps the depth.
TEST(Bevel, DepthTapers) {
  gg::BevelPairInput in = khk_example();
  in.taper = gg::DepthTaper::standard;
  auto r = gg::compute_bevel_pair(in);
  for (const auto& g : r.gear) {
    EXPECT_NEAR(g.h_ai / r.R_i, g.h_ae / r.R_e, 1e-12);
    EXPECT_NEAR(g.h_fm / r.R_m, g.h_fe / r.R_e, 1e-12);
  }
  in.taper = gg::DepthTaper::uniform;
  r = gg::compute_bevel_pair(in);
  for (const auto& g : r.gear) {
    EXPECT_EQ(g.theta_a, 0.0);
    EXPECT_EQ(g.theta_f, 0.0);
    EXPECT_DOUBLE_EQ(g.h_ai, g.h_ae);
    EXPECT_DOUBLE_EQ(g.delta_a, g.delta);
  }
}

// Gleason spiral bevel proportions (working depth 1.700 m, whole depth 1.888 m, wheel addendum
// 0.46 m + 0.39 m / m90^2 with m90 the 90-degree ratio): z = 15/45, m90 = 3, h_ae2 = m (0.46 +
// 0.39/9) = 0.503333 m; h_ae1 = 1.7 m - h_ae2 (zhygear.com, "Appendix of spiral bevel gears
// equations", by hand).
TEST(Bevel, GleasonSpiralProportions) {
  gg::BevelPairInput in;
  in.z1 = 15;
  in.z2 = 45;
  in.m_et = 4.0;
  in.b = 30.0;
  in.type = gg::BevelType::spiral;
  in.beta_m = 35.0 * kDeg;
  const auto r = gg::compute_bevel_pair(in);
  EXPECT_NEAR(r.u_v, 9.0, 1e-12);
  EXPECT_NEAR(r.gear[1].h_ae, 4.0 * (0.46 + 0.39 / 9.0), 1e-12);
  EXPECT_NEAR(r.gear[0].h_ae, 4.0 * 1.7 - 4.0 * (0.46 + 0.39 / 9.0), 1e-12);
  EXPECT_NEAR(r.gear[0].h_ae + r.gear[0].h_fe, 4.0 * 1.888, 1e-12);
  EXPECT_EQ(r.gear[0].hand, gg::SpiralHand::left);
  EXPECT_EQ(r.gear[1].hand, gg::SpiralHand::right);
}

// Zerol bevels (beta_m = 0, curved teeth) take the straight-bevel proportions (docs/bevel.md,
// decision): the same table as KHK's straight pair; a spiral angle is refused for them.
TEST(Bevel, ZerolTakesTheStraightProportions) {
  gg::BevelPairInput in = khk_example();
  in.type = gg::BevelType::zerol;
  const auto r = gg::compute_bevel_pair(in);
  EXPECT_NEAR(r.gear[0].h_ae, 4.035, 5e-4);  // KHK straight bevel table
  EXPECT_NEAR(r.gear[0].d_ae, 67.2180, 5e-5);
  in.beta_m = 5.0 * kDeg;
  EXPECT_THROW(gg::compute_bevel_pair(in), gg::GeometryError);
}

// Virtual gears (ISO 10300-1) by hand for the KHK pair: z_v = z / cos delta = 20/cos 26.565 =
// 22.3607 and 40/cos 63.435 = 89.4427; d_v = d_m / cos delta; the contact ratio from the
// lengths of the path of contact of the two virtual spur gears (tip radius r_v + h_am).
TEST(Bevel, VirtualGearsAndContactRatio) {
  const auto in = khk_example();
  const auto r = gg::compute_bevel_pair(in);
  EXPECT_NEAR(r.gear[0].z_v, 20.0 * std::sqrt(5.0) / 2.0, 1e-9);
  EXPECT_NEAR(r.gear[1].z_v, 40.0 * std::sqrt(5.0), 1e-9);
  EXPECT_NEAR(r.gear[0].z_vn, r.gear[0].z_v, 1e-12);  // straight: normal = transverse
  const double k = r.R_m / r.R_e;
  const double dv1 = 60.0 * k / std::cos(r.gear[0].delta), dv2 = 120.0 * k / std::cos(r.gear[1].delta);
  EXPECT_NEAR(r.gear[0].d_v, dv1, 1e-9);
  const double a = 20.0 * kDeg, rb1 = dv1 / 2 * std::cos(a), rb2 = dv2 / 2 * std::cos(a);
  const double ra1 = dv1 / 2 + r.gear[0].h_am, ra2 = dv2 / 2 + r.gear[1].h_am;
  const double g_alpha = std::sqrt(ra1 * ra1 - rb1 * rb1) + std::sqrt(ra2 * ra2 - rb2 * rb2) - (dv1 + dv2) / 2 * std::sin(a);
  EXPECT_NEAR(r.eps_va, g_alpha / (kPi * 3.0 * k * std::cos(a)), 1e-12);
  EXPECT_GT(r.eps_va, 1.4);
  EXPECT_EQ(r.eps_vb, 0.0);
}

// Undercut on the virtual gear: without the Gleason long addendum a 12-tooth pinion against 36
// (z_v1 = 12.65 < 2/sin^2 20 = 17.1) is undercut; with it (x_he1 = 0.46 (1 - 1/9)) it is not.
TEST(Bevel, UndercutOnTheVirtualGear) {
  gg::BevelPairInput in;
  in.z1 = 12;
  in.z2 = 36;
  in.m_et = 2.0;
  in.b = 12.0;
  in.x1 = 0.0;
  auto r = gg::compute_bevel_pair(in);
  // x_min = 1 - z_v sin^2 alpha / 2 (h_aP* = 1 at the mean point of a standard-proportion pair).
  const double z_v = 12.0 / std::cos(std::atan(1.0 / 3.0));
  EXPECT_NEAR(r.gear[0].x_min, r.h_mw / (2 * r.m_mn) - z_v * std::pow(std::sin(20 * kDeg), 2) / 2, 1e-12);
  EXPECT_LT(r.gear[0].x_hm, r.gear[0].x_min);
  bool warned = false;
  for (const auto& w : r.warnings) warned = warned || w.find("gear 1 is undercut") != std::string::npos;
  EXPECT_TRUE(warned);
  in.x1.reset();
  r = gg::compute_bevel_pair(in);
  EXPECT_GT(r.gear[0].x_hm, r.gear[0].x_min);
}

TEST(Bevel, FaceWidthWarningAndBadInput) {
  gg::BevelPairInput in = khk_example();
  in.b = 25.0;  // > R_e/3 = 22.36, < 10 m = 30
  auto r = gg::compute_bevel_pair(in);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings.front().find("R_e/3"), std::string::npos);
  auto field = [](gg::BevelPairInput bad) {
    try {
      gg::compute_bevel_pair(bad);
    } catch (const gg::GeometryError& e) {
      return e.field();
    }
    return std::string("none");
  };
  in = khk_example();
  in.b = 80.0;
  EXPECT_EQ(field(in), "face_width");
  in = khk_example();
  in.Sigma = 150.0 * kDeg;  // delta_2 > 90 deg: internal bevel
  EXPECT_EQ(field(in), "shaft_angle");
  in = khk_example();
  in.beta_m = 10.0 * kDeg;  // a straight bevel with a spiral angle
  EXPECT_EQ(field(in), "spiral_angle");
  in = khk_example();
  in.x1 = 1.5;
  EXPECT_EQ(field(in), "x1");
  in = khk_example();
  in.z1 = 0;
  EXPECT_EQ(field(in), "z1");
}

// Bhandari, Design of Machine Elements, Example 27-1 (straight bevel, 8 kW at 400 rpm of the
// pinion, i = 2, pinion pitch radius 200 mm, b = 0.2 R): P_t = 1061 N, P_r = 345.41 N,
// P_a = 172.71 N on the pinion. Here m_et = 10, z = 40/80.
TEST(BevelForces, BhandariStraightBevelExample) {
  gg::BevelPairInput in;
  in.z1 = 40;
  in.z2 = 80;
  in.m_et = 10.0;
  in.b = 0.2 * 200.0 * std::sqrt(5.0);
  const auto r = gg::compute_bevel_pair(in);
  EXPECT_NEAR(r.gear[0].d_m, 360.0, 1e-9);
  const double T1 = 8000.0 / (400.0 * 2.0 * kPi / 60.0);
  const auto f = gg::bevel_forces(in, r, {T1, 1, gg::Rotation::cw});
  EXPECT_NEAR(f.gear[0].F_t, 1061.0, 0.5);
  EXPECT_NEAR(f.gear[0].F_r, 345.41, 0.01);
  EXPECT_NEAR(f.gear[0].F_a, 172.71, 0.01);
  // At Sigma = 90 deg the pinion's axial force is the wheel's radial force and vice versa.
  EXPECT_NEAR(f.gear[1].F_r, f.gear[0].F_a, 1e-9);
  EXPECT_NEAR(f.gear[1].F_a, f.gear[0].F_r, 1e-9);
  // Power balance (no friction): T1 omega1 = T2 omega2, omega2 = omega1 z1/z2.
  EXPECT_NEAR(f.gear[1].T * 40.0 / 80.0, T1, 1e-9);
}

// The forces as a vector: the tooth normal at the mean point built from the hand's definition
// (AGMA 1012: outer half inclined clockwise seen from the apex side for a right hand), the
// pressure angle and the rolling condition, scaled to the torque, then resolved on each gear's
// axis and radius. Every hand, sense, driver and three shaft angles; the power balance with the
// speeds of the rolling cones.
struct VectorForces {
  double F_a[2], F_r[2], T[2], speed_ratio;
};

VectorForces forces_by_vectors(const gg::BevelPairInput& in, const gg::BevelPairResult& r, gg::SpiralHand hand1,
                               gg::Rotation rot1, int driver, double T) {
  const Cones k = cones_by_vectors(in.z1, in.z2, in.Sigma);
  const V P = mul(r.R_m, k.g);
  const V e_cw1 = unit(cross(k.a1, P));  // clockwise seen from gear 1's apex side = +rotation about a1
  const double b = in.beta_m;
  const V s = add(mul(std::cos(b), k.g), mul((hand1 == gg::SpiralHand::right ? 1.0 : -1.0) * std::sin(b), e_cw1));
  const V omega1 = mul(rot1 == gg::Rotation::ccw ? 1.0 : -1.0, k.a1);  // ccw from the back = +a1
  const V v = cross(omega1, P);
  const V a2xP = cross(k.a2, P);
  const V omega2 = mul(dot(v, a2xP) / dot(a2xP, a2xP), k.a2);
  // The flank normal: perpendicular to the tooth trace s, at alpha_n from the pitch plane;
  // the in-plane part q is perpendicular to s in the pitch plane (spanned by g and e_cw1).
  const V pitch_normal = k.c1;  // from gear 1 towards gear 2
  V q = unit(cross(pitch_normal, s));
  // The force on the driven gear does positive work; on gear 1 it pushes away from gear 2.
  const V v_unit = unit(v);
  const double sign_q = (dot(q, v_unit) > 0) == (driver == 2) ? 1.0 : -1.0;
  q = mul(sign_q, q);
  const V dir1 = add(mul(std::cos(in.alpha_n), q), mul(-std::sin(in.alpha_n), pitch_normal));
  // Scale: the driver's torque about its axis.
  const V a_drv = driver == 1 ? k.a1 : k.a2;
  const double moment_unit = std::fabs(dot(cross(P, driver == 1 ? dir1 : mul(-1.0, dir1)), a_drv)) / 1000.0;
  const V F1 = mul(T / moment_unit, dir1), F2 = mul(-1.0, F1);
  VectorForces out;
  const V r1 = unit(sub(P, mul(dot(P, k.a1), k.a1))), r2 = unit(sub(P, mul(dot(P, k.a2), k.a2)));
  out.F_a[0] = dot(F1, k.a1);
  out.F_a[1] = dot(F2, k.a2);
  out.F_r[0] = -dot(F1, r1);
  out.F_r[1] = -dot(F2, r2);
  out.T[0] = std::fabs(dot(cross(P, F1), k.a1)) / 1000.0;
  out.T[1] = std::fabs(dot(cross(P, F2), k.a2)) / 1000.0;
  out.speed_ratio = norm(omega2) / norm(omega1);
  return out;
}

TEST(BevelForces, MatchTheToothNormalResolvedOnTheCones) {
  for (const double Sigma : {90.0, 70.0, 115.0}) {
    for (const auto type : {gg::BevelType::straight, gg::BevelType::spiral}) {
      gg::BevelPairInput in;
      in.z1 = 13;
      in.z2 = 29;
      in.m_et = 4.0;
      in.b = 14.0;
      in.Sigma = Sigma * kDeg;
      in.type = type;
      in.beta_m = type == gg::BevelType::spiral ? 35.0 * kDeg : 0.0;
      for (const auto hand : {gg::SpiralHand::right, gg::SpiralHand::left})
        for (const auto rot : {gg::Rotation::ccw, gg::Rotation::cw})
          for (const int driver : {1, 2}) {
            SCOPED_TRACE(testing::Message() << "Sigma " << Sigma << ", " << gg::to_string(type) << ", hand1 " << gg::to_string(hand)
                                            << ", rotation1 " << gg::to_string(rot) << ", driver " << driver);
            in.hand1 = hand;
            const auto r = gg::compute_bevel_pair(in);
            const double T = 50.0;
            const auto f = gg::bevel_forces(in, r, {T, driver, rot});
            const auto v = forces_by_vectors(in, r, hand, rot, driver, T);
            for (int i = 0; i < 2; ++i) {
              EXPECT_NEAR(f.gear[i].F_a, v.F_a[i], 1e-9 * f.gear[i].F_t) << "gear " << i + 1;
              EXPECT_NEAR(f.gear[i].F_r, v.F_r[i], 1e-9 * f.gear[i].F_t) << "gear " << i + 1;
              EXPECT_NEAR(f.gear[i].T, v.T[i], 1e-9 * T) << "gear " << i + 1;
            }
            // Power balance: T1 omega1 = T2 omega2 with the speeds of the rolling pitch cones.
            EXPECT_NEAR(f.gear[0].T, f.gear[1].T * v.speed_ratio, 1e-9 * T);
            EXPECT_NEAR(v.speed_ratio, 13.0 / 29.0, 1e-12);
          }
    }
  }
}

// Hand derivation of the classic rule (Gleason; Budynas and Nisbett, Shigley's MED, ch. 13, spiral
// bevel forces W_a = W_t/cos psi (tan phi_n sin gamma -+ sin psi cos gamma), W_r = W_t/cos psi
// (tan phi_n cos gamma +- sin psi sin gamma), upper signs for a driving pinion with a right-hand
// spiral turning clockwise seen from its large end, or left-hand counter-clockwise): so a
// left-hand driving pinion turning clockwise, or a right-hand one counter-clockwise, is pushed
// away from the apex, out of mesh; reversing the sense reverses the spiral term, and with
// beta = 35 deg and a small pinion cone the thrust then points towards the apex.
TEST(BevelForces, SpiralThrustChangesDirectionWithTheSense) {
  gg::BevelPairInput in;
  in.z1 = 13;
  in.z2 = 39;
  in.m_et = 4.0;
  in.b = 18.0;
  in.type = gg::BevelType::spiral;
  in.beta_m = 35.0 * kDeg;
  in.hand1 = gg::SpiralHand::left;
  const auto r = gg::compute_bevel_pair(in);
  const auto out_of_mesh = gg::bevel_forces(in, r, {100.0, 1, gg::Rotation::cw});
  const auto into_mesh = gg::bevel_forces(in, r, {100.0, 1, gg::Rotation::ccw});
  EXPECT_GT(out_of_mesh.gear[0].F_a, 0.0);
  EXPECT_LT(into_mesh.gear[0].F_a, 0.0);
  // By hand: F_a = F_t / cos b (tan a sin d -+ sin b cos d), d = atan(1/3).
  const double F_t = 2000.0 * 100.0 / r.gear[0].d_m, d = std::atan(1.0 / 3.0), b = 35.0 * kDeg, a = 20.0 * kDeg;
  EXPECT_NEAR(out_of_mesh.gear[0].F_a, F_t / std::cos(b) * (std::tan(a) * std::sin(d) + std::sin(b) * std::cos(d)), 1e-9);
  EXPECT_NEAR(into_mesh.gear[0].F_a, F_t / std::cos(b) * (std::tan(a) * std::sin(d) - std::sin(b) * std::cos(d)), 1e-9);
  EXPECT_NEAR(into_mesh.gear[0].F_r, F_t / std::cos(b) * (std::tan(a) * std::cos(d) + std::sin(b) * std::sin(d)), 1e-9);
  EXPECT_NEAR(out_of_mesh.gear[0].F_r, F_t / std::cos(b) * (std::tan(a) * std::cos(d) - std::sin(b) * std::sin(d)), 1e-9);
  EXPECT_EQ(out_of_mesh.gear[1].rotation, gg::Rotation::ccw);
}

}  // namespace
