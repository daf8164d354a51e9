// Tests of gearkit/cam/follower_dynamics.hpp: kinetostatic force against Norton's equation,
// jump speed against the closed form of an eccentric cam and against a speed sweep, spring
// sizing, camshaft torque by virtual power against the moment of the contact force and against
// the work lost per cycle, Hertz stress against two textbook forms, a flat face's Hertz stress and
// sliding speed and a roller's speed and traction ratio against hand derivations.
#include <gearkit/cam/follower_dynamics.hpp>

#include "cam_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using namespace gearkit::cam;
using gearkit::cam::testing::dwell;
using gearkit::cam::testing::move;
using gearkit::cam::testing::rad;
using gearkit::cam::testing::translating;

constexpr double pi = std::numbers::pi;

double rpm(double n) { return n * pi / 30; }

/// Norton, Design of Machinery, problem 15-12: a pure eccentric (e = 20 mm) driving a flat-faced
/// follower, s = e (1 - cos theta): a simple harmonic rise of 2e over 180 deg and the same return.
/// Follower mass 1 kg, spring 10 N/m with 0.2 N preload, damping ratio 0.1, 200 rpm.
CamDesign eccentric() {
  const MotionProgram p({move(SegmentKind::rise, 0, 180, Law::simple_harmonic, 40),
                         move(SegmentKind::fall, 180, 360, Law::simple_harmonic, 40)});
  CamDesign d{p, translating(Contact::flat_face), 30, Rotation::ccw};
  validate(d);
  return d;
}

FollowerTrain problem_15_12(double zeta) {
  FollowerTrain t;
  t.mass = 1, t.spring_rate = 10, t.preload = 0.2;
  t.damping = damping_for_ratio(t, zeta);  // c = 2 zeta sqrt(k m) (Norton, eq. 15.3)
  return t;
}

TEST(FollowerDynamics, ContactForceIsNortonsEquationAtEveryAngle) {
  // F = m a + c v + k (s + x0) with k x0 = F_pl (Norton, eq. 15.8); for the eccentric
  // a = e w^2 cos theta, v = e w sin theta.
  const CamDesign d = eccentric();
  const FollowerTrain t = problem_15_12(0.1);
  const double e = 0.020, w = rpm(200), c = 2 * 0.1 * std::sqrt(10.0);
  for (int i = 0; i < 360; ++i) {
    const double th = rad(i);
    const DynamicState s = dynamic_state(d, t, w, th, nullptr);
    const double expected = 1 * e * w * w * std::cos(th) + c * e * w * std::sin(th) + 10 * e * (1 - std::cos(th)) + 0.2;
    EXPECT_NEAR(s.force, expected, 1e-9) << i;
    EXPECT_NEAR(s.lever, 1, 1e-12);  // a flat face pushes along its path
    EXPECT_EQ(s.wall, s.force >= 0 ? 1 : 0);
  }
}

TEST(FollowerDynamics, EccentricJumpSpeedIsTheClosedFormAndTheSweepAgrees) {
  // Undamped, the contact is lost first at theta = 180 deg when m e w^2 > 2 k e + F_pl:
  // w_jump = sqrt((2 k e + F_pl) / (m e)) = sqrt(0.6 / 0.02) = sqrt(30) rad/s (52.3 rpm), so the
  // problem's follower jumps at 200 rpm.
  const CamDesign d = eccentric();
  const auto jump = jump_speed(d, problem_15_12(0), 0, rpm(10000));
  ASSERT_TRUE(jump);
  EXPECT_NEAR(jump->omega, std::sqrt(30.0), 1e-9);
  EXPECT_NEAR(jump->theta, pi, 1e-6);
  std::vector<double> speeds;
  for (int n = 1; n <= 20; ++n) speeds.push_back(rpm(10.0 * n));
  const SpeedSweep sweep = sweep_speeds(d, problem_15_12(0), 0, speeds);
  ASSERT_TRUE(sweep.jump);
  EXPECT_NEAR(*sweep.jump, std::sqrt(30.0), 1e-8);
  EXPECT_LT(sweep.margin.back(), 0);  // at 200 rpm the force goes negative
  // Damped (zeta = 0.1): the per-angle roots and the sweep's bisection agree.
  const auto damped = jump_speed(d, problem_15_12(0.1), 0, rpm(10000));
  const SpeedSweep damped_sweep = sweep_speeds(d, problem_15_12(0.1), 0, speeds);
  ASSERT_TRUE(damped && damped_sweep.jump);
  EXPECT_NEAR(damped->omega, *damped_sweep.jump, 1e-8 * damped->omega);
  EXPECT_FALSE(jump_speed(d, problem_15_12(0), 0, 5.0));  // none below 5 rad/s
}

