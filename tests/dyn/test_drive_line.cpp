// Tests of gearkit/dyn/drive_line.hpp: reduction of inertias and torques with efficiencies.
#include <gearkit/dyn/drive_line.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

using namespace gearkit::dyn;
constexpr double pi = std::numbers::pi;

namespace {

// Paper-tube cutter (seed 004_b4a8ce5a956e12a3.txt, exam 2020-21, exercise 3): reducer
// tau = 5/17, eta_r = 0.8, I_r = 0.120 kg*m^2 at the motor shaft, cutter I_t = 9.5 kg*m^2.
DriveLine cutter() {
  DriveLine line;
  line.motor_efficiency = 0.85;
  line.stages = {{"reducer", 5.0 / 17.0, 0.8}};
  line.shaft_inertia = {0.120, 9.5};
  return line;
}

// Conveyor (same seed, exercise 3 of the later exam): tau = 1/15, eta_r = 0.7; the belt's
// 1000 kg at the drum radius 0.2 m is 40 kg*m^2 on the drum shaft.
DriveLine conveyor() {
  DriveLine line;
  line.motor_efficiency = 0.6;
  line.stages = {{"reducer", 1.0 / 15.0, 0.7}};
  line.shaft_inertia = {0, 1000 * 0.2 * 0.2};
  return line;
}

}  // namespace

TEST(DriveLine, CutterInertiaReducedToTheCutterShaft) {
  // Printed e): I_maq = I_r / tau^2 + I_t = 10.89 kg*m^2.
  EXPECT_NEAR(reduced_inertia(cutter(), 1), 10.89, 0.005);
  EXPECT_NEAR(reduced_inertia(cutter(), 0), reduced_inertia(cutter(), 1) * std::pow(5.0 / 17.0, 2), 1e-12);
}

TEST(DriveLine, SpeedRatiosAndEfficiencies) {
  DriveLine line;
  line.stages = {{"a", 0.5, 0.9}, {"b", -0.25, 0.8}};  // the sign of a ratio only gives the sense
  line.shaft_inertia = {1, 2, 3};
  validate(line);
  EXPECT_DOUBLE_EQ(speed_ratio(line, 0, 2), 0.125);
  EXPECT_DOUBLE_EQ(speed_ratio(line, 2, 0), 8);
  EXPECT_DOUBLE_EQ(efficiency_between(line, 2, 0), 0.72);
  EXPECT_DOUBLE_EQ(reduced_inertia(line, 0), 1 + 2 * 0.25 + 3 * 0.125 * 0.125);
  EXPECT_THROW(speed_ratio(line, 0, 3), std::out_of_range);
}

TEST(DriveLine, OtmProblem4MotorTorqueAtTheLoad) {
  // Seed 000, OTM 2015 problem 4: M_m4 = M_m z3 / z2 = 809.262 N*m (no losses).
  DriveLine line;
  line.stages = {{"gear 2-3", 20.0 / 50.0, 1}};
  line.shaft_inertia = {0, 0.1};
  const double motor_torque = 100e3 / (2950 * 2 * pi / 60);
  EXPECT_NEAR(reduced_torque(line, motor_torque, 0, 1), 809.262, 0.0005);
}

TEST(DriveLine, EfficiencyFollowsThePowerFlow) {
  DriveLine line;
  line.stages = {{"r", 0.1, 0.8}};
  line.shaft_inertia = {0, 1};
  // A load of 100 N*m (braking) on the slow shaft needs 100 * 0.1 / 0.8 at the motor.
  EXPECT_NEAR(reduced_torque(line, -100, 1, 0), -12.5, 1e-12);
  // A descending weight driving the slow shaft gives only 100 * 0.1 * 0.8 to the motor shaft.
  EXPECT_NEAR(reduced_torque(line, 100, 1, 0), 8, 1e-12);
  // A motor torque reaches the slow shaft diminished.
  EXPECT_NEAR(reduced_torque(line, 10, 0, 1), 80, 1e-12);
  EXPECT_DOUBLE_EQ(power_at_input(80, 0.8), 100);
  EXPECT_DOUBLE_EQ(power_at_input(-100, 0.8), -80);
}

TEST(DriveLine, ConveyorAccelerationAtHalfSpeed) {
  // Seed 004, conveyor d): at omega / omega_0 = 0.5, T_m = 116 (0.3 + 0.7/4 - 1/16) = 47.85 N*m,
  // a = (T_m eta_r - F_rp tau d/2) / (m tau d/2) = 2.212 m/s^2.
  const DriveLine line = conveyor();
  const double motor_torque = 116 * (0.3 + 0.7 * 0.25 - 0.0625);
  const double drum_resisting = 300 * 0.2;
  const double alpha = drive_line_acceleration(line, motor_torque, {0, drum_resisting}, 25 * pi);
  EXPECT_NEAR(alpha * (1.0 / 15.0) * 0.2, 2.212, 0.0005);
}

TEST(DriveLine, BrakingSendsPowerBackThroughTheStages) {
  // No motor torque and a brake of 10 N*m on the motor shaft: the load's kinetic energy flows
  // back towards the motor shaft, so the stage passes it times eta. Hand balance (stage ratio
  // 0.5, eta 0.8, 2 kg*m^2 on the motor shaft, 8 kg*m^2 on the output):
  //   2 a + 10 + 0.8 (8 * 0.5^2 a) = 0  ->  a = -10 / 3.6 rad/s^2.
  DriveLine line;
  line.stages = {{"r", 0.5, 0.8}};
  line.shaft_inertia = {2, 8};
  const double alpha = drive_line_acceleration(line, 0, {10, 0}, 1);
  EXPECT_NEAR(alpha, -10 / 3.6, 1e-12);
  EXPECT_LT(8 * 0.25 * alpha, 0);  // the assumed direction: the output gives power back
  // With the brake on the output instead, power flows forward (divide by eta):
  //   2 a + (8 * 0.25 a + 10 * 0.5) / 0.8 = 0  ->  a = -6.25 / 4.5.
  EXPECT_NEAR(drive_line_acceleration(line, 0, {0, 10}, 1), -6.25 / 4.5, 1e-12);
}

TEST(DriveLine, BadLinesAreRejected) {
  DriveLine line = cutter();
  line.stages[0].efficiency = 1.2;
  try {
    validate(line);
    FAIL() << "efficiency above 1 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("(0, 1]"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("reducer"), std::string::npos) << e.what();
  }
  line = cutter();
  line.stages[0].ratio = 0;
  EXPECT_THROW(validate(line), std::invalid_argument);
  line = cutter();
  line.shaft_inertia[1] = -1;
  EXPECT_THROW(validate(line), std::invalid_argument);
  line = cutter();
  line.motor_efficiency = 0;
  EXPECT_THROW(validate(line), std::invalid_argument);
  line = cutter();
  line.shaft_inertia = {0, 0};
  EXPECT_THROW(drive_line_acceleration(line, 10, {0, 0}, 1), std::invalid_argument);
  EXPECT_THROW(drive_line_acceleration(cutter(), 10, {0}, 1), std::invalid_argument);
}
