#include <gearkit/io/quantity.hpp>

#include <gearkit/io/error.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace gearkit::io {

QuantityError::~QuantityError() = default;

namespace {

// Runtime dimension: exponents of length, mass, time and plane angle. The angle is tracked so
// that "20 deg" is refused where a length is expected, but a unit without an angle (N*m, 1/s)
// is accepted where one is expected, since the radian is dimensionless in SI.
struct Dim {
  int L = 0, M = 0, T = 0, A = 0;
  Dim operator+(const Dim& o) const { return {L + o.L, M + o.M, T + o.T, A + o.A}; }
  Dim operator*(int k) const { return {L * k, M * k, T * k, A * k}; }
  bool same_LMT(const Dim& o) const { return L == o.L && M == o.M && T == o.T; }
};

struct UnitDef {
  std::string_view symbol;
  double factor;  // to SI
  Dim dim;
};

constexpr double pi = std::numbers::pi;
constexpr double kMetre = 1.0;
constexpr double kDegree = pi / 180.0;

constexpr Dim kLength{1, 0, 0, 0}, kMassD{0, 1, 0, 0}, kTimeD{0, 0, 1, 0}, kAngleD{0, 0, 0, 1};
constexpr Dim kForceD{1, 1, -2, 0}, kEnergyD{2, 1, -2, 0}, kPowerD{2, 1, -3, 0}, kPressureD{-1, 1, -2, 0};
constexpr Dim kNone{0, 0, 0, 0};

const std::array kUnits = {
    UnitDef{"m", kMetre, kLength},
    UnitDef{"mm", 1e-3 * kMetre, kLength},
    UnitDef{"cm", 1e-2 * kMetre, kLength},
    UnitDef{"km", 1e3 * kMetre, kLength},
    UnitDef{"um", 1e-6 * kMetre, kLength},
    UnitDef{"µm", 1e-6 * kMetre, kLength},       // U+00B5 MICRO SIGN
    UnitDef{"\u03bcm", 1e-6 * kMetre, kLength},  // U+03BC GREEK SMALL LETTER MU, which fonts draw the same
    UnitDef{"in", 0.0254, kLength},
    UnitDef{"ft", 0.3048, kLength},
    UnitDef{"rad", 1.0, kAngleD},
    UnitDef{"deg", kDegree, kAngleD},
    UnitDef{"°", kDegree, kAngleD},
    UnitDef{"rev", 2 * pi, kAngleD},
    UnitDef{"r", 2 * pi, kAngleD},  // revolution, as in r/min (ISO 80000-3 writes n in r/min too)
    UnitDef{"turn", 2 * pi, kAngleD},
    UnitDef{"s", 1.0, kTimeD},
    UnitDef{"ms", 1e-3, kTimeD},
    UnitDef{"min", 60.0, kTimeD},
    UnitDef{"h", 3600.0, kTimeD},
    UnitDef{"kg", 1.0, kMassD},
    UnitDef{"g", 1e-3, kMassD},
    UnitDef{"t", 1e3, kMassD},
    UnitDef{"N", 1.0, kForceD},
    UnitDef{"kN", 1e3, kForceD},
    UnitDef{"MN", 1e6, kForceD},
    UnitDef{"lbf", 4.4482216152605, kForceD},  // pound-force (US customary gear data: lbf*in, lbf)
    UnitDef{"J", 1.0, kEnergyD},
    UnitDef{"kJ", 1e3, kEnergyD},
    UnitDef{"MJ", 1e6, kEnergyD},
    UnitDef{"Wh", 3600.0, kEnergyD},
    UnitDef{"kWh", 3.6e6, kEnergyD},
    UnitDef{"W", 1.0, kPowerD},
    UnitDef{"kW", 1e3, kPowerD},
    UnitDef{"MW", 1e6, kPowerD},
    UnitDef{"hp", 745.69987158227022, kPowerD},  // mechanical horsepower
    UnitDef{"CV", 735.49875, kPowerD},           // metric horsepower (caballo de vapor)
    UnitDef{"Pa", 1.0, kPressureD},
    UnitDef{"kPa", 1e3, kPressureD},
    UnitDef{"MPa", 1e6, kPressureD},
    UnitDef{"GPa", 1e9, kPressureD},
    UnitDef{"bar", 1e5, kPressureD},
    UnitDef{"rpm", 2 * pi / 60.0, Dim{0, 0, -1, 1}},
    UnitDef{"rps", 2 * pi, Dim{0, 0, -1, 1}},
};

Dim dimension_of(Quantity q) {
  switch (q) {
    case Quantity::dimensionless: return kNone;
    case Quantity::length: return kLength;
    case Quantity::angle: return kAngleD;
    case Quantity::time: return kTimeD;
    case Quantity::mass: return kMassD;
    case Quantity::force: return kForceD;
    case Quantity::torque: return kEnergyD;
    case Quantity::energy: return kEnergyD;
    case Quantity::power: return kPowerD;
    case Quantity::velocity: return {1, 0, -1, 0};
    case Quantity::acceleration: return {1, 0, -2, 0};
    case Quantity::angular_velocity: return {0, 0, -1, 1};
    case Quantity::angular_acceleration: return {0, 0, -2, 1};
    case Quantity::moment_of_inertia: return {2, 1, 0, 0};
    case Quantity::stiffness: return {0, 1, -2, 0};
    case Quantity::pressure: return kPressureD;
    case Quantity::damping: return {0, 1, -1, 0};
    case Quantity::torsional_stiffness: return {2, 1, -2, -1};
    case Quantity::torsional_damping: return {2, 1, -1, -1};
  }
  return kNone;
}

bool compatible(const Dim& found, const Dim& expected) {
  if (!found.same_LMT(expected)) return false;
  return found.A == 0 || found.A == expected.A;
}

std::string quoted(std::string_view s) { return quote(s); }

bool is_space(char c) { return c == ' ' || c == '\t'; }

/// `text` with the spaces word processors put between a number and its unit (U+00A0 no-break,
/// U+202F narrow no-break, U+2009 thin) made plain spaces: they look the same, so a message that
/// refused them would show a space as the culprit.
std::string plain_spaces(std::string_view text) {
  static constexpr std::array<std::string_view, 3> kSpaces{"\u00a0", "\u202f", "\u2009"};
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const auto match =
        std::find_if(kSpaces.begin(), kSpaces.end(), [&](std::string_view sp) { return text.substr(i, sp.size()) == sp; });
    if (match != kSpaces.end()) {
      out += ' ';
      i += match->size();
    } else {
      out += text[i++];
    }
  }
  return out;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

const UnitDef* find_unit(std::string_view symbol) {
  for (const auto& u : kUnits)
    if (u.symbol == symbol) return &u;
  return nullptr;
}

struct ParsedUnit {
  double factor = 1.0;
  Dim dim;
};

// The typographic spellings of printed tables and course notes, mapped to the ASCII grammar:
// the middle dot and the dot operator are products (N·m), superscript digits and the
// superscript minus are exponents (min⁻¹, kg·m²).
std::string ascii_unit(std::string_view text) {
  struct Spelling {
    std::string_view utf8, ascii;
  };
  static constexpr std::array<Spelling, 14> kSpellings{{
      {"\u00b7", "*"}, {"\u22c5", "*"}, {"\u207b", "-"}, {"\u2070", "0"}, {"\u00b9", "1"},
      {"\u00b2", "2"}, {"\u00b3", "3"}, {"\u2074", "4"}, {"\u2075", "5"}, {"\u2076", "6"},
      {"\u2077", "7"}, {"\u2078", "8"}, {"\u2079", "9"}, {"\u00d7", "*"},
  }};
  std::string out;
  bool in_superscript = false;
  for (std::size_t i = 0; i < text.size();) {
    const Spelling* match = nullptr;
    for (const auto& sp : kSpellings)
      if (text.substr(i, sp.utf8.size()) == sp.utf8) match = &sp;
    const bool superscript = match && match->ascii != "*";
    if (superscript && !in_superscript) out += '^';
    in_superscript = superscript;
    if (match) {
      out += match->ascii;
      i += match->utf8.size();
    } else {
      out += text[i++];
    }
  }
  return out;
}

// ISO 80000-3 (items 3-17 and 3-18): a rotational speed written without an angle, n in min^-1
// or s^-1, counts revolutions; only rad/s (or deg/s, rpm...) names an angle per time. So where an
// angular velocity is expected, a unit whose angle exponent is 0 is read as revolutions per that
// time: 1020 min^-1 = 1020 r/min = 106.8 rad/s, 10 1/s = 10 r/s = 62.8 rad/s.
double rotational_frequency_factor(const ParsedUnit& u, Quantity expected) {
  return expected == Quantity::angular_velocity && u.dim.A == 0 ? 2 * pi : 1.0;
}

// UNIT = FACTOR (('*' | '/') FACTOR)*, FACTOR = SYMBOL ['^' INTEGER] | '1'
ParsedUnit parse_unit(std::string_view text, std::string_view whole) {
  ParsedUnit result;
  std::size_t i = 0;
  int sign = +1;
  bool expect_factor = true;
  while (i < text.size()) {
    if (!expect_factor) {
      char op = text[i];
      if (op == '*' || op == '/') {
        sign = op == '*' ? +1 : -1;
        ++i;
        expect_factor = true;
        continue;
      }
      throw QuantityError(fmt::format("expected '*' or '/' between units, found {} in {}",
                                      quoted(text.substr(i, 1)), quoted(whole)));
    }
    // A symbol: letters, the degree sign or micro sign (UTF-8 bytes), or the digit 1 (as in 1/s).
    std::size_t start = i;
    if (text[i] == '1') {
      ++i;
    } else {
      while (i < text.size() && (std::isalpha(static_cast<unsigned char>(text[i])) ||
                                 static_cast<unsigned char>(text[i]) >= 0x80)) {
        ++i;
      }
    }
    std::string_view symbol = text.substr(start, i - start);
    if (symbol.empty())
      throw QuantityError(fmt::format("expected a unit symbol, found {} in {}",
                                      quoted(text.substr(i, 1)), quoted(whole)));
    int power = 1;
    if (i < text.size() && text[i] == '^') {
      ++i;
      std::size_t pstart = i;
      if (i < text.size() && (text[i] == '-' || text[i] == '+')) ++i;
      while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
      std::string_view ptext = text.substr(pstart, i - pstart);
      if (ptext.empty() || ptext == "-" || ptext == "+")
        throw QuantityError(fmt::format("expected an integer exponent after '^' in {}", quoted(whole)));
      std::from_chars(ptext.data() + (ptext[0] == '+' ? 1 : 0), ptext.data() + ptext.size(), power);
      if (std::abs(power) > 4)
        throw QuantityError(fmt::format("expected an exponent from -4 to 4, found {} in {}", ptext,
                                        quoted(whole)));
    }
    if (symbol == "1") {
      if (power != 1) throw QuantityError(fmt::format("expected a unit symbol, found '1^' in {}", quoted(whole)));
    } else {
      const UnitDef* u = find_unit(symbol);
      if (!u) throw QuantityError(fmt::format("unknown unit {} in {}", quoted(symbol), quoted(whole)));
      result.factor *= std::pow(u->factor, sign * power);
      result.dim = result.dim + u->dim * (sign * power);
    }
    expect_factor = false;
  }
  if (expect_factor && !text.empty())
    throw QuantityError(fmt::format("expected a unit after '{}' in {}", text.back(), quoted(whole)));
  return result;
}

// The number at the start of `text`: optional sign, digits, fraction, exponent. Returns the
// characters consumed, 0 if there is no number.
std::size_t scan_number(std::string_view text) {
  std::size_t i = 0;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  std::size_t digits = 0;
  while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i, ++digits;
  if (i < text.size() && text[i] == '.') {
    ++i;
    while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i, ++digits;
  }
  if (digits == 0) return 0;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    std::size_t j = i + 1;
    if (j < text.size() && (text[j] == '+' || text[j] == '-')) ++j;
    std::size_t exp_digits = 0;
    while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j]))) ++j, ++exp_digits;
    if (exp_digits > 0) i = j;
  }
  return i;
}

}  // namespace

