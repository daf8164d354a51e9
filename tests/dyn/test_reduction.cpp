// Tests of gearkit/dyn/reduction.hpp: virtual power, reduced forces and reduced inertia of a
// linkage from velocity coefficients.
#include <gearkit/dyn/motion.hpp>
#include <gearkit/dyn/reduction.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

using namespace gearkit::dyn;
constexpr double pi = std::numbers::pi;

TEST(Reduction, Otm2015Problem1cReducedForceAtA) {
  // Seed 000_bc94d104a9983772.txt, OTM 2015 problem 1 c): seat m5 = 8 kg, v_A = 2 m/s downwards,
  // v_5 = 0.76 m/s upwards, a_5 = 0.6 m/s^2; weight P5 = 8 * 9.8 = 78.4 N, inertia force
  // F_i5 = 4.8 N at 112 deg from v_5 (the seed's angle). Printed: F_A = 30.48 N against V_A,
  // and the balancing torque on the crank M2 = F_A * O2A = 36.6 N*m (O2A = 1.2 m).
  const Vec2 v_a{0, -2};
  const Vec2 v_5{0, 0.76};
  const double angle = (90.0 + 112.0) * pi / 180;  // measured from +x; v_5 points along +y
  const std::vector<ForceAtPoint> forces{
      {weight(8, 9.8), v_5},
      {{4.8 * std::cos(angle), 4.8 * std::sin(angle)}, v_5},
  };
  const double power = virtual_power(forces);
  const double f_a = reduced_force(power, v_a);
  EXPECT_NEAR(f_a, -30.48, 0.005);  // negative: it opposes V_A
  const double omega_2 = 2 / 1.2;
  EXPECT_NEAR(std::abs(reduced_torque_at(power, omega_2)), 36.6, 0.05);
  EXPECT_NEAR(std::abs(f_a) * 1.2, 36.6, 0.05);
  EXPECT_THROW(reduced_force(power, {0, 0}), std::invalid_argument);
  EXPECT_THROW(reduced_torque_at(power, 0), std::invalid_argument);
  const Vec2 fi = inertia_force(8, {0, 0.6});
  EXPECT_DOUBLE_EQ(fi.y, -4.8);
}

namespace {

// Slider-crank: crank O A (r), rod A B (l), slider B on the x axis. Crank J_O, rod mass m_rod
// with centre at mid-rod and J_G = m l^2 / 12, slider m_s.
struct SliderCrank {
  double r = 0.1, l = 0.4, j_crank = 0.02, m_rod = 2, m_s = 5;

  Vec2 a(double q) const { return {r * std::cos(q), r * std::sin(q)}; }
  Vec2 b(double q) const { return {r * std::cos(q) + std::sqrt(l * l - std::pow(r * std::sin(q), 2)), 0}; }
  Vec2 g(double q) const { return {(a(q).x + b(q).x) / 2, (a(q).y + b(q).y) / 2}; }
  double phi(double q) const { return std::atan2(-a(q).y, b(q).x - a(q).x); }

  std::vector<BodyMass> bodies() const {
    return {{0, j_crank}, {m_rod, m_rod * l * l / 12}, {m_s, 0}};
  }

  // Velocity coefficients by differences of the closed-form positions (what a position solver
  // alone would give), and their derivatives by second differences.
  std::vector<VelocityCoefficients> coefficients(double q) const {
    const double h = 1e-5;
    const auto d = [h](auto f, double x) { return (f(x + h) - f(x - h)) / (2 * h); };
    const auto d2 = [h](auto f, double x) { return (f(x + h) - 2 * f(x) + f(x - h)) / (h * h); };
    const auto gx = [this](double x) { return g(x).x; };
    const auto gy = [this](double x) { return g(x).y; };
    const auto bx = [this](double x) { return b(x).x; };
    const auto ph = [this](double x) { return phi(x); };
    VelocityCoefficients crank{{0, 0}, 1, {0, 0}, 0};
    VelocityCoefficients rod{{d(gx, q), d(gy, q)}, d(ph, q), {d2(gx, q), d2(gy, q)}, d2(ph, q)};
    VelocityCoefficients slider{{d(bx, q), 0}, 0, {d2(bx, q), 0}, 0};
    return {crank, rod, slider};
  }
};

}  // namespace

TEST(Reduction, SliderCrankInertiaAtHandPositions) {
  const SliderCrank sc;
  const auto bodies = sc.bodies();
  // q = 90 deg: the rod translates with A (omega_rod = 0) and B moves with A: I = J + (m_rod + m_s) r^2.
  EXPECT_NEAR(reduced_inertia(bodies, sc.coefficients(pi / 2)), sc.j_crank + (sc.m_rod + sc.m_s) * sc.r * sc.r, 1e-8);
  // q = 0: B is at rest, the rod turns about B at r / l, its centre moves at r / 2:
  // I = J + m_rod (r/2)^2 + J_G (r/l)^2.
  const double expected0 = sc.j_crank + sc.m_rod * std::pow(sc.r / 2, 2) + sc.m_rod * sc.l * sc.l / 12 * std::pow(sc.r / sc.l, 2);
  EXPECT_NEAR(reduced_inertia(bodies, sc.coefficients(0)), expected0, 1e-8);
  // dI/dq against a difference of I.
  const double q = 0.7, h = 1e-4;
  const double fd = (reduced_inertia(bodies, sc.coefficients(q + h)) - reduced_inertia(bodies, sc.coefficients(q - h))) / (2 * h);
  EXPECT_NEAR(reduced_inertia_derivative(bodies, sc.coefficients(q)), fd, 1e-5);
}