TEST(FollowerDynamics, SpringSizedForTheEccentricHoldsAndIsTheHandSolution) {
  // Problem 15-12's "respecify the spring": undamped, the contact needs k e (1 - cos) + F_pl >=
  // -m e W^2 cos + F_min. The least mean spring force over the turn is the line through (0,
  // F_min) and (2e, F_min + m e W^2): k = m W^2 / 2, F_pl = F_min (hand derivation).
  const CamDesign d = eccentric();
  const double W = rpm(200);
  SizingRequest rq;
  rq.omega = W, rq.min_force = 1;
  const SpringSizing s = size_spring(d, problem_15_12(0), rq);
  EXPECT_NEAR(s.spring_rate, W * W / 2, 1e-3 * W * W / 2);
  EXPECT_NEAR(s.preload, 1, 1e-3);
  FollowerTrain sized = problem_15_12(0);
  sized.spring_rate = s.spring_rate, sized.preload = s.preload;
  for (double w : {0.0, W / 3, W / 2, W}) EXPECT_GE(least_contact_margin(d, sized, w, 1), -1e-9) << w;
  // A rate given: only the preload; here F_pl = F_min + sup(-m e W^2 cos - k e (1 - cos)) at 180 deg.
  rq.spring_rate = 100;
  const SpringSizing p = size_spring(d, problem_15_12(0), rq);
  EXPECT_NEAR(p.preload, 1 + 0.02 * W * W - 100 * 0.04, 1e-9);
  // With a damping ratio the damping follows the rate, and the result still holds.
  rq.spring_rate.reset();
  rq.damping_ratio = 0.1;
  const SpringSizing z = size_spring(d, problem_15_12(0), rq);
  FollowerTrain damped = problem_15_12(0);
  damped.spring_rate = z.spring_rate, damped.preload = z.preload, damped.damping = z.damping;
  EXPECT_NEAR(z.damping, 2 * 0.1 * std::sqrt(z.spring_rate * 1), 1e-9 * z.damping);
  for (double w : {W / 4, W / 2, 3 * W / 4, W}) EXPECT_GE(least_contact_margin(d, damped, w, 1), -1e-9) << w;
}

/// A Norton-style double-dwell cam (rise 10 mm in 90 deg, dwell 45 deg, fall 10 mm in 180 deg,
/// dwell; 3-4-5 both ways; roller 12.5 mm, base 63.7 mm), m = 7.5 kg, c = 2.74 N s/m, spring
/// 100 N/m with 10 N preload, 10 rad/s: is the spring satisfactory?
CamDesign double_dwell() {
  const MotionProgram p({move(SegmentKind::rise, 0, 90, Law::polynomial_345, 10), dwell(90, 135),
                         move(SegmentKind::fall, 135, 315, Law::polynomial_345, 10), dwell(315, 360)});
  CamDesign d{p, translating(Contact::roller, 12.5), 63.7, Rotation::ccw};
  validate(d);
  return d;
}

FollowerTrain double_dwell_train() {
  FollowerTrain t;
  t.mass = 7.5, t.spring_rate = 100, t.preload = 10, t.damping = 2.74;
  return t;
}

