#include <gearkit/train/rational.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace gearkit::train {
namespace {

TEST(Rational, FractionStrings) {
  EXPECT_EQ(to_fraction_string(Rational(94, 144)), "47/72");
  EXPECT_EQ(to_fraction_string(Rational(-6, 3)), "-2");
  EXPECT_EQ(to_fraction_string(Rational(0)), "0");
  // The issue's own example of the output format.
  EXPECT_EQ(to_fraction_and_decimal(Rational(47, 72)), "47/72 = 0.652778");
  EXPECT_EQ(to_fraction_and_decimal(Rational(3)), "3");
}

TEST(Rational, FromDouble) {
  EXPECT_EQ(rational_from_double(0.98), Rational(49, 50));
  EXPECT_EQ(rational_from_double(-0.0625), Rational(-1, 16));
  EXPECT_EQ(rational_from_double(2.5), Rational(5, 2));
  EXPECT_EQ(rational_from_double(6.0), Rational(6));
  EXPECT_THROW(rational_from_double(std::nan("")), std::invalid_argument);
  EXPECT_THROW(rational_from_double(1.0, 0.0), std::invalid_argument);
}

TEST(Rational, MakeRationalMovesTheSign) {
  EXPECT_EQ(make_rational(24, -84), Rational(-2, 7));
  EXPECT_EQ(make_rational(-24, -84), Rational(2, 7));
  EXPECT_THROW(make_rational(1, 0), std::invalid_argument);
}

TEST(Rational, ToDouble) { EXPECT_DOUBLE_EQ(to_double(Rational(1, 3)), 1.0 / 3.0); }

}  // namespace
}  // namespace gearkit::train
