#pragma once
// Small helpers to build mechanisms in C++ for the element tests (no YAML anywhere).
#include <gearkit/kin/data.hpp>
#include <gearkit/kin/joints.hpp>
#include <gearkit/kin/model.hpp>
#include <gearkit/kin/solve.hpp>
#include <gearkit/kin/testing.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace gearkit::elements::testing {

inline constexpr double kDeg = std::numbers::pi / 180.0;

/// A body with its frame at `origin` [m], drawn at `angle` [rad], and points in local coordinates [m].
inline int add_body(kin::Model& model, const std::string& name, Eigen::Vector2d origin, double angle,
                    std::vector<std::pair<std::string, Eigen::Vector2d>> points, double inertia = 0.0) {
  kin::Body b;
  b.name = name;
  b.points = std::move(points);
  b.position_guess = origin;
  b.angle_guess = angle;
  b.inertia = inertia;
  return model.add_body(std::move(b));
}

inline kin::BodyPoint point(const kin::Model& model, int body, const std::string& name) {
  const kin::Body& b = body == kin::kGround ? model.ground() : model.bodies()[static_cast<std::size_t>(body)];
  return {body, *b.point(name)};
}

inline void revolute(kin::Model& model, const std::string& name, int a, const std::string& pa, int b,
                     const std::string& pb) {
  model.add_constraint(name, std::make_shared<kin::Revolute>(point(model, a, pa), point(model, b, pb)));
}

/// An angle driver of `body` relative to ground at `value` [rad], speed [rad/s].
inline int drive_angle(kin::Model& model, int body, double value, double speed = 1.0) {
  const int c = model.add_constraint("driver", std::make_shared<kin::AngleDriver>(body, kin::kGround, kin::Motion{speed, 0.0}));
  model.set_driver(c, kin::DriverQuantity::angle, value);
  return c;
}

/// Position, velocity and acceleration at the drivers' values; fails the test if any step fails.
inline void solve_all(const kin::Model& model, kin::Data& data) {
  const kin::PositionReport p = kin::solve_position(model, data, 0.0);
  ASSERT_TRUE(p.converged) << p.message;
  ASSERT_TRUE(kin::solve_velocity(model, data));
  ASSERT_TRUE(kin::solve_acceleration(model, data));
}

/// Phi_q, Phi_t and gamma of `c` against finite differences of its Phi at random
/// configurations (kin::testing::check_derivatives, the checker of every element type).
inline void expect_derivatives(const kin::Constraint& c) {
  const kin::testing::DerivativeReport r = kin::testing::check_derivatives(c);
  EXPECT_TRUE(r.ok()) << r.describe(c.kind());
  EXPECT_GE(r.entries_checked, 16 * 5);  // at least a row of one moving body per configuration
}

/// The same for the constraint of `model` named `name`.
inline void expect_derivatives(const kin::Model& model, const std::string& name) {
  const std::optional<int> index = model.constraint_index(name);
  ASSERT_TRUE(index) << name;
  expect_derivatives(*model.constraints()[static_cast<std::size_t>(*index)].constraint);
}

/// The value a reaction names `symbol`, or NaN.
inline double value_of(const std::vector<kin::ReactionValue>& values, const std::string& symbol) {
  for (const auto& v : values)
    if (v.symbol == symbol) return v.value;
  return std::nan("");
}

}  // namespace gearkit::elements::testing