TEST(FollowerDynamics, DoubleDwellSpringIsNotSatisfactoryByHandCalculation) {
  // Q(u) = m L/beta^2 y'' w^2 + c L/beta y' w + k L y + F_pl with the 3-4-5 polynomial; the least
  // value in the rise (beta = pi/2), minimised here independently by dense evaluation of the
  // polynomials, is about -6.5 N: the follower leaves the cam (the kinetostatic force is negative).
  const double L = 0.010, beta = pi / 2, w = 10, m = 7.5, c = 2.74, k = 100, F = 10;
  double least = INFINITY;
  for (int i = 0; i <= 200000; ++i) {
    const double u = i / 200000.0;
    const double y = u * u * u * (10 - 15 * u + 6 * u * u), dy = 30 * u * u * (1 - u) * (1 - u),
                 d2y = 60 * u * (1 - 3 * u + 2 * u * u);
    least = std::min(least, m * L / (beta * beta) * d2y * w * w + c * L / beta * dy * w + k * L * y + F);
  }
  EXPECT_NEAR(least, -6.47, 0.01);
  const double margin = least_contact_margin(double_dwell(), double_dwell_train(), w, 0);
  EXPECT_NEAR(margin, least, 1e-6);
  const auto jump = jump_speed(double_dwell(), double_dwell_train(), 0, 1000);
  ASSERT_TRUE(jump);
  EXPECT_LT(jump->omega, w);
}

TEST(FollowerDynamics, CamshaftTorqueByVirtualPowerIsTheMomentOfTheContactForce) {
  // T w = Q dq/dt (power) must equal the moment about the cam centre of the contact force
  // F_n n at the contact point (statics of the cam), at every angle: two independent routes.
  for (bool oscillating : {false, true}) {
    SCOPED_TRACE(oscillating ? "oscillating" : "translating");
    CamDesign d = double_dwell();
    FollowerTrain t = double_dwell_train();
    if (oscillating) {
      d = CamDesign{gearkit::cam::testing::otm2015_program(), gearkit::cam::testing::oscillating(Contact::roller, 160, 110, 12),
                    50, Rotation::cw};
      t.mass = 0.02, t.spring_rate = 40, t.preload = 5, t.damping = 0.01;  // kg m^2, N m/rad, N m, N m s/rad
    }
    validate(d);
    const double w = 12, sigma = rotation_sign(d.rotation);
    for (int i = 0; i < 720; ++i) {
      const double th = rad(0.5 * i);
      const DynamicState s = dynamic_state(d, t, w, th, nullptr);
      const ContactState c = contact_at(d, th);
      // The follower pushes the cam with -F_n n at the contact; the shaft balances its moment.
      const double moment = -(c.contact_fixed.x * (-c.normal.y) - c.contact_fixed.y * (-c.normal.x)) * 1e-3 * s.contact_force;
      if (s.wall == 0) continue;
      EXPECT_NEAR(s.torque, sigma * moment, 1e-9 * std::max(1.0, std::abs(s.torque))) << i;
    }
  }
}

TEST(FollowerDynamics, CamshaftTorqueIntegratesToTheWorkLostPerCycle) {
  // Over a turn the spring and the inertia give back what they take: the shaft's work per cycle
  // is the damping loss, c w integral(q'^2 dtheta), which for a 3-4-5 segment is c w L^2 / beta
  // * 10/7 (integral of y'^2 = 900 B(5,5) = 10/7). Friction at a sliding (flat-face) contact adds
  // mu integral(F_n |v_slide|) / w.
  const CamDesign d = double_dwell();
  const FollowerTrain t = double_dwell_train();
  const double w = 5;  // below the jump speed
  const int n = 36000;
  double work = 0;
  for (const DynamicState& s : dynamics_over_turn(d, t, w, n, nullptr)) work += s.torque * 2 * pi / n;
  const double L = 0.010;
  const double loss = 2.74 * w * L * L * (10.0 / 7.0) * (1 / (pi / 2) + 1 / pi);
  EXPECT_NEAR(work, loss, 1e-6 * loss);
  // The mean torque times the speed is the power lost.
  FollowerTrain sliding = t;
  sliding.friction = 0.1;
  CamDesign flat = d;
  flat.follower = translating(Contact::flat_face);
  double with_friction = 0, friction_work = 0;
  for (const DynamicState& s : dynamics_over_turn(flat, sliding, w, n, nullptr)) {
    with_friction += s.torque * 2 * pi / n;
    friction_work += 0.1 * s.contact_force * s.sliding_speed / w * 2 * pi / n;
  }
  EXPECT_NEAR(with_friction, loss + friction_work, 1e-6 * (loss + friction_work));
  EXPECT_GT(friction_work, 0);
}

