// Tests of gearkit/dyn/motion.hpp: the equation of motion integrated with Boost.Odeint, checked
// against closed forms, an independent quadrature, and energy balances.
#include <gearkit/dyn/curve.hpp>
#include <gearkit/dyn/drive_line.hpp>
#include <gearkit/dyn/flywheel.hpp>
#include <gearkit/dyn/motion.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

using namespace gearkit::dyn;
constexpr double pi = std::numbers::pi;

namespace {

// Conveyor of seed 004_b4a8ce5a956e12a3.txt: T_m = 116 (0.3 + 0.7 x^2 - x^4), x = w / (50 pi);
// reducer 1/15, eta 0.7; belt 1000 kg at r = 0.2 m; passive resistances 300 N.
double conveyor_motor_torque(double w) {
  const double x = w / (50 * pi);
  return 116 * (0.3 + 0.7 * x * x - x * x * x * x);
}

DriveLine conveyor_line() {
  DriveLine line;
  line.motor_efficiency = 0.6;
  line.stages = {{"reducer", 1.0 / 15.0, 0.7}};
  line.shaft_inertia = {0, 1000 * 0.2 * 0.2};
  return line;
}

AccelerationLaw conveyor_law() {
  return [line = conveyor_line()](double, double, double w) {
    return drive_line_acceleration(line, conveyor_motor_torque(w), {0, 300 * 0.2}, w);
  };
}

// The seed's start-up balance solved by hand: T_m eta = F r tau  ->  with x^2 = u,
// u^2 - 0.7 u - (0.3 - F r tau / (eta T_0)) = 0.
double conveyor_steady_speed() {
  const double c = 0.3 - 300 * 0.2 / 15 / (0.7 * 116);
  const double u = (0.7 + std::sqrt(0.49 + 4 * c)) / 2;
  return std::sqrt(u) * 50 * pi;
}

// The seed's equation of motion while accelerating, written on the motor shaft:
// alpha = (T_m eta - F r tau) / (m r^2 tau^2).
double conveyor_alpha(double w) {
  const double tau = 1.0 / 15.0;
  return (conveyor_motor_torque(w) * 0.7 - 300 * 0.2 * tau) / (1000 * 0.04 * tau * tau);
}

}  // namespace

TEST(Motion, ConveyorAccelerationAtHalfSpeed) {
  // Seed: a = 2.212 m/s^2 when omega / omega_0 = 0.5.
  const double alpha = conveyor_law()(0, 0, 25 * pi);
  EXPECT_NEAR(alpha / 15 * 0.2, 2.212, 0.0005);
}

TEST(Motion, ConveyorStartUpReachesTheSteadySpeed) {
  MotionOptions o;
  o.t_end = 30;
  o.output_step = 1e-3;
  o.steady_tolerance = 1e-9;
  const MotionResult r = integrate_motion(conveyor_law(), 0, 0, o);
  ASSERT_FALSE(r.cannot_start);
  ASSERT_TRUE(r.steady);
  const double w_ss = conveyor_steady_speed();  // 153.98 rad/s, about 1470 min^-1
  EXPECT_NEAR(r.samples.back().omega, w_ss, 1e-6 * w_ss);
  EXPECT_NEAR(r.cycle_mean_speed.back(), w_ss, 1e-6 * w_ss);

  // Start-up time to 95 % of the steady speed against an independent quadrature of
  // t = integral dw / alpha(w) (Simpson, 20000 intervals).
  const double w_end = 0.95 * w_ss;
  const int n = 20000;
  double sum = 0;
  for (int i = 0; i <= n; ++i) {
    const double w = w_end * i / n;
    const double weight = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    sum += weight / conveyor_alpha(w);
  }
  const double t_quadrature = sum * (w_end / n) / 3;
  const auto t_ode = time_to_reach(r, w_end);
  ASSERT_TRUE(t_ode.has_value());
  EXPECT_NEAR(*t_ode, t_quadrature, 1e-4 * t_quadrature);
}

