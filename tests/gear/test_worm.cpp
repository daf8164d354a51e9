// Tests for gearkit/gear/worm.hpp: cylindrical worm and wheel.
#include <gearkit/gear/crossed_helical.hpp>
#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/gear/worm.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace gg = gearkit::gear;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kLbf = 4.4482216152605;  // N per lbf

// The worm pair of the "Worm Gear Formula-Master" worksheet (Niemann/DIN column; scribd document
// 418425143, found with the search tool) and of KHK's axial-module worm table: m_x = 3, z1 = 2,
// z2 = 30, d_m1 = 44, x2 = 0, 20 deg.
gg::WormInput sheet_pair() {
  gg::WormInput in;
  in.z1 = 2;
  in.z2 = 30;
  in.m_x = 3.0;
  in.d_m1 = 44.0;
  in.flank = gg::WormFlank::ZA;
  in.mu = 0.05;
  return in;
}

// Shigley/Budynas (Mechanical Engineering Design, ch. 13, worm force example): a 2-thread
// right-hand worm of pitch diameter 2 in at 1200 rev/min, a 30-tooth wheel of transverse
// diametral pitch 6 teeth/in, phi_n = 14.5 deg, transmitting 1 hp; here with f = 0.03.
gg::WormInput shigley_pair() {
  gg::WormInput in;
  in.z1 = 2;
  in.z2 = 30;
  in.m_x = 25.4 / 6.0;
  in.d_m1 = 2.0 * 25.4;
  in.flank = gg::WormFlank::ZN;
  in.alpha_0 = 14.5 * kDeg;
  in.mu = 0.03;
  in.n1 = 1200.0;
  return in;
}

double norm(const std::array<double, 3>& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

}  // namespace

TEST(Worm, WorksheetGeometry) {
  const gg::WormResult w = gg::compute_worm(sheet_pair());
  // Worksheet values: lead angle 7.7651660184 deg, lead 18.8495559215, normal module
  // 2.97249050413290, d_a1 = 50, d_f1 = 36.5, d2 = 90, a = 67, throat (tip) diameter 96,
  // d_f2 = 82.5, outside diameter 99, throat radius 19, wheel width 27.9.
  EXPECT_NEAR(w.gamma / kDeg, 7.7651660184, 1e-9);
  EXPECT_NEAR(w.p_z, 18.8495559215, 1e-9);
  EXPECT_NEAR(w.m_n, 2.97249050413290, 1e-12);
  EXPECT_NEAR(w.q, 44.0 / 3.0, 1e-12);
  EXPECT_NEAR(w.d_a1, 50.0, 1e-12);
  EXPECT_NEAR(w.d_f1, 36.5, 1e-12);
  EXPECT_NEAR(w.d2, 90.0, 1e-12);
  EXPECT_NEAR(w.a, 67.0, 1e-12);
  EXPECT_NEAR(w.d_a2, 96.0, 1e-12);
  EXPECT_NEAR(w.d_f2, 82.5, 1e-12);
  EXPECT_NEAR(w.d_e2, 99.0, 1e-12);
  EXPECT_NEAR(w.r_k, 19.0, 1e-12);
  EXPECT_NEAR(w.b2, 27.9, 1e-12);
  EXPECT_NEAR(w.u, 15.0, 1e-15);
  EXPECT_NEAR(w.gamma_w, w.gamma, 1e-15);  // no profile shift: the pitch cylinder is the reference one
}

TEST(Worm, ProfileShiftFromTheCentreDistance) {
  gg::WormInput in = sheet_pair();
  in.centre_distance = 68.5;  // 1.5 mm more than 67: x2 = 1.5 / 3 = 0.5 (DIN 3975 a = (d_m1 + d2)/2 + x2 m)
  const gg::WormResult w = gg::compute_worm(in);
  EXPECT_NEAR(w.x2, 0.5, 1e-12);
  EXPECT_NEAR(w.d_a2, 90.0 + 2.0 * 3.0 * 1.5, 1e-12);  // d2 + 2 m (1 + x2)
  EXPECT_NEAR(w.d_w1, 47.0, 1e-12);                     // 2 a - d2
  EXPECT_NEAR(std::tan(w.gamma_w), 6.0 / 47.0, 1e-12);
  EXPECT_NEAR(w.r_k, 19.0, 1e-12);  // a - d_a2 / 2 = 68.5 - 49.5: d_m1/2 - m whatever the shift
}