TEST(FollowerDynamics, HertzLineStressAgreesWithNortonsForm) {
  // Johnson, Contact Mechanics, eq. 4.45: p0 = sqrt(P E* / (pi R)); Norton, Machine Design,
  // sec. 7.10: b = sqrt(2 F (m1 + m2) / (pi L B)), p_max = 2 F / (pi b L), B = (1/R1 + 1/R2) / 2,
  // m = (1 - nu^2) / E. Steel on steel, roller 10 mm on a 25 mm convex cam, 2 kN over 12 mm.
  const double E = 206e9, nu = 0.3, F = 2000, L = 0.012, R1 = 0.025, R2 = 0.010;
  const double p0 = hertz_line_stress(F, L, R1, R2, contact_modulus(E, nu, E, nu));
  const double m = (1 - nu * nu) / E, B = 0.5 * (1 / R1 + 1 / R2);
  const double b = std::sqrt(2 * F * (2 * m) / (pi * L * B));
  EXPECT_NEAR(p0, 2 * F / (pi * b * L), 1e-6 * p0);
  // A hand value: E* = 206e9 / (2 (1 - 0.09)) = 113.2 GPa, 1/R = 140 1/m, P = 166.7 kN/m:
  // p0 = sqrt(166667 * 113.19e9 * 140 / pi) = 916.9 MPa.
  EXPECT_NEAR(p0 / 1e6, 916.9, 0.1);
  // Concave cam radius larger than the roller: conformal, lower stress; smaller: no contact.
  EXPECT_LT(hertz_line_stress(F, L, -0.030, R2, contact_modulus(E, nu, E, nu)), p0);
  EXPECT_TRUE(std::isnan(hertz_line_stress(F, L, -0.008, R2, contact_modulus(E, nu, E, nu))));
  EXPECT_EQ(hertz_line_stress(-5, L, R1, R2, contact_modulus(E, nu, E, nu)), 0);
}

TEST(FollowerDynamics, RollerRollsWithTheProfileSpeedOverItsRadius) {
  // Rolling without slip: on a dwell (circle of radius R_b about the centre) the roller turns at
  // w R_b / R_r relative to a translating follower.
  const CamDesign d = double_dwell();
  ContactMaterial steel;
  steel.width = 0.015;
  const DynamicState s = dynamic_state(d, double_dwell_train(), 10, rad(100), &steel);
  EXPECT_NEAR(std::abs(s.roller_speed), 10 * (63.7 + 10) / 12.5, 1e-9);
  // On the upper dwell the cam's radius is R_b + L = 73.7 mm, convex: Hertz with 1/R = 1/73.7 + 1/12.5.
  const double E_star = contact_modulus(206e9, 0.3, 206e9, 0.3);
  EXPECT_NEAR(s.hertz_stress, hertz_line_stress(s.contact_force, 0.015, 0.0737, 0.0125, E_star), 1e-6 * s.hertz_stress);
  EXPECT_NEAR(s.rho_cam, 0.0737, 1e-9);
}

/// Cycloidal law over a segment of beta rad, lift L: s, s', s'' against theta (Norton, Design of
/// Machinery, ch. 8, cycloidal displacement: s = L (x - sin(2 pi x) / (2 pi)), x = theta / beta).
struct Svaj {
  double s, v, a;
};
Svaj cycloidal(double L, double beta, double theta) {
  const double x = theta / beta;
  return {L * (x - std::sin(2 * pi * x) / (2 * pi)), L / beta * (1 - std::cos(2 * pi * x)),
          2 * pi * L / (beta * beta) * std::sin(2 * pi * x)};
}

