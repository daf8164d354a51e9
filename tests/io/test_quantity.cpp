// Tests for gearkit/io/quantity.hpp. Reference factors: SI brochure (BIPM, 9th ed.) definitions:
// 1 in = 25.4 mm exactly, 1 rev = 2 pi rad, 1 min = 60 s, 1 hp (mechanical) = 745.699872 W.
#include <gearkit/io/quantity.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

using gearkit::io::parse_quantity_si;
using gearkit::io::Quantity;
using gearkit::io::QuantityError;

namespace {
constexpr double pi = std::numbers::pi;
}

TEST(Quantity, ParsesEveryUnitOfTheIssue) {
  EXPECT_DOUBLE_EQ(parse_quantity_si("9 mm", Quantity::length, "mm"), 0.009);
  EXPECT_DOUBLE_EQ(parse_quantity_si("0.2 m", Quantity::length, "mm"), 0.2);
  EXPECT_DOUBLE_EQ(parse_quantity_si("20 deg", Quantity::angle, "deg"), 20 * pi / 180);
  EXPECT_DOUBLE_EQ(parse_quantity_si("1.2 rad", Quantity::angle, "deg"), 1.2);
  EXPECT_DOUBLE_EQ(parse_quantity_si("2950 rpm", Quantity::angular_velocity, "rpm"), 2950 * 2 * pi / 60);
  EXPECT_DOUBLE_EQ(parse_quantity_si("100 kW", Quantity::power, "W"), 100e3);
  EXPECT_DOUBLE_EQ(parse_quantity_si("36.6 N*m", Quantity::torque, "N*m"), 36.6);
  EXPECT_DOUBLE_EQ(parse_quantity_si("0.1 kg*m^2", Quantity::moment_of_inertia, "kg*m^2"), 0.1);
}

TEST(Quantity, BareNumberTakesTheFieldsDefaultUnit) {
  EXPECT_DOUBLE_EQ(parse_quantity_si("9", Quantity::length, "mm"), 0.009);
  EXPECT_DOUBLE_EQ(parse_quantity_si("20", Quantity::angle, "deg"), 20 * pi / 180);
  EXPECT_DOUBLE_EQ(parse_quantity_si("1500", Quantity::angular_velocity, "rpm"), 50 * pi);
  EXPECT_DOUBLE_EQ(parse_quantity_si("2.5", Quantity::dimensionless, ""), 2.5);
}