TEST(Worm, FlankFormsNameTheSectionOfThePressureAngle) {
  gg::WormInput in = sheet_pair();
  const gg::WormResult za = gg::compute_worm(in);
  EXPECT_NEAR(za.alpha_x, 20.0 * kDeg, 1e-15);
  // tan alpha_n = tan alpha_x cos gamma (DIN 3975), by hand: tan 20 cos 7.7651660 = 0.360633...
  EXPECT_NEAR(std::tan(za.alpha_n), std::tan(20.0 * kDeg) * std::cos(7.7651660184 * kDeg), 1e-12);
  in.flank = gg::WormFlank::ZI;
  const gg::WormResult zi = gg::compute_worm(in);
  EXPECT_NEAR(zi.alpha_n, 20.0 * kDeg, 1e-15);
  // The involute helicoid's base cylinder: its lead is the worm's, pi d_b1 tan gamma_b = p_z, and
  // cos gamma_b = cos gamma cos alpha_n (base helix of an involute helicoid, ISO/TR 10828).
  EXPECT_NEAR(std::numbers::pi * zi.d_b1 * std::tan(zi.gamma_b), zi.p_z, 1e-9);
  EXPECT_NEAR(std::cos(zi.gamma_b), std::cos(zi.gamma) * std::cos(20.0 * kDeg), 1e-12);
  EXPECT_TRUE(std::isnan(za.d_b1));
}

TEST(Worm, ShigleyForceExample) {
  const gg::WormResult w = gg::compute_worm(shigley_pair());
  // Lead angle: tan lambda = L / (pi d) = (2 pi / 6) / (2 pi) = 1/6: 9.4623222 deg.
  EXPECT_NEAR(w.gamma / kDeg, 9.462322208, 1e-8);
  // Sliding velocity V_s = pi d n / cos lambda = 636.985 ft/min = 3.23589 m/s.
  EXPECT_NEAR(w.v_g / 0.00508, 636.9854026, 1e-6);
  // 1 hp at 1200 rev/min on the worm: W_t = 33000 / (pi 2 1200 / 12) = 52.5211 lbf; Shigley's
  // eq. 13-43 in its own form, by hand: W = W_t / (cos phi_n sin lambda + f cos lambda)
  // = 278.2513 lbf, W_y = W sin phi_n = 69.6686 lbf, W_z = W (cos phi_n cos lambda - f sin lambda)
  // = 264.3507 lbf; efficiency eq. 13-46 (cos phi_n - f tan lambda)/(cos phi_n + f cot lambda) = 0.838871.
  const double T1 = 745.69987158 / (1200.0 * 2.0 * std::numbers::pi / 60.0);
  const gg::WormForces f = gg::worm_forces(w, T1, true, true);
  EXPECT_NEAR(f.F_t1 / kLbf, 52.52113122, 1e-6);
  EXPECT_NEAR(f.F_n / kLbf, 278.2512961, 1e-6);
  EXPECT_NEAR(f.F_r / kLbf, 69.66856064, 1e-6);
  EXPECT_NEAR(f.F_t2 / kLbf, 264.3506906, 1e-6);
  EXPECT_NEAR(f.F_a1, f.F_t2, 1e-12);
  EXPECT_NEAR(f.F_a2, f.F_t1, 1e-12);
  EXPECT_NEAR(w.eta_12, 0.8388708965, 1e-9);
}

TEST(Worm, AgmaFrictionCoefficient) {
  // ANSI/AGMA 6034-B92 by hand: V_s = 636.985 ft/min: 0.103 exp(-0.110 * 636.985^0.45) + 0.012 = 0.0257973;
  // V_s = 5 ft/min: 0.124 exp(-0.074 * 5^0.645) = 0.100617; at rest 0.150.
  EXPECT_NEAR(gg::worm_friction_coefficient_agma(636.9854026 * 0.00508), 0.02579732749, 1e-10);
  EXPECT_NEAR(gg::worm_friction_coefficient_agma(5.0 * 0.00508), 0.124 * std::exp(-0.074 * std::pow(5.0, 0.645)), 1e-15);
  EXPECT_NEAR(gg::worm_friction_coefficient_agma(5.0 * 0.00508), 0.100617, 1e-6);
  EXPECT_EQ(gg::worm_friction_coefficient_agma(0.0), 0.150);
  EXPECT_THROW(gg::worm_friction_coefficient_agma(-1.0), std::domain_error);
  gg::WormInput in = shigley_pair();
  in.mu.reset();
  const gg::WormResult w = gg::compute_worm(in);
  EXPECT_TRUE(w.mu_from_velocity);
  EXPECT_NEAR(w.mu, 0.02579732749, 1e-9);
}