TEST(Reduction, WeightTorqueOfAPendulum) {
  // A point mass m at distance L from the pivot, q from the horizontal: T = -m g L cos q.
  const std::vector<BodyMass> bodies{{3, 0}};
  const double q = 0.4, L = 0.5;
  const std::vector<VelocityCoefficients> k{{{-L * std::sin(q), L * std::cos(q)}, 1, {}, 0}};
  EXPECT_NEAR(reduced_weight_torque(bodies, k, 9.81), -3 * 9.81 * L * std::cos(q), 1e-12);
  EXPECT_NEAR(reduced_torque_of_force({0, -10}, k[0].k_G), -10 * L * std::cos(q), 1e-12);
}

TEST(Reduction, SpringTorqueIsMinusTheDerivativeOfItsEnergy) {
  // A spring from the fixed point Q = (0.3, 0.2) to the crank pin P = r (cos q, sin q):
  // T = -dV/dq with V = 1/2 k (|PQ| - L0)^2, checked by a central difference of V.
  const double r = 0.1, k = 2000, l0 = 0.15;
  const Vec2 q_fixed{0.3, 0.2};
  const auto pin = [r](double q) { return Vec2{r * std::cos(q), r * std::sin(q)}; };
  const auto energy = [&](double q) {
    const Vec2 p = pin(q);
    const double l = std::hypot(p.x - q_fixed.x, p.y - q_fixed.y);
    return 0.5 * k * (l - l0) * (l - l0);
  };
  for (double q : {0.0, 0.8, 2.0, 4.5}) {
    const Vec2 k_p{-r * std::sin(q), r * std::cos(q)};
    const double h = 1e-6;
    EXPECT_NEAR(reduced_spring_torque(pin(q), q_fixed, k_p, {0, 0}, k, l0), -(energy(q + h) - energy(q - h)) / (2 * h), 1e-5)
        << "q = " << q;
  }
  // A slider on x with a spring to the origin: the reduced force is -k (x - L0).
  EXPECT_NEAR(reduced_spring_torque({0.4, 0}, {0, 0}, {1, 0}, {0, 0}, k, l0), -k * (0.4 - l0), 1e-9);
  EXPECT_THROW(spring_force_on({1, 1}, {1, 1}, k, l0), std::invalid_argument);
}

TEST(Reduction, TabulatedLinkageConservesEnergyInTheEquationOfMotion) {
  const SliderCrank sc;
  const auto bodies = sc.bodies();
  const InertiaTable table = tabulate_inertia(
      bodies, [&sc](double q) { return sc.coefficients(q); }, 0, 2 * pi, 360, true);
  EXPECT_NEAR(table.inertia(pi / 2), sc.j_crank + (sc.m_rod + sc.m_s) * sc.r * sc.r, 1e-8);
  EXPECT_NEAR(table.inertia(2 * pi + pi / 2), table.inertia(pi / 2), 1e-14);
  // The mean against a fine midpoint rule over the interpolant itself.
  double mean = 0;
  const int n = 36000;
  for (int i = 0; i < n; ++i) mean += table.inertia(2 * pi * (i + 0.5) / n) / n;
  EXPECT_NEAR(table.mean_inertia(), mean, 1e-10);
  ReducedSystem sys;
  sys.inertia = [&table](double q) { return table.inertia(q); };
  sys.inertia_derivative = [&table](double q) { return table.derivative(q); };
  MotionOptions o;
  o.t_end = 1;
  o.output_step = 1e-3;
  o.stop_when_steady = false;
  const MotionResult res = integrate_motion(acceleration_law(sys), 0, 30, o);
  const double e0 = 0.5 * table.inertia(0) * 900;
  double worst = 0;
  for (const auto& s : res.samples) worst = std::max(worst, std::abs(0.5 * table.inertia(s.theta) * s.omega * s.omega - e0));
  // The interpolant is only C1 at the nodes, which costs the integrator some accuracy there;
  // an I' inconsistent with I would make the energy drift by the interpolation error instead.
  EXPECT_LT(worst, 1e-6 * e0);
  EXPECT_GT(res.samples.back().theta, 4 * pi);  // several turns, through every table interval
}

TEST(Reduction, BadInertiaTablesAndBodies) {
  using V = std::vector<double>;
  EXPECT_THROW(InertiaTable(V{0, 1, 2}, V{1, 0, 1}, {}, true), std::invalid_argument);   // zero inertia
  EXPECT_THROW(InertiaTable(V{0, 1, 2}, V{1, -2, 1}, {}, true), std::invalid_argument);  // negative
  EXPECT_THROW(InertiaTable(V{0, 1, 2}, V{1, 2, 3}, {}, true), std::invalid_argument);   // not periodic
  EXPECT_THROW(InertiaTable(V{0, 2, 1}, V{1, 2, 1}, {}, true), std::invalid_argument);   // not increasing
  EXPECT_THROW(InertiaTable(V{0, 1}, V{1, 1}, {}, true), std::invalid_argument);         // too few
  const std::vector<BodyMass> bad{{-1, 0}};
  const std::vector<VelocityCoefficients> k(1);
  EXPECT_THROW(reduced_inertia(bad, k), std::invalid_argument);
  EXPECT_THROW(reduced_inertia(std::vector<BodyMass>{{1, 0}, {1, 0}}, k), std::invalid_argument);
  // Central differences for a table given without derivatives: exact for a linear stretch.
  const InertiaTable lin(V{0, 1, 2, 3}, V{1, 2, 3, 4}, {}, false);
  EXPECT_NEAR(lin.derivative(1.5), 1, 1e-12);
  EXPECT_NEAR(lin.inertia(1.5), 2.5, 1e-12);
}
