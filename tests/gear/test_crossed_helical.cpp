// Tests for gearkit/gear/crossed_helical.hpp: crossed helical (screw) gears.
#include <gearkit/gear/crossed_helical.hpp>
#include <gearkit/gear/gear_pair.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

namespace gg = gearkit::gear;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
using Vec = std::array<double, 3>;

Vec cross(const Vec& a, const Vec& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec add(const Vec& a, const Vec& b, double k = 1.0) { return {a[0] + k * b[0], a[1] + k * b[1], a[2] + k * b[2]}; }
Vec scale(const Vec& a, double k) { return {k * a[0], k * a[1], k * a[2]}; }
double norm(const Vec& a) { return std::sqrt(dot(a, a)); }

// A screw gear pair of the proportions of KHK's screw gear table: m_n = 3, alpha_n = 20 deg,
// z1 = 15, z2 = 24, beta1 = 20 deg and beta2 = 30 deg, both right hand: Sigma = 50 deg. Expected
// values are hand calculations (KHK's printed table was not reachable).
gg::CrossedHelicalInput khk_pair() {
  gg::CrossedHelicalInput in;
  in.z1 = 15;
  in.z2 = 24;
  in.m_n = 3.0;
  in.beta1 = 20.0 * kDeg;
  in.beta2 = 30.0 * kDeg;
  in.mu = 0.05;
  in.n1 = 1000.0;
  return in;
}

// The tooth line at the pitch point of a right-hand (hand = 1) or left-hand helix of helix angle
// |beta| about the unit axis e, the pitch point lying at the unit radial direction rr from the axis:
// cos|beta| e + hand sin|beta| (e x rr) (a right-hand helix advances along e turning about e).
Vec tooth_line(const Vec& e, const Vec& rr, double beta) {
  const double hand = beta > 0.0 ? 1.0 : -1.0;
  return add(scale(e, std::cos(beta)), cross(e, rr), hand * std::sin(std::fabs(beta)));
}

}  // namespace

TEST(CrossedHelical, GeometryByHand) {
  const gg::CrossedHelicalResult c = gg::compute_crossed_helical(khk_pair());
  // d_i = z_i m_n / cos beta_i: 45 / cos 20 = 47.888000, 72 / cos 30 = 83.138439; a = 65.513219.
  EXPECT_NEAR(c.gear[0].d, 47.8880, 5e-5);
  EXPECT_NEAR(c.gear[1].d, 83.1384, 5e-5);
  EXPECT_NEAR(c.a, 65.5132, 5e-5);
  EXPECT_NEAR(c.gear[0].d_a, 47.8880 + 6.0, 5e-5);
  EXPECT_NEAR(c.Sigma, 50.0 * kDeg, 1e-15);  // same hands add
  EXPECT_NEAR(c.u, 1.6, 1e-15);
  gg::CrossedHelicalInput opposite = khk_pair();
  opposite.beta2 = -10.0 * kDeg;  // left hand: Sigma = 20 - 10
  EXPECT_NEAR(gg::compute_crossed_helical(opposite).Sigma, 10.0 * kDeg, 1e-15);
}

// The frame of the header, checked by vectors: the two gears' tooth lines coincide at the pitch
// point, and the relative velocity of the pitch points lies along them with the size of the
// closed formula v_g = v1 sin Sigma / cos beta2.
TEST(CrossedHelical, FrameAndSlidingVelocityByVectors) {
  for (const auto& [b1, b2] : {std::pair{20.0, 30.0}, std::pair{-20.0, -30.0}, std::pair{40.0, -10.0}, std::pair{45.0, 45.0}})
    for (double n1 : {1000.0, -600.0}) {
      gg::CrossedHelicalInput in = khk_pair();
      in.beta1 = b1 * kDeg;
      in.beta2 = b2 * kDeg;
      in.n1 = n1;
      const gg::CrossedHelicalResult c = gg::compute_crossed_helical(in);
      const double S = c.Sigma;
      const Vec x{1, 0, 0}, z{0, 0, 1}, g2{std::cos(S), -std::sin(S), 0.0};
      const double r1 = c.gear[0].d / 2000.0, r2 = c.gear[1].d / 2000.0;  // m
      const Vec t1 = tooth_line(x, z, in.beta1), t2 = tooth_line(g2, scale(z, -1.0), in.beta2);
      EXPECT_NEAR(norm(cross(t1, t2)), 0.0, 1e-12) << b1 << " " << b2;  // same line
      const double w1 = n1 * std::numbers::pi / 30.0, w2 = c.n2 * std::numbers::pi / 30.0;
      const Vec v1 = cross(scale(x, w1), scale(z, r1)), v2 = cross(scale(g2, w2), scale(z, -r2));
      const Vec slide = add(v1, v2, -1.0);
      EXPECT_NEAR(norm(cross(slide, t1)), 0.0, 1e-9 * norm(v1)) << b1 << " " << b2;  // slides along the teeth
      EXPECT_NEAR(norm(slide), c.v_g, 1e-9 * c.v_g);
    }
}