TEST(FollowerDynamics, FlatFaceHertzIsLineContactOnTheCamsRadiusOfCurvature) {
  // A flat face on a convex cam: a line contact between a cylinder of the cam's radius of curvature
  // rho and a plane, p0 = sqrt(P E* / (pi rho)), P = F / L (Johnson, Contact Mechanics, eq. 4.45
  // with 1/R = 1/rho + 1/infinity). For a translating flat face normal to its path, rho = R_b + s +
  // s'' (Norton, Design of Machinery, ch. 8, flat-faced follower), the normal is along the path (F_n = Q) and the
  // cam's point at the contact (height R_b + s) slides along the face at w (R_b + s).
  const double Rb = 40, L_rise = 20, beta = rad(120), w = 30;
  CamDesign d{gearkit::cam::testing::rise_dwell_return(L_rise), translating(Contact::flat_face), Rb, Rotation::ccw};
  validate(d);
  FollowerTrain t;
  t.mass = 2, t.spring_rate = 2000, t.preload = 50, t.damping = 10;
  ContactMaterial m;
  m.width = 0.012, m.E_cam = 206e9, m.nu_cam = 0.3, m.E_follower = 100e9, m.nu_follower = 0.25;
  const double E_star = 1 / ((1 - 0.09) / 206e9 + (1 - 0.0625) / 100e9);  // Johnson, eq. 4.22
  for (double deg : {10.0, 30.0, 55.0, 75.0, 100.0, 115.0}) {
    const Svaj k = cycloidal(L_rise, beta, rad(deg));
    const double Q = t.mass * k.a * 1e-3 * w * w + t.damping * k.v * 1e-3 * w + t.spring_rate * k.s * 1e-3 + t.preload;
    const double rho = (Rb + k.s + k.a) * 1e-3;
    const DynamicState s = dynamic_state(d, t, w, rad(deg), &m);
    ASSERT_GT(Q, 0) << deg;
    EXPECT_NEAR(s.contact_force, Q, 1e-9 * Q) << deg;
    EXPECT_NEAR(s.rho_cam, rho, 1e-9) << deg;
    EXPECT_NEAR(s.hertz_stress, std::sqrt(Q / m.width * E_star / (pi * rho)), 1e-7 * s.hertz_stress) << deg;
    EXPECT_NEAR(s.sliding_speed, w * (Rb + k.s) * 1e-3, 1e-9) << deg;
  }
  // On the base circle (a dwell): rho = R_b, the preload alone.
  const DynamicState b = dynamic_state(d, t, w, rad(330), &m);
  EXPECT_NEAR(b.hertz_stress, std::sqrt(50 / m.width * E_star / (pi * Rb * 1e-3)), 1e-7 * b.hertz_stress);
}