std::string_view describe(Quantity q) {
  switch (q) {
    case Quantity::dimensionless: return "a plain number";
    case Quantity::length: return "a length";
    case Quantity::angle: return "an angle";
    case Quantity::time: return "a time";
    case Quantity::mass: return "a mass";
    case Quantity::force: return "a force";
    case Quantity::torque: return "a torque";
    case Quantity::energy: return "an energy";
    case Quantity::power: return "a power";
    case Quantity::velocity: return "a velocity";
    case Quantity::acceleration: return "an acceleration";
    case Quantity::angular_velocity: return "an angular velocity";
    case Quantity::angular_acceleration: return "an angular acceleration";
    case Quantity::moment_of_inertia: return "a moment of inertia";
    case Quantity::stiffness: return "a stiffness";
    case Quantity::pressure: return "a pressure";
    case Quantity::damping: return "a damping coefficient";
    case Quantity::torsional_stiffness: return "a torsional stiffness";
    case Quantity::torsional_damping: return "a torsional damping coefficient";
  }
  return "a quantity";
}

MagnitudeRange magnitude_range(Quantity q) {
  // Far beyond any machine (a 10 km part, 1e8 rpm, 1 TW) yet far inside double's range, so that
  // products and quotients of accepted values stay finite; the floor keeps 1/x finite too.
  constexpr double kFloor = 1e-15;
  switch (q) {
    case Quantity::dimensionless: return {kFloor, 1e9, ""};
    case Quantity::length: return {kFloor, 1e4, "m"};
    case Quantity::angle: return {kFloor, 1e7, "rad"};
    case Quantity::time: return {kFloor, 1e10, "s"};  // a gear life of 1e6 h is 3.6e9 s
    case Quantity::mass: return {kFloor, 1e8, "kg"};
    case Quantity::force: return {kFloor, 1e12, "N"};
    case Quantity::torque: return {kFloor, 1e12, "N*m"};
    case Quantity::energy: return {kFloor, 1e15, "J"};
    case Quantity::power: return {kFloor, 1e12, "W"};
    case Quantity::velocity: return {kFloor, 1e5, "m/s"};
    case Quantity::acceleration: return {kFloor, 1e9, "m/s^2"};
    case Quantity::angular_velocity: return {kFloor, 1e7, "rad/s"};
    case Quantity::angular_acceleration: return {kFloor, 1e10, "rad/s^2"};
    case Quantity::moment_of_inertia: return {kFloor, 1e10, "kg*m^2"};
    case Quantity::stiffness: return {kFloor, 1e13, "N/m"};
    case Quantity::pressure: return {kFloor, 1e13, "Pa"};
    case Quantity::damping: return {kFloor, 1e12, "N*s/m"};
    case Quantity::torsional_stiffness: return {kFloor, 1e12, "N*m/rad"};
    case Quantity::torsional_damping: return {kFloor, 1e12, "N*m*s/rad"};
  }
  return {kFloor, 1e9, ""};
}

