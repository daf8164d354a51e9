// Tests for gearkit/gear/iso6336_root.hpp (ISO 6336-3:2019 method B): the 30-degree tangent
// construction checked against the fillet libgear generates by simulating the rack cutter
// (tooth_form.hpp), the rack limit, and the root factors.
#include <gearkit/gear/iso6336_root.hpp>

#include <gearkit/gear/cylindrical_gear.hpp>
#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/gear/involute.hpp>
#include <gearkit/gear/tooth_form.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace gg = gearkit::gear;
namespace iso = gearkit::gear::iso6336;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

iso::ToothRootInput spur(int z, double x, double eps_alpha) {
  iso::ToothRootInput in;
  in.z = z;
  in.m_n = 8.0;
  in.alpha_n = 20.0 * kDeg;
  in.x_E = x;
  in.h_fP = 1.4;
  in.rho_fP = 0.39;
  in.d = z * 8.0;
  in.d_a = in.d + 2.0 * 8.0 * (1.0 + x);
  in.eps_alpha = eps_alpha;
  return in;
}

struct Numeric {
  double s_Fn, rho_F, projection;  // chord, fillet radius and the chord's distance from the centre
};

// The 30-degree tangent point found on the drawn fillet of tooth space 0: the tooth beside the
// +x flank has its centre line at eta = pi/z from the +y axis.
Numeric thirty_degree_point(const std::vector<gg::Point2>& flank, int z) {
  const double eta_t = kPi / z;
  auto angle_to_centre_line = [&](std::size_t i) {
    const double dx = flank[i + 1].x - flank[i].x, dy = flank[i + 1].y - flank[i].y;
    const double ux = std::sin(eta_t), uy = std::cos(eta_t);  // centre line direction
    return std::acos(std::fabs(dx * ux + dy * uy) / std::hypot(dx, dy));
  };
  for (std::size_t i = 1; i + 2 < flank.size(); ++i) {
    const double a0 = angle_to_centre_line(i - 1), a1 = angle_to_centre_line(i);
    if (a0 >= kPi / 6.0 && a1 < kPi / 6.0) {
      const gg::Point2 p = flank[i];
      const double r = std::hypot(p.x, p.y), eta = std::atan2(p.x, p.y);
      // Radius of the circle through three neighbours.
      const gg::Point2 a = flank[i - 1], c = flank[i + 1];
      const double ab = std::hypot(p.x - a.x, p.y - a.y), bc = std::hypot(c.x - p.x, c.y - p.y), ca = std::hypot(a.x - c.x, a.y - c.y);
      const double area2 = std::fabs((p.x - a.x) * (c.y - a.y) - (p.y - a.y) * (c.x - a.x));
      return {2.0 * r * std::sin(eta_t - eta), ab * bc * ca / (2.0 * area2), r * std::cos(eta_t - eta)};
    }
  }
  return {NAN, NAN, NAN};
}

}  // namespace

TEST(ToothRoot, ThirtyDegreeTangentMatchesTheGeneratedFillet) {
  // Spur gears cut by the ISO 53 D rack (h_fP = 1.4, rho_fP = 0.39), with and without shift.
  for (const auto& [z, x] : {std::pair{17, 0.145}, std::pair{30, 0.0}, std::pair{60, -0.2}, std::pair{24, 0.5}}) {
    gg::GearPairInput pair;
    pair.z1 = z;
    pair.z2 = 3 * z;
    pair.module = 8.0;
    pair.h_fP = 1.4;
    pair.rho_fP = 0.39;
    pair.x1 = x;
    const auto result = gg::compute_gear_pair(pair);
    gg::ToothFormSpec spec = gg::tooth_form_spec(pair, result, 0);
    spec.tolerance = 1e-7;
    const Numeric n = thirty_degree_point(gg::space_flank(spec), z);
    iso::ToothRootInput in = spur(z, x, result.pair.eps_alpha);
    in.d_a = result.gear[0].d_a;
    const iso::ToothRoot root = iso::external_tooth_root(in);
    EXPECT_NEAR(n.s_Fn, root.s_Fn, 2e-4 * root.s_Fn) << "z = " << z << ", x = " << x;
    EXPECT_NEAR(n.rho_F, root.rho_F, 2e-3 * root.rho_F) << "z = " << z << ", x = " << x;
    // h_Fe: the load line of the outer single-contact point crosses the centre line at
    // r_L = r_en (cos gamma_e - sin gamma_e tan alpha_Fen); gamma_e is the half tooth angle there,
    // from libgear's involute thickness (tooth_thickness_at), independent of ISO 6336-3 Eq. 29.
    const double r_en = 0.5 * root.d_en;
    const double d = result.gear[0].d, d_b = result.gear[0].d_b;
    const double gamma_e = 0.5 * gg::tooth_thickness_at(result.gear[0].s_t, d, d_b, 20.0 * kDeg, root.d_en) / r_en;
    const double alpha_en = std::acos(d_b / root.d_en);
    EXPECT_NEAR(root.alpha_Fen, alpha_en - gamma_e, 1e-9);
    const double r_L = r_en * (std::cos(gamma_e) - std::sin(gamma_e) * std::tan(alpha_en - gamma_e));
    EXPECT_NEAR(r_L - n.projection, root.h_Fe, 2e-4 * root.h_Fe) << "z = " << z << ", x = " << x;
  }
}