TEST(CrossedHelical, EfficiencyByHand) {
  // Sigma = 90, beta1 = beta2 = 45 deg, mu = 0.05: rho' = atan(0.05 / cos 20) = 3.045773 deg,
  // eta = cos(45 + rho') / cos(45 - rho') = 0.898959 (Niemann/Winter), in both directions.
  gg::CrossedHelicalInput in = khk_pair();
  in.beta1 = in.beta2 = 45.0 * kDeg;
  const gg::CrossedHelicalResult c = gg::compute_crossed_helical(in);
  EXPECT_NEAR(c.eta_12, 0.8989585, 1e-7);
  EXPECT_NEAR(c.eta_21, 0.8989585, 1e-7);
}

// Virtual power and the force's make-up: for every driver, hand and sense, input power = output
// power + mu F_n v_g; the force on gear 2 has the friction mu F_n along the tooth line (the sign:
// it drags gear 2 along gear 1's sliding), its normal part F_n, and pushes gear 2 away from gear 1.
TEST(CrossedHelical, PowerBalanceAndForceMakeUp) {
  for (const auto& [b1, b2] : {std::pair{20.0, 30.0}, std::pair{-20.0, -30.0}, std::pair{40.0, -10.0}})
    for (double n1 : {1000.0, -600.0})
      for (int driver : {1, 2}) {
        gg::CrossedHelicalInput in = khk_pair();
        in.beta1 = b1 * kDeg;
        in.beta2 = b2 * kDeg;
        in.n1 = n1;
        const gg::CrossedHelicalResult c = gg::compute_crossed_helical(in);
        const gg::CrossedForces f = gg::crossed_forces(c, in.alpha_n, 30.0, driver, driver);
        const double w1 = std::fabs(n1) * std::numbers::pi / 30.0, w2 = w1 / c.u;
        const double P1 = f.T1 * w1, P2 = f.T2 * w2;
        EXPECT_NEAR(driver == 1 ? P1 - P2 : P2 - P1, 0.05 * f.F_n * c.v_g, 1e-9 * P1) << b1 << " " << b2 << " " << n1 << " " << driver;
        EXPECT_NEAR(norm(f.on_2), f.F_n * std::sqrt(1.0 + 0.05 * 0.05), 1e-9 * f.F_n);
        const Vec x{1, 0, 0}, z{0, 0, 1};
        const Vec t1 = tooth_line(x, z, in.beta1);
        const Vec g2{std::cos(c.Sigma), -std::sin(c.Sigma), 0.0};
        // Pitch point velocities (pitch point at +z d1/2 from gear 1's axis, -z d2/2 from gear 2's).
        const Vec v1 = cross(scale(x, n1), scale(z, c.gear[0].d / 2.0));
        const Vec v2 = cross(scale(g2, c.n2), scale(z, -c.gear[1].d / 2.0));
        const Vec slide = add(v1, v2, -1.0);  // gear 1 relative to gear 2: its friction drags gear 2 along
        const double friction = dot(f.on_2, t1) / norm(t1) * (dot(slide, t1) > 0 ? 1.0 : -1.0);
        EXPECT_NEAR(friction, 0.05 * f.F_n, 1e-9 * f.F_n) << b1 << " " << b2 << " " << n1 << " " << driver;
        EXPECT_GT(f.on_2[2], 0.0);
        // The driven gear is pushed along its motion.
        EXPECT_GT(driver == 1 ? dot(f.on_2, v2) : dot(f.on_1, v1), 0.0);
        // Axial components along each axis, as stored.
        EXPECT_NEAR(f.F_a1, dot(f.on_1, x), 1e-9 * f.F_n);
        EXPECT_NEAR(f.F_a2, dot(f.on_2, g2), 1e-9 * f.F_n);
      }
}

TEST(CrossedHelical, BadInputNamesTheField) {
  auto field_of = [](const gg::CrossedHelicalInput& in) {
    try {
      gg::compute_crossed_helical(in);
    } catch (const gg::GeometryError& e) {
      return e.field();
    }
    return std::string("none");
  };
  gg::CrossedHelicalInput in = khk_pair();
  in.beta2 = -20.0 * kDeg;  // parallel shafts
  EXPECT_EQ(field_of(in), "beta2");
  in = khk_pair();
  in.beta1 = 89.0 * kDeg;
  EXPECT_EQ(field_of(in), "beta1");
  in = khk_pair();
  in.m_n = -1.0;
  EXPECT_EQ(field_of(in), "m_n");
}
