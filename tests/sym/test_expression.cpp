// Tests for gearkit/sym/expression.hpp: formulas compared after trigonometric expansion.
#include <gearkit/sym/expression.hpp>

#include <gtest/gtest.h>

#include <stdexcept>

using gearkit::sym::equivalent;
using gearkit::sym::equivalent_up_to_sign;

TEST(Expression, AngleSumIdentities) {
  EXPECT_TRUE(equivalent("sin(a-b)", "sin(a)*cos(b)-cos(a)*sin(b)"));
  EXPECT_TRUE(equivalent("cos(a+b)", "cos(a)*cos(b)-sin(a)*sin(b)"));
  EXPECT_TRUE(equivalent("cos(phi2-phi1)", "cos(phi1-phi2)"));
  EXPECT_TRUE(equivalent("sin(-x)", "-sin(x)"));
  EXPECT_TRUE(equivalent("l3*sin(phi2+phi3)/(l1*sin(phi2+phi1))", "l3*sin(phi3+phi2)/(l1*sin(phi1+phi2))"));
}

TEST(Expression, DifferentFormulasAreNotEquivalent) {
  EXPECT_FALSE(equivalent("sin(a-b)", "sin(a+b)"));
  EXPECT_FALSE(equivalent("l1*cos(phi1)", "l1*sin(phi1)"));
  EXPECT_FALSE(equivalent("l1/l3", "l3/l1"));
  EXPECT_FALSE(equivalent_up_to_sign("d-l1*cos(phi1)", "d+l1*cos(phi1)"));
}

TEST(Expression, RowsOfPhiMatchUpToSign) {
  EXPECT_TRUE(equivalent_up_to_sign("-l3*cos(phi2)-l1*cos(phi1)+d", "l3*cos(phi2)+l1*cos(phi1)-d"));
  EXPECT_FALSE(equivalent("-l3*cos(phi2)-l1*cos(phi1)+d", "l3*cos(phi2)+l1*cos(phi1)-d"));
}

TEST(Expression, UnreadableTextIsAnError) {
  EXPECT_THROW(equivalent("sin(", "x"), std::invalid_argument);
}