TEST(ToothRoot, FormFactorTendsToTheRack) {
  // As z grows the external tooth and the internal tooth both become the rack tooth.
  const iso::ToothRoot ext = iso::external_tooth_root(spur(200000, 0.0, 1.8));
  iso::ToothRootInput ring = spur(200000, 0.0, 1.8);
  ring.d_a = ring.d - 2.0 * 8.0;
  const iso::ToothRoot in = iso::internal_tooth_root(ring);
  EXPECT_NEAR(ext.s_Fn, in.s_Fn, 1e-3 * in.s_Fn);
  EXPECT_NEAR(ext.rho_F, in.rho_F, 1e-3 * in.rho_F);
  EXPECT_NEAR(ext.h_Fe, in.h_Fe, 2e-3 * in.h_Fe);
  EXPECT_NEAR(ext.Y_F, in.Y_F, 5e-3 * in.Y_F);
  // And Y_F falls towards that value as z grows (x = 0).
  double previous = 1e9;
  for (int z : {14, 20, 40, 100, 1000, 100000}) {
    const double Y_F = iso::external_tooth_root(spur(z, 0.0, 1.6)).Y_F;
    EXPECT_LT(Y_F, previous) << z;
    previous = Y_F;
  }
  EXPECT_NEAR(iso::external_tooth_root(spur(100000, 0.0, 1.6)).Y_F, iso::external_tooth_root(spur(200000, 0.0, 1.6)).Y_F, 1e-4);
}

TEST(ToothRoot, StressCorrectionAndSimpleFactors) {
  // Eq. 42: L = 2, q_s = 2: Y_S = (1.2 + 0.26) 2^(1/(1.21 + 1.15)).
  EXPECT_NEAR(iso::stress_correction_factor(10.0, 5.0, 2.5), 1.46 * std::pow(2.0, 1.0 / 2.36), 1e-12);
  EXPECT_NEAR(iso::form_factor(1.0, 0.0, 2.0, 0.0), 1.5, 1e-12);
  EXPECT_NEAR(iso::helix_angle_factor_F(1.2, 15.8 * kDeg), 1.0 - 15.8 / 120.0, 1e-12);
  EXPECT_NEAR(iso::helix_angle_factor_F(0.5, 40.0 * kDeg), 1.0 - 0.5 * 30.0 / 120.0, 1e-12);
  EXPECT_DOUBLE_EQ(iso::rim_thickness_factor(0.0, 18.0, 8.0, false), 1.0);
  EXPECT_DOUBLE_EQ(iso::rim_thickness_factor(30.0, 18.0, 8.0, false), 1.0);
  EXPECT_NEAR(iso::rim_thickness_factor(18.0, 18.0, 8.0, false), 1.6 * std::log(2.242), 1e-12);
  EXPECT_NEAR(iso::rim_thickness_factor(20.0, 18.0, 8.0, true), 1.15 * std::log(8.324 * 8.0 / 20.0), 1e-12);
  EXPECT_DOUBLE_EQ(iso::deep_tooth_factor(2.3, 6), 1.0);
  EXPECT_NEAR(iso::deep_tooth_factor(2.3, 4), -0.666 * 2.3 + 2.366, 1e-12);
  EXPECT_DOUBLE_EQ(iso::deep_tooth_factor(2.7, 3), 0.7);
  EXPECT_DOUBLE_EQ(iso::deep_tooth_factor(2.7, 0), 0.7);  // ISO 1328-1:1995 grade 0 is the finest grade
  EXPECT_NEAR(iso::relative_notch_sensitivity_factor(0.003, 2.5), 1.0, 1e-12);  // the test gear's notch
  EXPECT_NEAR(iso::relative_surface_factor(gg::MaterialClass::case_carburized, 0.5), 1.12, 1e-12);
  EXPECT_NEAR(iso::size_factor_F(gg::MaterialClass::case_carburized, 8.0), 0.97, 1e-12);
  EXPECT_DOUBLE_EQ(iso::size_factor_F(gg::MaterialClass::case_carburized, 4.0), 1.0);
  EXPECT_NEAR(iso::root_stress_limit(500.0, 1.0, 1.0, 1.0, 1.0), 1000.0, 1e-12);  // sigma_FE = 2 sigma_Flim
  EXPECT_NEAR(iso::nominal_root_stress(1000.0, 10.0, 2.0, 2.0, 2.0, 1.0, 1.0, 1.0), 200.0, 1e-12);
}

TEST(ToothRoot, ImpossibleConstructionIsADomainError) {
  iso::ToothRootInput in = spur(17, 0.0, 5.0);  // load point below the base circle
  EXPECT_THROW(iso::external_tooth_root(in), std::domain_error);
}

// ISO 6336-3:2019 clause 10: Y_DT < 1 is for gears of proven high precision (grade <= 4). Without
// a grade the precision is unknown and the factor stays 1 (it used to take "no grade" as grade 0).
TEST(ToothRoot, DeepToothFactorNeedsAKnownGrade) {
  EXPECT_DOUBLE_EQ(iso::deep_tooth_factor(2.7, std::nullopt), 1.0);
  EXPECT_DOUBLE_EQ(iso::deep_tooth_factor(2.3, std::nullopt), 1.0);
  EXPECT_DOUBLE_EQ(iso::deep_tooth_factor(2.7, 5), 1.0);
  EXPECT_NEAR(iso::deep_tooth_factor(2.3, 4), 0.8342, 1e-4);
}