double unit_factor_si(std::string_view given_unit, Quantity expected) {
  const std::string plain = plain_spaces(given_unit);
  const std::string_view unit = plain;
  const std::string ascii = ascii_unit(trim(unit));
  ParsedUnit u = parse_unit(ascii, unit);
  if (!compatible(u.dim, dimension_of(expected)))
    throw QuantityError(fmt::format("expected {}, found unit {}", describe(expected), quoted(trim(unit))));
  return u.factor * rotational_frequency_factor(u, expected);
}

namespace {

/// The SI value of `text` and the number as typed (before its unit).
std::pair<double, double> parse_si_and_number(std::string_view given, Quantity expected, std::string_view default_unit) {
  const std::string plain = plain_spaces(given);
  std::string_view t = trim(plain);
  if (t.empty()) throw QuantityError(fmt::format("expected {}, found an empty value", describe(expected)));
  std::size_t n = scan_number(t);
  if (n == 0)
    throw QuantityError(fmt::format("expected {} such as '{}', found {}", describe(expected),
                                    default_unit.empty() ? "1.5" : fmt::format("12 {}", default_unit),
                                    quoted(t)));
  std::string number(t.substr(0, n));
  std::string_view rest = trim(t.substr(n));
  if (!rest.empty() && rest.front() == ',')
    throw QuantityError(fmt::format("expected a decimal point, found a comma in {}", quoted(t)));
  if (!rest.empty() && (rest.front() == 'x' || rest.front() == 'X') && number == "0")
    throw QuantityError(fmt::format("expected a decimal number, found {}", quoted(t)));
  errno = 0;
  char* end = nullptr;
  double value = std::strtod(number.c_str(), &end);
  // ERANGE also flags an underflow to a subnormal or zero: the range check below refuses those.
  if (!std::isfinite(value) || (errno == ERANGE && std::abs(value) >= 1.0))
    throw QuantityError(fmt::format("expected a finite number, found {}", quoted(t)));
  if (errno == ERANGE && value == 0.0 && number.find_first_of("123456789") != std::string::npos)
    value = std::numeric_limits<double>::denorm_min();  // "1e-400" is not 0: let the range refuse it
  double factor = 1.0;
  if (rest.empty()) {
    // A bare power was kW in gear pair files and W in dyn models and options: no bare-number
    // unit of power is obvious, so a power needs its unit wherever it is read (docs/units.md).
    if (expected == Quantity::power)
      throw QuantityError(fmt::format("expected {} with its unit ({}), found {}", describe(expected),
                                      unit_examples(expected), quoted(t)));
    if (!default_unit.empty()) factor = unit_factor_si(default_unit, expected);
  } else {
    const std::string ascii = ascii_unit(rest);
    ParsedUnit u = parse_unit(ascii, t);
    if (!compatible(u.dim, dimension_of(expected)))
      throw QuantityError(fmt::format("expected {}, found {} (unit {})", describe(expected), quoted(t), quoted(rest)));
    factor = u.factor * rotational_frequency_factor(u, expected);
  }
  double si_value = value * factor;
  if (!std::isfinite(si_value))
    throw QuantityError(fmt::format("expected a finite number, found {}", quoted(t)));
  return {si_value, value};
}

}  // namespace