// Virtual power: what goes in leaves as output plus the friction work mu F_n v_g, for both
// drivers, both hands and both senses; the friction loss is computed from the contact force's
// size, |F| = F_n sqrt(1 + mu^2) (normal force and friction at right angles).
TEST(Worm, PowerBalanceInEveryCase) {
  for (bool right : {true, false})
    for (double n1 : {1450.0, -1450.0})
      for (bool worm_drives : {true, false}) {
        gg::WormInput in = shigley_pair();
        in.z1 = 4;  // 17.2 deg lead: not self-locking, the wheel can drive
        in.right_hand = right;
        in.n1 = n1;
        in.mu = 0.06;
        const gg::WormResult w = gg::compute_worm(in);
        const gg::WormForces f = gg::worm_forces(w, 20.0, !worm_drives, worm_drives);
        const double omega1 = std::fabs(n1) * 2.0 * std::numbers::pi / 60.0, omega2 = omega1 * in.z1 / in.z2;
        const double P1 = f.T1 * omega1, P2 = f.T2 * omega2;
        const double F_n = norm(f.on_wheel) / std::sqrt(1.0 + 0.06 * 0.06);
        const double loss = 0.06 * F_n * w.v_g;
        EXPECT_NEAR(worm_drives ? P1 - P2 : P2 - P1, loss, 1e-9 * P1) << right << n1 << worm_drives;
        EXPECT_NEAR(F_n, f.F_n, 1e-9 * f.F_n);
        EXPECT_NEAR(f.P_in - f.P_out, f.P_loss, 1e-9 * f.P_in);
        EXPECT_NEAR(f.P_out / f.P_in, worm_drives ? w.eta_12 : w.eta_21, 1e-12);
        // The driver's torque does positive work: the driven gear's force points along its motion.
        // Worm surface velocity at the pitch point (0, 0, d2/2): omega1 x r = omega1 d_w1 / 2 (+y);
        // the wheel's: omega2 about +y at radius d2/2 (+z) gives omega2 d2 / 2 (+x).
        const double v_worm_y = (n1 > 0 ? 1.0 : -1.0);
        const double v_wheel_x = w.n2 > 0 ? 1.0 : -1.0;
        const double driven_power = worm_drives ? f.on_wheel[0] * v_wheel_x : f.on_worm[1] * v_worm_y;
        EXPECT_GT(driven_power, 0.0);
        EXPECT_LT(f.on_wheel[2], 0.0);  // the contact pushes the wheel away from the worm
      }
}

TEST(Worm, WheelSenseFollowsTheHand) {
  // A right-hand screw turned about +x advances along +x in a fixed nut; a worm held axially
  // therefore moves the wheel's teeth (the nut) along -x at the pitch point (0, 0, d2/2), i.e. the
  // wheel turns about -y (omega x r = -x for omega along -y and r along +z).
  gg::WormInput in = sheet_pair();
  in.n1 = 300.0;
  EXPECT_LT(gg::compute_worm(in).n2, 0.0);
  EXPECT_NEAR(gg::compute_worm(in).n2, -20.0, 1e-12);
  in.right_hand = false;
  EXPECT_NEAR(gg::compute_worm(in).n2, 20.0, 1e-12);
}

TEST(Worm, SelfLockingIsAWarningAndStopsTheWheelDriving) {
  gg::WormInput in = sheet_pair();
  in.z1 = 1;             // tan gamma = 3/44: 3.90 deg
  in.flank = gg::WormFlank::ZI;  // alpha_n = 20 deg
  in.mu = 0.08;          // rho' = atan(0.08 / cos 20) = 4.87 deg > gamma
  in.n1 = 100.0;
  const gg::WormResult w = gg::compute_worm(in);
  EXPECT_TRUE(w.self_locking_dynamic);
  EXPECT_TRUE(w.self_locking_static);
  EXPECT_LE(w.eta_21, 0.0);
  EXPECT_FALSE(w.warnings.empty());
  EXPECT_THROW(gg::worm_forces(w, 10.0, false, false), std::domain_error);
  EXPECT_NO_THROW(gg::worm_forces(w, 10.0, true, true));
  // Efficiency by hand: tan(3.90049 deg) / tan(3.90049 + 4.86610 deg) = 0.442133
  const double g = std::atan(3.0 / 44.0), r = std::atan(0.08 / std::cos(20.0 * kDeg));
  EXPECT_NEAR(w.eta_12, std::tan(g) / std::tan(g + r), 1e-12);
  EXPECT_NEAR(w.eta_12, 0.442133, 1e-6);
}

