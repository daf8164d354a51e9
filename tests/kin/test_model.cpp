// The immutable mechanism description (model.hpp): names, indices, rows and drivers, and the
// refusal of inconsistent additions.
#include <gearkit/kin/model.hpp>

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>

namespace gearkit::kin {
namespace {

Body named(const std::string& name) {
  Body b;
  b.name = name;
  b.points = {{"P", {0.1, 0.0}}};
  return b;
}

TEST(Model, NamesIndicesAndRows) {
  Model m;
  // Many bodies and constraints: lookups by name must keep answering the right index.
  const int n = 2000;
  for (int k = 0; k < n; ++k) EXPECT_EQ(m.add_body(named("link" + std::to_string(k))), k);
  for (int k = 0; k + 1 < n; ++k)
    m.add_constraint("pin" + std::to_string(k),
                     std::make_shared<Revolute>(BodyPoint{k, {0.1, 0.0}}, BodyPoint{k + 1, {0.0, 0.0}}));
  const int drv = m.add_constraint("input", std::make_shared<AngleDriver>(0, kGround, Motion{}));
  EXPECT_EQ(m.coordinates(), 3 * n);
  EXPECT_EQ(m.equations(), 2 * (n - 1) + 1);
  EXPECT_EQ(m.body_index("link1234"), 1234);
  EXPECT_EQ(m.body_index("ground"), kGround);
  EXPECT_FALSE(m.body_index("link2000").has_value());
  EXPECT_EQ(m.body_name(1234), "link1234");
  EXPECT_EQ(m.body_name(kGround), "ground");
  EXPECT_EQ(m.constraint_index("pin1998"), 1998);
  EXPECT_FALSE(m.constraint_index("pin1999").has_value());
  EXPECT_EQ(m.constraints()[1998].first_row, 2 * 1998);  // each revolute takes two rows
  EXPECT_EQ(m.constraints()[static_cast<std::size_t>(drv)].first_row, 2 * (n - 1));
  ASSERT_EQ(m.drivers().size(), 1u);
  EXPECT_EQ(m.drivers()[0].constraint, drv);
  m.set_driver(drv, DriverQuantity::angle, 0.25);
  EXPECT_EQ(m.drivers()[0].value, 0.25);
}

TEST(Model, RefusesInconsistentAdditions) {
  Model m;
  m.add_body(named("crank"));
  EXPECT_THROW(m.add_body(named("crank")), std::invalid_argument);
  EXPECT_THROW(m.add_body(named("ground")), std::invalid_argument);
  m.add_constraint("O", std::make_shared<Revolute>(BodyPoint{0, {0, 0}}, BodyPoint{kGround, {0, 0}}));
  EXPECT_THROW(m.add_constraint("O", std::make_shared<Revolute>(BodyPoint{0, {0.1, 0}}, BodyPoint{kGround, {0.1, 0}})),
               std::invalid_argument);
  EXPECT_THROW(m.add_constraint("bad", std::make_shared<Revolute>(BodyPoint{0, {0, 0}}, BodyPoint{3, {0, 0}})),
               std::invalid_argument);
  EXPECT_THROW(m.add_constraint("empty", nullptr), std::invalid_argument);
  EXPECT_THROW(m.set_driver(0, DriverQuantity::angle, 0.0), std::invalid_argument);  // not a driver
  EXPECT_EQ(m.constraints().size(), 1u);  // nothing half-added
  EXPECT_EQ(m.equations(), 2);
}

TEST(Model, PointPositionInAPose) {
  Eigen::VectorXd q(3);
  q << 0.1, 0.2, M_PI / 2;
  const Eigen::Vector2d p = Model::point_position(q, BodyPoint{0, {0.05, 0.0}});
  EXPECT_NEAR(p.x(), 0.1, 1e-15);
  EXPECT_NEAR(p.y(), 0.25, 1e-15);
  EXPECT_EQ(Model::point_position(q, BodyPoint{kGround, {0.3, 0.4}}), Eigen::Vector2d(0.3, 0.4));
}

TEST(Model, LoadsAreDetected) {
  Model m;
  m.add_body(named("link"));
  EXPECT_FALSE(m.has_loads());
  m.add_torque({0, 2.0, "T"});
  EXPECT_TRUE(m.has_loads());
}

}  // namespace
}  // namespace gearkit::kin