TEST(Motion, FlywheelOfOtmProblem4KeepsTheFluctuation) {
  // OTM 2015 problem 4 (seed 000): with the closed-form total inertia, the integrated motion over
  // one steady cycle must swing between the closed-form omega_min and omega_max. With constant
  // inertia the relation E = I delta omega_m^2 is exact, so only integration error remains.
  const double w_load = 2950 * 2 * pi / 60 * 0.4;
  const double drive = 100e3 / (2950 * 2 * pi / 60) * 2.5;
  const PiecewiseLinear d = PiecewiseLinear::constant(drive, 0, 2 * pi);
  const PiecewiseLinear res = PiecewiseLinear({0, pi / 2, pi, 2 * pi}, {0, 0, 1, 0}, true).scaled(drive * 8 / 3);
  const CycleEnergy c = analyse_cycle(d, res);
  const FlywheelSizing s = size_flywheel(c.energy_excursion, w_load, 0.005, 0.1);

  ReducedSystem sys;
  sys.inertia = [&](double) { return s.inertia_total; };
  sys.drive_torque = [&](double th, double) { return d(th); };
  sys.resisting_torque = [&](double th, double) { return res(th); };
  MotionOptions o;
  o.t_end = 0.2;
  o.output_step = 1e-4;
  o.cycle = 2 * pi;
  o.stop_when_steady = false;
  const MotionResult r = integrate_motion(acceleration_law(sys), c.theta_at_energy_min, s.omega_min, o);
  ASSERT_GE(r.cycle_max_speed.size(), 2u);
  EXPECT_NEAR(r.cycle_max_speed[0], s.omega_max, 1e-7 * s.omega_max);
  EXPECT_NEAR(r.cycle_min_speed[0], s.omega_min, 1e-7 * s.omega_min);
  // Steady: the speed comes back after each cycle (driving energy = resisting energy).
  EXPECT_NEAR(r.cycle_mean_speed[1], r.cycle_mean_speed[0], 1e-9 * w_load);
  const double delta = (r.cycle_max_speed[1] - r.cycle_min_speed[1]) /
                       (0.5 * (r.cycle_max_speed[1] + r.cycle_min_speed[1]));
  EXPECT_NEAR(delta, 0.005, 1e-7);
}

TEST(Motion, CutterAtConstantPowerBalancesEnergyPerCycle) {
  // Seed 004, paper-tube cutter f): P = 2.1 kW through eta_r = 0.8 into I_maq = 10.89 kg*m^2,
  //   I_maq omega alpha + T_r omega - P eta_r = 0.
  // In the steady cycle the energy received equals the energy taken: P eta_r t_c = E_t, so the
  // cycle lasts E_t / (P eta_r), and the losses are P (1 - eta_r) t_c.
  const double inertia = 0.120 * std::pow(17.0 / 5.0, 2) + 9.5;
  const PiecewiseLinear tr = gearkit::dyn::difference(
      PiecewiseLinear::constant(22.5, 0, 30 * pi),
      PiecewiseLinear({0, 20 * pi, 25 * pi, 30 * pi}, {0, 0, -135, 0}, true));
  const double e_t = tr.integral(0, 30 * pi);
  ReducedSystem sys;
  sys.inertia = [&](double) { return inertia; };
  sys.drive_torque = [](double, double w) { return 2100 * 0.8 / w; };
  sys.resisting_torque = [&](double th, double) { return tr(th); };
  MotionOptions o;
  o.t_end = 400;
  o.output_step = 0.01;
  o.cycle = 30 * pi;
  o.steady_tolerance = 1e-10;
  const MotionResult r = integrate_motion(acceleration_law(sys), 0, 10 * pi, o);
  ASSERT_TRUE(r.steady);
  const std::size_t k = r.cycle_end_times.size() - 1;
  const double t_c = r.cycle_end_times[k] - r.cycle_end_times[k - 1];
  EXPECT_NEAR(t_c, e_t / (2100 * 0.8), 1e-6 * t_c);
  EXPECT_NEAR(2100 * t_c, e_t + 2100 * 0.2 * t_c, 1e-6 * e_t);
}