TEST(FollowerDynamics, RollerSpeedAndTractionRatioAreTheRollingRollersByHand) {
  // A radial translating roller on a cam turning at w (ccw). In the cam's frame the roller centre
  // runs along the pitch curve r = R_p + s (R_p = R_b + R_r) at V_p = w sqrt(r^2 + s'^2), and the
  // contact point, where it rolls without slip, is its instantaneous centre: it turns at V_p / R_r
  // relative to the cam (clockwise, as it goes round the cam clockwise), so at W = w - V_p / R_r
  // absolute, which is its speed on a translating follower's pin (-w R_b / R_r on the base circle).
  // Its angular acceleration w dW/dtheta = -w^2 s' (r + s'') / (R_r sqrt(r^2 + s'^2)) needs the
  // tangential force I |alpha| / R_r at the contact; the normal force is Q / cos(phi), tan(phi) =
  // s' / r (Norton, Design of Machinery, ch. 8, pressure angle with no eccentricity).
  const double Rb = 40, Rr = 10, L_rise = 20, beta = rad(120), w = 40;
  CamDesign d{gearkit::cam::testing::rise_dwell_return(L_rise), translating(Contact::roller, Rr), Rb, Rotation::ccw};
  validate(d);
  FollowerTrain t;
  t.mass = 1.5, t.spring_rate = 3000, t.preload = 80, t.roller_inertia = 4e-6;
  for (double deg : {5.0, 20.0, 45.0, 60.0, 80.0, 100.0, 118.0}) {
    const Svaj k = cycloidal(L_rise, beta, rad(deg));
    const double r = (Rb + Rr + k.s) * 1e-3, v = k.v * 1e-3, a = k.a * 1e-3;
    const double Vp = w * std::hypot(r, v);
    const double spin = w - Vp / (Rr * 1e-3);
    const double alpha = -w * w * v * (r + a) / (Rr * 1e-3 * std::hypot(r, v));
    const double Q = t.mass * a * w * w + t.spring_rate * k.s * 1e-3 + t.preload;
    const double Fn = Q * std::hypot(r, v) / r;
    const DynamicState s = dynamic_state(d, t, w, rad(deg), nullptr);
    EXPECT_NEAR(s.roller_speed, spin, 1e-9 * std::abs(spin)) << deg;
    EXPECT_NEAR(s.contact_force, Fn, 1e-9 * Fn) << deg;
    EXPECT_NEAR(s.traction / s.contact_force, t.roller_inertia * std::abs(alpha) / (Rr * 1e-3) / Fn,
                1e-6 * s.traction / s.contact_force + 1e-12)
        << deg;
  }
  // On a dwell the roller turns steadily: no traction needed.
  const DynamicState dw = dynamic_state(d, t, w, rad(150), nullptr);
  EXPECT_NEAR(dw.roller_speed, -w * (Rb + L_rise) / Rr, 1e-9);
  EXPECT_NEAR(dw.traction, 0, 1e-9);
}

}  // namespace

namespace {

using namespace gearkit::cam;
using gearkit::cam::testing::rad;
using gearkit::cam::testing::translating;

TEST(FollowerDynamics, FormClosedCamsCarryTheNegativeForceOnTheOtherSurface) {
  // Groove and conjugate cams: no spring, Q = M q'' w^2 + c q' w + F_load; where Q < 0 the outer
  // wall or the second roller pushes back, with F_n = Q / h on that surface (h < 0), and the
  // shaft torque is still the moment of that contact force about the cam centre.
  for (Closure closure : {Closure::groove, Closure::conjugate}) {
    CamDesign d{gearkit::cam::testing::rise_dwell_return(20), translating(Contact::roller, 10), 40, Rotation::ccw};
    d.follower.closure = closure;
    d.follower.second.distance = 130;
    validate(d);
    FollowerTrain t;
    t.mass = 2, t.damping = 5;
    const double w = 30;
    const CamDesign other = closure == Closure::groove ? outer_wall_of(d) : conjugate_cam_of(d);
    bool both = false;
    for (int i = 0; i < 360; ++i) {
      const DynamicState s = dynamic_state(d, t, w, rad(i), nullptr);
      EXPECT_GE(s.contact_force, 0);
      EXPECT_NE(s.wall, 0);
      const ContactState c = contact_at(s.wall > 0 ? d : other, rad(i));
      const double h = (c.normal.x * c.point_per_s.x + c.normal.y * c.point_per_s.y);
      EXPECT_NEAR(s.contact_force, s.force / h, 1e-9 * std::max(1.0, s.contact_force));
      const double moment = (c.contact_fixed.x * c.normal.y - c.contact_fixed.y * c.normal.x) * 1e-3 * s.contact_force;
      EXPECT_NEAR(s.torque, moment, 1e-9 * std::max(1.0, std::abs(s.torque))) << i;
      both = both || s.wall < 0;
    }
    EXPECT_TRUE(both);
  }
}

}  // namespace