// Issue 25, 1: `train --power sun=7.5` was 7.5 W and `gear --power 7.5` 7.5 kW. An option's power,
// torque or speed now needs its unit; the same text with a unit gives the same SI value as a model
// file (1 kW = 1000 W; 1 rpm = 2 pi / 60 rad/s; SI brochure).
TEST(Quantity, AnOptionsPowerTorqueOrSpeedNeedsItsUnit) {
  using gearkit::io::parse_option_quantity_si;
  using gearkit::io::parse_option_quantity_si_any_size;
  const auto message = [](std::string_view text, Quantity q) {
    try {
      parse_option_quantity_si(text, q, "");
    } catch (const QuantityError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(message("7.5", Quantity::power), "expected a power with its unit (7.5kW, 7500 W), found '7.5'");
  EXPECT_EQ(message(" 7.5 ", Quantity::power), "expected a power with its unit (7.5kW, 7500 W), found '7.5'");
  EXPECT_EQ(message("40", Quantity::torque), "expected a torque with its unit (36.6 N*m, 0.5 kN*m), found '40'");
  EXPECT_EQ(message("1450", Quantity::angular_velocity),
            "expected an angular velocity with its unit (1450rpm, 152 rad/s), found '1450'");
  EXPECT_EQ(message("200", Quantity::velocity), "expected a velocity with its unit (200 mm/min, 0.5 m/s), found '200'");
  EXPECT_THROW(parse_option_quantity_si_any_size("1e300", Quantity::velocity, "mm/min"), QuantityError);
  EXPECT_THROW(parse_option_quantity_si("0", Quantity::power, "W"), QuantityError);  // even 0 needs a unit
  EXPECT_DOUBLE_EQ(parse_option_quantity_si("7.5kW", Quantity::power, ""), 7500.0);
  EXPECT_DOUBLE_EQ(parse_option_quantity_si("7500 W", Quantity::power, ""), 7500.0);
  EXPECT_DOUBLE_EQ(parse_option_quantity_si("1450rpm", Quantity::angular_velocity, ""), 1450 * 2 * pi / 60);
  EXPECT_DOUBLE_EQ(parse_option_quantity_si("0.5 kN*m", Quantity::torque, ""), 500.0);
  // Not a number at all is the parser's own message, not the unit rule's.
  EXPECT_EQ(message("kW", Quantity::power).find("with its unit"), std::string::npos);
  // Lengths and angles keep the option's bare-number unit.
  EXPECT_DOUBLE_EQ(parse_option_quantity_si("3", Quantity::length, "mm"), 0.003);
  EXPECT_DOUBLE_EQ(parse_option_quantity_si("20", Quantity::angle, "deg"), 20 * pi / 180);
  EXPECT_TRUE(gearkit::io::option_needs_unit(Quantity::power));
  EXPECT_FALSE(gearkit::io::option_needs_unit(Quantity::length));
  EXPECT_FALSE(gearkit::io::option_needs_unit(Quantity::time));
}

TEST(Quantity, NumberForms) {
  EXPECT_DOUBLE_EQ(parse_quantity_si("9mm", Quantity::length, ""), 0.009);
  EXPECT_DOUBLE_EQ(parse_quantity_si("  .5 m ", Quantity::length, ""), 0.5);
  EXPECT_DOUBLE_EQ(parse_quantity_si("-1.5e-3 m", Quantity::length, ""), -1.5e-3);
  EXPECT_DOUBLE_EQ(parse_quantity_si("+2E2 mm", Quantity::length, ""), 0.2);
}

TEST(Quantity, DerivedAndOtherUnits) {
  EXPECT_DOUBLE_EQ(parse_quantity_si("1 in", Quantity::length, ""), 0.0254);
  EXPECT_DOUBLE_EQ(parse_quantity_si("90 °", Quantity::angle, ""), pi / 2);
  EXPECT_DOUBLE_EQ(parse_quantity_si("0.25 rev", Quantity::angle, ""), pi / 2);
  EXPECT_DOUBLE_EQ(parse_quantity_si("10 rad/s", Quantity::angular_velocity, ""), 10);
  EXPECT_DOUBLE_EQ(parse_quantity_si("10 1/s", Quantity::angular_velocity, ""), 10 * 2 * pi);
  EXPECT_DOUBLE_EQ(parse_quantity_si("2 m/s^2", Quantity::acceleration, ""), 2);
  EXPECT_DOUBLE_EQ(parse_quantity_si("3 kN*m", Quantity::torque, ""), 3000);
  EXPECT_NEAR(parse_quantity_si("140.08 lbf*in", Quantity::torque, ""), 140.08 * 4.4482216152605 * 0.0254, 1e-12);  // pound-force (NIST SP 811)
  EXPECT_DOUBLE_EQ(parse_quantity_si("1 hp", Quantity::power, ""), 745.69987158227022);
  EXPECT_DOUBLE_EQ(parse_quantity_si("5 N/mm", Quantity::stiffness, ""), 5000);
  EXPECT_DOUBLE_EQ(parse_quantity_si("200 GPa", Quantity::pressure, ""), 200e9);
  EXPECT_DOUBLE_EQ(parse_quantity_si("2 kWh", Quantity::energy, ""), 7.2e6);
  EXPECT_DOUBLE_EQ(parse_quantity_si("500 g", Quantity::mass, ""), 0.5);
  EXPECT_DOUBLE_EQ(parse_quantity_si("1 kg*mm^2", Quantity::moment_of_inertia, ""), 1e-6);
  EXPECT_DOUBLE_EQ(parse_quantity_si("2 min", Quantity::time, ""), 120);
  // Cam follower trains: damping, torsion springs and rotational damping.
  EXPECT_DOUBLE_EQ(parse_quantity_si("2.74 N*s/m", Quantity::damping, ""), 2.74);
  EXPECT_DOUBLE_EQ(parse_quantity_si("3 N*s/mm", Quantity::damping, ""), 3000);
  EXPECT_DOUBLE_EQ(parse_quantity_si("50 N*m/rad", Quantity::torsional_stiffness, ""), 50);
  EXPECT_DOUBLE_EQ(parse_quantity_si("1 N*m/deg", Quantity::torsional_stiffness, ""), 180 / pi);
  EXPECT_DOUBLE_EQ(parse_quantity_si("0.5 N*m*s/rad", Quantity::torsional_damping, ""), 0.5);
  EXPECT_THROW(parse_quantity_si("50 N/m", Quantity::torsional_stiffness, ""), QuantityError);
  EXPECT_THROW(parse_quantity_si("2 N*s", Quantity::damping, ""), QuantityError);
}

// ISO 80000-3 items 3-17 and 3-18: rotational frequency n counts revolutions per time, written
// min^-1, r/min or rev/min; only a unit naming an angle (rad/s, deg/s) is an angular velocity.
// Seed 004 writes n_mot = 1440 min^-1 and reads it as 1440 * 2 pi / 60 = 150.80 rad/s.
TEST(Quantity, RotationalSpeedWithoutAnAngleCountsRevolutions) {
  const double n = 1440 * 2 * pi / 60;
  EXPECT_DOUBLE_EQ(parse_quantity_si("1440 min^-1", Quantity::angular_velocity, "rpm"), n);
  EXPECT_DOUBLE_EQ(parse_quantity_si("1440 1/min", Quantity::angular_velocity, "rpm"), n);
  EXPECT_DOUBLE_EQ(parse_quantity_si("1440 r/min", Quantity::angular_velocity, "rpm"), n);
  EXPECT_DOUBLE_EQ(parse_quantity_si("1440 rev/min", Quantity::angular_velocity, "rpm"), n);
  EXPECT_DOUBLE_EQ(parse_quantity_si("1440 rpm", Quantity::angular_velocity, "rpm"), n);
  EXPECT_DOUBLE_EQ(parse_quantity_si("24 s^-1", Quantity::angular_velocity, "rpm"), n);
  EXPECT_DOUBLE_EQ(parse_quantity_si("150 rad/min", Quantity::angular_velocity, "rpm"), 2.5);
  EXPECT_DOUBLE_EQ(gearkit::io::unit_factor_si("min^-1", Quantity::angular_velocity), 2 * pi / 60);
  // A frequency or a rate that is not a rotational speed keeps its plain meaning.
  EXPECT_DOUBLE_EQ(parse_quantity_si("2 1/s^2", Quantity::angular_acceleration, ""), 2);
  EXPECT_DOUBLE_EQ(parse_quantity_si("3 min", Quantity::time, ""), 180);
}

// The spellings of the seeds' printed text: 1020 min⁻¹, 20 N·m, 0.120 kg·m², a ⋅ as product.
TEST(Quantity, UnicodeSpellingsOfTheSeeds) {
  EXPECT_DOUBLE_EQ(parse_quantity_si("1020 min⁻¹", Quantity::angular_velocity, "rpm"), 1020 * 2 * pi / 60);
  EXPECT_DOUBLE_EQ(parse_quantity_si("20 N·m", Quantity::torque, ""), 20);
  EXPECT_DOUBLE_EQ(parse_quantity_si("465.9 N·mm", Quantity::torque, ""), 0.4659);
  EXPECT_DOUBLE_EQ(parse_quantity_si("0.120 kg·m²", Quantity::moment_of_inertia, ""), 0.12);
  EXPECT_DOUBLE_EQ(parse_quantity_si("2 kg⋅m²", Quantity::moment_of_inertia, ""), 2);
  EXPECT_DOUBLE_EQ(parse_quantity_si("9.81 m/s²", Quantity::acceleration, ""), 9.81);
  EXPECT_THROW(parse_quantity_si("1 mm³", Quantity::length, ""), QuantityError);  // a volume
}

// Issue 26, section 3. An exponent 0 is a factor of 1 (x^0 = 1): N*m*rad^0 is N*m. U+03BC (Greek
// mu) and U+00B5 (micro sign) look the same in every font; both are micro (SI brochure, 9th ed.,
// table 7: the prefix symbol is the Greek letter mu). No-break spaces (U+00A0, U+202F) and the
// thin space (U+2009) that word processors put between a number and its unit are spaces.
TEST(Quantity, ZeroExponentGreekMuAndNoBreakSpaces) {
  EXPECT_DOUBLE_EQ(parse_quantity_si("36.6 N*m*rad^0", Quantity::torque, ""), 36.6);
  EXPECT_DOUBLE_EQ(parse_quantity_si("2 kg*m^2*s^0", Quantity::moment_of_inertia, ""), 2);
  EXPECT_DOUBLE_EQ(parse_quantity_si("5 \u03bcm", Quantity::length, "mm"), 5e-6);
  EXPECT_DOUBLE_EQ(parse_quantity_si("5 \u00b5m", Quantity::length, "mm"), 5e-6);
  EXPECT_DOUBLE_EQ(parse_quantity_si("9\u00a0mm", Quantity::length, ""), 0.009);
  EXPECT_DOUBLE_EQ(parse_quantity_si("9\u202fmm", Quantity::length, ""), 0.009);
  EXPECT_DOUBLE_EQ(parse_quantity_si("\u00a09 mm\u00a0", Quantity::length, ""), 0.009);
  EXPECT_DOUBLE_EQ(parse_quantity_si("20\u2009N\u00b7m", Quantity::torque, ""), 20);
  // A no-break space between two units is refused as a space is, and shown as one plainly.
  try {
    parse_quantity_si("9 mm\u00a0mm", Quantity::length, "");
    FAIL() << "accepted two units";
  } catch (const QuantityError& e) {
    EXPECT_NE(std::string(e.what()).find("between units"), std::string::npos) << e.what();
  }
}

TEST(Quantity, TypedBoostUnitsFrontEnds) {
  namespace io = gearkit::io;
  EXPECT_DOUBLE_EQ(io::parse<io::Length>("9").value(), 0.009);
  EXPECT_DOUBLE_EQ(io::parse<io::Angle>("180").value(), pi);
  EXPECT_DOUBLE_EQ(io::parse<io::AngularVelocity>("60").value(), 2 * pi);
  EXPECT_DOUBLE_EQ(io::parse<io::Power>("100 kW").value(), 1e5);
  EXPECT_DOUBLE_EQ(io::parse<io::Torque>("36.6").value(), 36.6);
  EXPECT_DOUBLE_EQ(io::parse<io::MomentOfInertia>("0.1").value(), 0.1);
}

// Each malformed input must be refused with a message that says what was wrong.
struct Malformed {
  const char* text;
  Quantity expected;
  const char* message_part;
};

class QuantityMalformed : public ::testing::TestWithParam<Malformed> {};

TEST_P(QuantityMalformed, IsRefusedWithAClearMessage) {
  const Malformed& m = GetParam();
  try {
    parse_quantity_si(m.text, m.expected, "mm");
    FAIL() << "accepted '" << m.text << "'";
  } catch (const QuantityError& e) {
    EXPECT_NE(std::string(e.what()).find(m.message_part), std::string::npos)
        << "message for '" << m.text << "' was: " << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    All, QuantityMalformed,
    ::testing::Values(Malformed{"", Quantity::length, "empty"},
                      Malformed{"   ", Quantity::length, "empty"},
                      Malformed{"mm", Quantity::length, "expected a length"},
                      Malformed{"9 mmm", Quantity::length, "unknown unit 'mmm'"},
                      Malformed{"9 MM", Quantity::length, "unknown unit 'MM'"},
                      Malformed{"20 deg", Quantity::length, "expected a length"},
                      Malformed{"9 mm", Quantity::angle, "expected an angle"},
                      Malformed{"5 m/s", Quantity::length, "expected a length"},
                      Malformed{"9,5 mm", Quantity::length, "comma"},
                      Malformed{"9 m^", Quantity::length, "exponent"},
                      Malformed{"9 m^x", Quantity::length, "exponent"},
                      Malformed{"9 m^9", Quantity::length, "exponent"},
                      Malformed{"9 m^-5", Quantity::length, "exponent"},
                      Malformed{"9 m/", Quantity::length, "expected a unit"},
                      Malformed{"9 * m", Quantity::length, "expected a unit symbol"},
                      Malformed{"9 mm mm", Quantity::length, "between units"},
                      Malformed{"nan", Quantity::length, "expected a length"},
                      Malformed{"inf mm", Quantity::length, "expected a length"},
                      Malformed{"1e999 mm", Quantity::length, "finite"},
                      Malformed{"0x10 mm", Quantity::length, "decimal"},
                      Malformed{"--9 mm", Quantity::length, "expected a length"},
                      Malformed{"2950 rpm", Quantity::power, "expected a power"},
                      Malformed{"100 kW", Quantity::torque, "expected a torque"},
                      Malformed{"0.1 kg*m", Quantity::moment_of_inertia, "expected a moment of inertia"},
                      Malformed{"20 deg", Quantity::dimensionless, "expected a plain number"},
                      Malformed{"12 teeth", Quantity::dimensionless, "unknown unit"}));

TEST(Quantity, DefaultUnitIsCheckedToo) {
  // A programming error in a field's declared default must not pass silently.
  EXPECT_THROW(parse_quantity_si("9", Quantity::length, "deg"), QuantityError);
}

// Issue 11 items 7 and 10: every quantity has a range (docs/units.md) far beyond any machine but
// far inside double's, so that no accepted value can make a result overflow to inf or divide to
// nan; the message names the range in SI.
TEST(Quantity, SizesOutsideTheRangeAreRefused) {
  EXPECT_DOUBLE_EQ(parse_quantity_si("10 km", Quantity::length, "mm"), 1e4);  // the largest length
  EXPECT_DOUBLE_EQ(parse_quantity_si("0 mm", Quantity::length, "mm"), 0.0);
  EXPECT_DOUBLE_EQ(parse_quantity_si("-210 GPa", Quantity::pressure, "MPa"), -210e9);  // a modulus fits
  for (const auto& [text, q] : std::vector<std::pair<std::string, Quantity>>{
           {"1e200", Quantity::length}, {"1e-300", Quantity::dimensionless}, {"4.9e-324", Quantity::length}, {"1e-400", Quantity::length},
           {"1e300", Quantity::dimensionless}, {"1e9 rpm", Quantity::angular_velocity}, {"-1e20 deg", Quantity::angle},
           {"1e13 W", Quantity::power}}) {
    try {
      parse_quantity_si(text, q, q == Quantity::length ? "mm" : "");
      ADD_FAILURE() << text << " was accepted";
    } catch (const QuantityError& e) {
      EXPECT_NE(std::string(e.what()).find("of size 0 or between"), std::string::npos) << e.what();
    }
  }
  const auto range = gearkit::io::magnitude_range(Quantity::length);
  EXPECT_EQ(range.si_unit, "m");
  EXPECT_LT(range.largest * range.largest / range.smallest, 1e300);  // products stay finite
}