TEST(Motion, VariableInertiaConservesKineticEnergy) {
  // Slider-crank, crank r = 0.1 m, rod l = 0.4 m, slider 5 kg, crank 0.02 kg*m^2; no torque.
  // x = r cos q + sqrt(l^2 - r^2 sin^2 q), I = J + m (dx/dq)^2, and 1/2 I(q) q'^2 stays constant.
  const double r = 0.1, l = 0.4, m = 5, j = 0.02;
  const auto k = [&](double q) {
    const double s = std::sin(q), c = std::cos(q);
    return -r * s - r * r * s * c / std::sqrt(l * l - r * r * s * s);
  };
  const auto dk = [&](double q) {  // central difference of k is enough for the check below
    const double h = 1e-5;
    return (k(q + h) - k(q - h)) / (2 * h);
  };
  ReducedSystem sys;
  sys.inertia = [&](double q) { return j + m * k(q) * k(q); };
  sys.inertia_derivative = [&](double q) { return 2 * m * k(q) * dk(q); };
  MotionOptions o;
  o.t_end = 2;
  o.output_step = 1e-3;
  o.stop_when_steady = false;
  const MotionResult res = integrate_motion(acceleration_law(sys), 0.3, 20, o);
  const double e0 = 0.5 * sys.inertia(0.3) * 400;
  double worst = 0, spread = 0;
  double wmin = 1e9, wmax = 0;
  for (const auto& s : res.samples) {
    worst = std::max(worst, std::abs(0.5 * sys.inertia(s.theta) * s.omega * s.omega - e0));
    wmin = std::min(wmin, s.omega);
    wmax = std::max(wmax, s.omega);
  }
  spread = wmax - wmin;
  EXPECT_LT(worst, 1e-7 * e0);
  EXPECT_GT(spread, 1);  // the speed does vary: the check is not trivial
}

TEST(Motion, CannotStartAndStall) {
  ReducedSystem sys;
  sys.inertia = [](double) { return 2.0; };
  sys.drive_torque = [](double, double) { return 1.0; };
  sys.resisting_torque = [](double, double) { return 2.0; };
  MotionOptions o;
  o.t_end = 5;
  const MotionResult r = integrate_motion(acceleration_law(sys), 0, 0, o);
  EXPECT_TRUE(r.cannot_start);
  EXPECT_EQ(r.samples.size(), 1u);
  // From 3 rad/s the net -1 N*m on 2 kg*m^2 stops it at t = 2 * 3 / 1 = 6 s.
  o.t_end = 10;
  const MotionResult s = integrate_motion(acceleration_law(sys), 0, 3, o);
  EXPECT_TRUE(s.stalled);
  EXPECT_NEAR(s.stall_time, 6, 1e-9);
  EXPECT_EQ(s.samples.back().omega, 0);
}

TEST(Motion, SlowDriftIsNotSteady) {
  // Constant power into a free inertia keeps speeding up (omega^2 = omega0^2 + 2 P t / I): at
  // 1000 rad/s the mean speed changes by only 2 pi P / (I omega^2) = 6.3e-6 rad/s per turn,
  // 6.3e-9 relative, far below the tolerance, yet the change does not decay, so it is not steady.
  ReducedSystem sys;
  sys.inertia = [](double) { return 1.0; };
  sys.drive_torque = [](double, double w) { return 1.0 / w; };
  MotionOptions o;
  o.t_end = 2;
  o.output_step = 1e-3;
  const MotionResult r = integrate_motion(acceleration_law(sys), 0, 1000, o);
  EXPECT_FALSE(r.steady);
  EXPECT_NEAR(r.samples.back().omega, std::sqrt(1000.0 * 1000.0 + 2 * 1.0 * 2), 1e-9 * 1000);
}

TEST(Motion, StepLimitBoundsTheWork) {
  // A free flywheel at 100 rad/s never becomes "steady" in a way that stops early when asked
  // not to; the step limit ends it and says so.
  ReducedSystem sys;
  sys.inertia = [](double) { return 1.0; };
  MotionOptions o;
  o.t_end = 1e6;
  o.output_step = 1e3;
  o.stop_when_steady = false;
  o.max_steps = 100;
  const MotionResult r = integrate_motion(acceleration_law(sys), 0, 100, o);
  EXPECT_TRUE(r.step_limit_reached);
  EXPECT_LT(r.samples.back().t, o.t_end);
  // The motion itself is right: theta = omega t.
  EXPECT_NEAR(r.samples.back().theta, 100 * r.samples.back().t, 1e-6 * r.samples.back().theta);
}

TEST(Motion, BadInertiaAndOptions) {
  ReducedSystem sys;
  sys.inertia = [](double) { return 0.0; };
  sys.drive_torque = [](double, double) { return 1.0; };
  const AccelerationLaw law = acceleration_law(sys);
  EXPECT_THROW(law(0, 0, 0), std::domain_error);
  EXPECT_THROW(acceleration_law(ReducedSystem{}), std::invalid_argument);
  MotionOptions o;
  o.t_end = 0;
  sys.inertia = [](double) { return 1.0; };
  EXPECT_THROW(integrate_motion(acceleration_law(sys), 0, 0, o), std::invalid_argument);
}
