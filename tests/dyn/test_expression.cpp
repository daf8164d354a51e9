// Tests of gearkit/dyn/expression.hpp (muParser behind a small interface).
#include <gearkit/dyn/expression.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

using gearkit::dyn::Expression;

TEST(Expression, ConveyorMotorCurve) {
  // Seed 004_b4a8ce5a956e12a3.txt, conveyor exercise d): T_m = T_0 (c1 + c2 x^2 + c3 x^4),
  // x = omega / omega_0, T_0 = 116 N*m, omega_0 = 50 pi rad/s, c = 0.3, 0.7, -1.
  // At x = 0.5: 116 (0.3 + 0.175 - 0.0625) = 47.85 N*m.
  const Expression t("T0*(c1 + c2*(omega/w0)^2 + c3*(omega/w0)^4)", {"omega"},
                     {{"T0", 116}, {"w0", 50 * std::numbers::pi}, {"c1", 0.3}, {"c2", 0.7}, {"c3", -1}});
  EXPECT_NEAR(t({25 * std::numbers::pi}), 47.85, 1e-12);
  EXPECT_NEAR(t({0}), 34.8, 1e-12);
}

TEST(Expression, SeveralVariablesAndFunctions) {
  const Expression e("a*sin(theta) + max(omega, 2) + _pi", {"theta", "omega"}, {{"a", 3}});
  EXPECT_NEAR(e({std::numbers::pi / 2, 1}), 3 + 2 + std::numbers::pi, 1e-12);
}

TEST(Expression, MalformedOrUnknownNamesAreRejected) {
  EXPECT_THROW(Expression("", {"theta"}), std::invalid_argument);
  EXPECT_THROW(Expression("2*(theta", {"theta"}), std::invalid_argument);
  try {
    Expression("3*omega", {"theta"});
    FAIL() << "unknown variable accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("3*omega"), std::string::npos) << e.what();
  }
  EXPECT_THROW(Expression("system(1)", {"theta"}), std::invalid_argument);
}

TEST(Expression, NonFiniteResultIsADomainError) {
  const Expression e("1/theta", {"theta"});
  EXPECT_THROW(e({0.0}), std::domain_error);
  EXPECT_THROW(e(std::span<const double>()), std::invalid_argument);
}