TEST(Worm, StaticOnlySelfLocking) {
  gg::WormInput in = sheet_pair();  // 7.77 deg lead
  in.mu = 0.03;                     // running: rho' = 1.83 deg, the wheel drives
  in.mu_static = 0.15;              // at rest: rho'_0 = 9.07 deg > gamma
  const gg::WormResult w = gg::compute_worm(in);
  EXPECT_TRUE(w.self_locking_static);
  EXPECT_FALSE(w.self_locking_dynamic);
  EXPECT_GT(w.eta_21, 0.0);
}

// The worm is a crossed helical pair with beta1 = 90 deg - gamma, beta2 = gamma (both of the
// worm's hand): the closed worm formulas (Shigley's) and the crossed helical ones (derived in the
// pitch plane) must agree, and so must the force vectors after the change of frame (crossed: z
// from the worm axis towards the wheel axis, g2 = -y; worm: z from the wheel centre to the worm axis).
TEST(Worm, AgreesWithTheCrossedHelicalPair) {
  for (bool right : {true, false})
    for (bool worm_drives : {true, false}) {
      gg::WormInput in = shigley_pair();
      in.z1 = 4;
      in.right_hand = right;
      const gg::WormResult w = gg::compute_worm(in);
      gg::CrossedHelicalInput c;
      c.z1 = 30;  // placeholder tooth count: only the angles, d and speeds matter below
      c.z2 = 30;
      c.m_n = 1.0;
      c.alpha_n = w.alpha_n;
      const double hand = right ? 1.0 : -1.0;
      c.beta1 = hand * (90.0 * kDeg - w.gamma_w);
      c.beta2 = hand * w.gamma_w;
      c.mu = 0.03;
      c.n1 = in.n1;
      gg::CrossedHelicalResult ch = gg::compute_crossed_helical(c);
      EXPECT_NEAR(ch.eta_12, w.eta_12, 1e-12);
      EXPECT_NEAR(ch.eta_21, w.eta_21, 1e-12);
      // Give the crossed pair the worm's diameters so that the torques are comparable.
      ch.gear[0].d = w.d_w1;
      ch.gear[1].d = w.d2;
      const gg::CrossedForces cf = gg::crossed_forces(ch, w.alpha_n, 10.0, 1, worm_drives ? 1 : 2);
      const gg::WormForces wf = gg::worm_forces(w, 10.0, true, worm_drives);
      EXPECT_NEAR(cf.F_t2, wf.F_t2, 1e-9 * wf.F_t2);
      EXPECT_NEAR(cf.F_r, wf.F_r, 1e-9 * wf.F_r);
      // (x, y, z)_crossed = (x, -y, -z)_worm
      EXPECT_NEAR(cf.on_2[0], wf.on_wheel[0], 1e-9 * wf.F_t2) << right << worm_drives;
      EXPECT_NEAR(cf.on_2[1], -wf.on_wheel[1], 1e-9 * wf.F_t2) << right << worm_drives;
      EXPECT_NEAR(cf.on_2[2], -wf.on_wheel[2], 1e-9 * wf.F_t2) << right << worm_drives;
    }
}

TEST(Worm, BadInputNamesTheField) {
  auto field_of = [](const gg::WormInput& in) {
    try {
      gg::compute_worm(in);
    } catch (const gg::GeometryError& e) {
      return e.field();
    }
    return std::string("none");
  };
  gg::WormInput in = sheet_pair();
  in.q = 14.0;  // both q and d_m1
  EXPECT_EQ(field_of(in), "q");
  in = sheet_pair();
  in.d_m1 = 5.0;  // root diameter 5 - 7.5 < 0
  EXPECT_EQ(field_of(in), "d_m1");
  in = sheet_pair();
  in.z1 = 0;
  EXPECT_EQ(field_of(in), "z1");
  in = sheet_pair();
  in.centre_distance = 10.0;
  EXPECT_EQ(field_of(in), "centre_distance");
  in = sheet_pair();
  in.mu = -0.1;
  EXPECT_EQ(field_of(in), "mu");
}