double parse_quantity_si_any_size(std::string_view text, Quantity expected, std::string_view default_unit) {
  return parse_si_and_number(text, expected, default_unit).first;
}

double parse_quantity_si(std::string_view text, Quantity expected, std::string_view default_unit) {
  const auto [si_value, value] = parse_si_and_number(text, expected, default_unit);
  const std::string plain = plain_spaces(text);
  const std::string_view t = trim(plain);
  const MagnitudeRange range = magnitude_range(expected);
  // A non-zero number that underflows to 0 in SI is as much out of range as one that is tiny.
  const double size = si_value == 0.0 && value != 0.0 ? std::numeric_limits<double>::denorm_min() : std::abs(si_value);
  if (size > range.largest || (size > 0.0 && size < range.smallest))
    throw QuantityError(fmt::format("expected {} of size 0 or between {:g} and {:g}{}{}, found {}", describe(expected),
                                    range.smallest, range.largest, range.si_unit.empty() ? "" : " ",
                                    range.si_unit, quoted(t)));
  return si_value;
}

bool option_needs_unit(Quantity q) {
  return q == Quantity::power || q == Quantity::torque || q == Quantity::angular_velocity || q == Quantity::velocity;
}

std::string_view unit_examples(Quantity q) {
  switch (q) {
    case Quantity::power: return "7.5kW, 7500 W";
    case Quantity::torque: return "36.6 N*m, 0.5 kN*m";
    case Quantity::angular_velocity: return "1450rpm, 152 rad/s";
    case Quantity::velocity: return "200 mm/min, 0.5 m/s";
    default: return "";
  }
}

namespace {

/// Refuses a bare number for a quantity that option_needs_unit.
void check_option_unit(std::string_view text, Quantity expected) {
  if (!option_needs_unit(expected)) return;
  const std::string_view t = trim(text);
  const std::size_t n = scan_number(t);
  if (n > 0 && n == t.size())
    throw QuantityError(fmt::format("expected {} with its unit ({}), found {}", describe(expected), unit_examples(expected),
                                    quoted(t)));
}

}  // namespace

double parse_option_quantity_si(std::string_view text, Quantity expected, std::string_view default_unit) {
  check_option_unit(text, expected);
  return parse_quantity_si(text, expected, default_unit);
}

double parse_option_quantity_si_any_size(std::string_view text, Quantity expected, std::string_view default_unit) {
  check_option_unit(text, expected);
  return parse_quantity_si_any_size(text, expected, default_unit);
}

}  // namespace gearkit::io
