// Outputs: rates and accelerations against finite differences in time, ratios against
// finite differences in the input.
#include <gearkit/kin/output.hpp>
#include <gearkit/kin/solve.hpp>

#include <gtest/gtest.h>

#include "mechanisms.hpp"

namespace gearkit::kin {
namespace {

using testing::kDeg;

TEST(Output, RatesAndAccelerationsMatchFiniteDifferences) {
  Model m = testing::pantograph(-70 * kDeg);
  // Drive with speed 2 rad/s and acceleration 5 rad/s^2 through time.
  Model timed;
  timed.ground() = m.ground();
  for (const Body& b : m.bodies()) timed.add_body(b);
  for (const ModelConstraint& c : m.constraints())
    if (!c.constraint->is_driver()) timed.add_constraint(c.name, c.constraint);
  const int drv = timed.add_constraint("input", std::make_shared<AngleDriver>(0, kGround, Motion{2.0, 5.0}));
  timed.set_driver(drv, DriverQuantity::angle, -70 * kDeg);
  std::vector<Output> outputs(4);
  outputs[0] = {"s", OutputKind::slider_displacement, {}, 0, kGround, *timed.constraint_index("guide")};
  outputs[1] = {"Tx", OutputKind::point_x, testing::at(timed, 3, "T")};
  outputs[2] = {"Ty", OutputKind::point_y, testing::at(timed, 3, "T")};
  outputs[3] = {"arm-coupler", OutputKind::body_angle, {}, 3, 1};
  Data data(timed);
  const double t = 0.05, h = 1e-4;
  const SolverOptions tight{1e-13, 50, 0.5};
  auto value_at = [&](double time, const Output& o) {
    EXPECT_TRUE(solve_position(timed, data, time, tight).converged);
    return evaluate_output(timed, data, o).value;
  };
  for (const Output& o : outputs) {
    const double vm = value_at(t - h, o), vp = value_at(t + h, o), v0 = value_at(t, o);
    ASSERT_TRUE(solve_velocity(timed, data));
    ASSERT_TRUE(solve_acceleration(timed, data));
    const OutputValue ov = evaluate_output(timed, data, o);
    EXPECT_NEAR(ov.value, v0, 1e-15) << o.name;
    EXPECT_NEAR(ov.rate, (vp - vm) / (2 * h), 1e-7) << o.name;
    EXPECT_NEAR(ov.acceleration, (vp - 2 * v0 + vm) / (h * h), 1e-4) << o.name;
    // Ratio to the input: the rate divided by the input speed at t.
    const Eigen::VectorXd dq = input_sensitivity(timed, data, 0);
    EXPECT_NEAR(output_derivative(timed, data, o, dq) * (2.0 + 5.0 * t), ov.rate, 1e-10) << o.name;
  }
}

// The course's conventions and the new kinds, each against an independent evaluation: a point's
// coordinate from another point (difference of the two points' positions), an angle along a
// segment, clockwise and from the vertical (atan2 of the segment's end points), a point's speed
// and acceleration magnitude (norms of finite differences of its position in time).
TEST(Output, ConventionsSpeedAndAccelerationMagnitude) {
  Model m = testing::pantograph(-70 * kDeg);
  Model timed;
  timed.ground() = m.ground();
  for (const Body& b : m.bodies()) timed.add_body(b);
  for (const ModelConstraint& c : m.constraints())
    if (!c.constraint->is_driver()) timed.add_constraint(c.name, c.constraint);
  const int drv = timed.add_constraint("input", std::make_shared<AngleDriver>(0, kGround, Motion{2.0, 5.0}));
  timed.set_driver(drv, DriverQuantity::angle, -70 * kDeg);
  const BodyPoint T = testing::at(timed, 3, "T"), S = testing::at(timed, 3, "S"), R = testing::at(timed, 3, "R");
  Output from{"T from R", OutputKind::point_x, T};
  from.from = R;
  Output along{"RS cw from vertical", OutputKind::body_angle, {}, 3, kGround};
  along.offset = std::atan2(S.local.y() - R.local.y(), S.local.x() - R.local.x());
  along.zero = 90 * kDeg;
  along.sense = -1;
  const Output speed{"speed of T", OutputKind::point_speed, T};
  const Output accel{"acceleration of T", OutputKind::point_acceleration, T};
  Data data(timed);
  const SolverOptions tight{1e-13, 50, 0.5};
  const double t = 0.05, h = 1e-4;
  auto position_at = [&](double time, const BodyPoint& p) {
    EXPECT_TRUE(solve_position(timed, data, time, tight).converged);
    return point_position(data, p);
  };
  const Eigen::Vector2d pm = position_at(t - h, T), pp = position_at(t + h, T), p2m = position_at(t - 2 * h, T),
                        p2p = position_at(t + 2 * h, T), p0 = position_at(t, T);
  const Eigen::Vector2d s0 = position_at(t, S), r0 = position_at(t, R);
  ASSERT_TRUE(solve_position(timed, data, t, tight).converged);
  ASSERT_TRUE(solve_velocity(timed, data));
  ASSERT_TRUE(solve_acceleration(timed, data));
  EXPECT_NEAR(evaluate_output(timed, data, from).value, (p0 - r0).x(), 1e-15);
  const double direction = std::atan2(s0.y() - r0.y(), s0.x() - r0.x());
  EXPECT_NEAR(std::remainder(evaluate_output(timed, data, along).value - (90 * kDeg - direction), 2 * M_PI), 0.0, 1e-12);
  const Eigen::Vector2d v = (pp - pm) / (2 * h), a = (pp - 2 * p0 + pm) / (h * h);
  const OutputValue sv = evaluate_output(timed, data, speed);
  EXPECT_NEAR(sv.value, v.norm(), 1e-7);
  // d|v|/dt from the speeds at t +- h (fourth-order central velocities there).
  const Eigen::Vector2d vp = (p2p - p0) / (2 * h), vm = (p0 - p2m) / (2 * h);
  EXPECT_NEAR(sv.rate, (vp.norm() - vm.norm()) / (2 * h), 1e-4);
  EXPECT_TRUE(std::isnan(sv.acceleration));
  EXPECT_NEAR(evaluate_output(timed, data, accel).value, a.norm(), 1e-4);
  // Ratios: speed per unit input speed; none for an acceleration.
  const Eigen::VectorXd dq = input_sensitivity(timed, data, 0);
  EXPECT_NEAR(output_derivative(timed, data, speed, dq) * (2.0 + 5.0 * t), sv.value, 1e-10);
  EXPECT_TRUE(std::isnan(output_derivative(timed, data, accel, dq)));
  EXPECT_NEAR(output_derivative(timed, data, along, dq), -(dq(3 * 3 + 2)), 1e-15);
  EXPECT_STREQ(output_units(speed).value, "mm_s");
  EXPECT_STREQ(output_units(accel).rate, "");
  EXPECT_STREQ(output_units(along).value, "deg");
}

TEST(Output, SliderOutputNeedsAPrismatic) {
  Model m = testing::four_bar({0.04, 0.12, 0.08, 0.1}, 0.3);
  Data data(m);
  Output o{"bad", OutputKind::slider_displacement, {}, 0, kGround, 0};
  EXPECT_THROW(evaluate_output(m, data, o), std::invalid_argument);
}

TEST(Model, RejectsDuplicatesAndBadIndices) {
  Model m;
  Body b;
  b.name = "crank";
  m.add_body(b);
  EXPECT_THROW(m.add_body(b), std::invalid_argument);
  b.name = "ground";
  EXPECT_THROW(m.add_body(b), std::invalid_argument);
  EXPECT_THROW(m.add_constraint("j", std::make_shared<Revolute>(BodyPoint{0, Eigen::Vector2d::Zero()}, BodyPoint{5, Eigen::Vector2d::Zero()})), std::invalid_argument);
  m.add_constraint("j", std::make_shared<Revolute>(BodyPoint{0, Eigen::Vector2d::Zero()}, BodyPoint{kGround, Eigen::Vector2d::Zero()}));
  EXPECT_THROW(m.add_constraint("j", std::make_shared<Revolute>(BodyPoint{0, Eigen::Vector2d::Zero()}, BodyPoint{kGround, Eigen::Vector2d::Zero()})), std::invalid_argument);
  EXPECT_THROW(m.set_driver(0, DriverQuantity::angle, 0.0), std::invalid_argument);  // not a driver
  EXPECT_EQ(m.equations(), 2);
  EXPECT_EQ(m.coordinates(), 3);
  EXPECT_EQ(*m.body_index("ground"), kGround);
  EXPECT_FALSE(m.body_index("nope"));
  EXPECT_FALSE(m.has_loads());
}

}  // namespace
}  // namespace gearkit::kin
