#include "gear_options.hpp"

#include <gearkit/io/command_line.hpp>
#include <gearkit/io/error.hpp>
#include <gearkit/io/quantity.hpp>

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <map>
#include <numbers>

namespace gearkit::plugins::gear {

namespace gg = gearkit::gear;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

[[noreturn]] void fail(std::string_view key, std::string_view message) {
  io::fail_option(fmt::format("--{}", key), message);
}

bool given(const io::po::variables_map& vm, const char* key) { return vm.count(key) > 0; }

std::string text_of(const io::po::variables_map& vm, const char* key) { return vm[key].as<std::string>(); }

// A required option is asked for where it is read, so that a bad value of an earlier one is
// reported before a missing later one (`--z1 x` alone is about --z1, not a missing --z2).
void require(const io::po::variables_map& vm, const char* key, std::string_view what) {
  if (!given(vm, key)) fail(key, fmt::format("expected {}, found none (or give a gear-pair file)", what));
}

int teeth(const io::po::variables_map& vm, const char* key) {
  const std::string s = text_of(vm, key);
  int value = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (s.empty() || ec != std::errc() || end != s.data() + s.size()) {
    fail(key, fmt::format("expected a whole number of teeth, found {}", io::quote(s)));
  }
  if (value <= 0) fail(key, fmt::format("expected a number of teeth >= 1, found {}", value));
  if (value > 100000) fail(key, fmt::format("expected at most 100000 teeth, found {}", value));
  return value;
}

double quantity(const io::po::variables_map& vm, const char* key, io::Quantity q, const char* unit, double scale) {
  const std::string s = text_of(vm, key);
  try {
    return io::parse_quantity_si(s, q, unit) * scale;
  } catch (const io::QuantityError& e) {
    fail(key, e.what());
  }
}

double length_mm(const io::po::variables_map& vm, const char* key) {
  return quantity(vm, key, io::Quantity::length, "mm", 1000.0);
}

double angle_rad(const io::po::variables_map& vm, const char* key) { return quantity(vm, key, io::Quantity::angle, "deg", 1.0); }

double number(const io::po::variables_map& vm, const char* key) {
  return quantity(vm, key, io::Quantity::dimensionless, "", 1.0);
}

void exclusive(const io::po::variables_map& vm, const char* a, const char* b, std::string_view why) {
  if (given(vm, a) && given(vm, b)) fail(b, fmt::format("cannot be combined with --{}: {}", a, why));
}

}  // namespace

void add_gear_options(io::po::options_description& desc) {
  namespace po = io::po;
  desc.add_options()
      ("z1", po::value<std::string>()->value_name("N"), "teeth of gear 1 (pinion)")
      ("z2", po::value<std::string>()->value_name("N"), "teeth of gear 2 (wheel, or ring with --internal)")
      ("ratio", po::value<std::string>()->value_name("U"),
       "gear ratio u = z2/z1 (4 for a reduction 1/4): with --z1 or --z2 it gives the other; with neither, the teeth of "
       "the unshifted pair that fits --centre-distance")
      ("module", po::value<std::string>()->value_name("LEN"), "module (normal; transverse with --transverse) (bare number: mm)")
      ("pressure-angle", po::value<std::string>()->value_name("ANGLE"), "pressure angle (default 20 deg) (bare number: deg)")
      ("helix-angle", po::value<std::string>()->value_name("ANGLE"), "helix angle (default 0: spur) (bare number: deg)")
      ("x1", po::value<std::string>()->value_name("X"), "profile shift coefficient of gear 1 (default 0)")
      ("x2", po::value<std::string>()->value_name("X"), "profile shift coefficient of gear 2 (default 0; ISO sign for a ring)")
      ("centre-distance", po::value<std::string>()->value_name("LEN"),
       "working centre distance: the shift sum follows from it (with --x1: x2 = sum - x1) (bare number: mm)")
      ("split", po::value<std::string>()->value_name("balanced|proportional|min-shift|user"),
       "split of the shift sum with --centre-distance (default balanced specific sliding; min-shift: the smallest "
       "shifts free of undercut; user with --x1)")
      ("undercut-limit", po::value<std::string>()->value_name("iso|practical"),
       "the undercut limit --split min-shift keeps: ISO x_min (default) or the practical (14 - z)/17 of DIN 3960 and "
       "course notes")
      ("radii", po::bool_switch(), "print the gear table in radii (r, r_w, r_b, r_a, r_f), as course notes do")
      ("internal", po::bool_switch(), "gear 2 is an internal gear (ring); z2 > z1")
      ("transverse", po::bool_switch(), "module and pressure angle are given in the transverse section")
      ("no-tip-shortening", po::bool_switch(), "keep d_a = d + 2 m (h_aP + x) even when k > 0")
      ("addendum", po::value<std::string>()->value_name("COEF"), "rack addendum coefficient h_aP* (default 1)")
      ("dedendum", po::value<std::string>()->value_name("COEF"), "rack dedendum coefficient h_fP* (default 1.25)")
      ("root-radius", po::value<std::string>()->value_name("COEF"), "rack root radius coefficient rho_fP* (default 0.38)")
      ("rack1", po::value<std::string>()->value_name("H_aP,H_fP,RHO_fP"),
       "the tool of gear 1 when it differs from gear 2's: rack coefficients h_aP*,h_fP*,rho_fP* (default --addendum, "
       "--dedendum, --root-radius)")
      ("rack2", po::value<std::string>()->value_name("H_aP,H_fP,RHO_fP"), "the tool of gear 2 (as --rack1)")
      ("tip-diameter1", po::value<std::string>()->value_name("LEN"), "tip diameter d_a1 as made (default from the rack) (bare number: mm)")
      ("tip-diameter2", po::value<std::string>()->value_name("LEN"), "tip diameter d_a2 as made, a ring's its magnitude (bare number: mm)")
      ("root-diameter1", po::value<std::string>()->value_name("LEN"), "root diameter d_f1 as made, a warning if the tool cuts another (bare number: mm)")
      ("root-diameter2", po::value<std::string>()->value_name("LEN"), "root diameter d_f2 as made (bare number: mm)")
      ("face-width", po::value<std::string>()->value_name("LEN"), "face width b (overlap ratio) (bare number: mm)")
      ("face-width1", po::value<std::string>()->value_name("LEN"), "face width of gear 1 when the widths differ (default --face-width) (bare number: mm)")
      ("face-width2", po::value<std::string>()->value_name("LEN"), "face width of gear 2 (default --face-width) (bare number: mm)")
      ("face-offset", po::value<std::string>()->value_name("LEN"), "axial offset of the middle of gear 2's face from gear 1's (default 0) (bare number: mm)")
      ("backlash", po::value<std::string>()->value_name("LEN"), "target normal backlash j_bn: sets equal thickness allowances (bare number: mm)")
      ("allowance1", po::value<std::string>()->value_name("LEN"), "normal tooth thickness allowance A_sn1 (negative: thinner) (bare number: mm)")
      ("allowance2", po::value<std::string>()->value_name("LEN"), "normal tooth thickness allowance A_sn2 (negative: thinner) (bare number: mm)")
      ("centre-distance-deviation", po::value<std::string>()->value_name("LEN"), "centre distance deviation A_a (bare number: mm)")
      ("pin-diameter", po::value<std::string>()->value_name("LEN"), "pin/ball diameter for both gears (bare number: mm)")
      ("pin-diameter1", po::value<std::string>()->value_name("LEN"), "pin/ball diameter for gear 1 (bare number: mm)")
      ("pin-diameter2", po::value<std::string>()->value_name("LEN"), "pin/ball diameter for gear 2 (bare number: mm)")
      ("svg", po::value<std::string>()->value_name("FILE"), "write the drawing as SVG")
      ("dxf", po::value<std::string>()->value_name("FILE"), "write the drawing as DXF (R2000, drawn in mm)")
      ("draw", po::value<std::string>()->value_name("pair|gear1|gear2"), "what --svg/--dxf draw (default pair)")
      ("tolerance", po::value<std::string>()->value_name("LEN"), "largest distance of the drawn tooth outline from the generated form (default 1um; 0.1um..1mm) (bare number: mm)")
      ("cutter-teeth", po::value<std::string>()->value_name("N"), "teeth of the shaper cutter that cuts the ring (default: about 100 mm diameter)")
      ("cutter-tip-radius", po::value<std::string>()->value_name("LEN"), "tip rounding radius of the ring's shaper cutter (default rho_fP* m_n, or 3/4 of the largest that fits) (bare number: mm)");
}

namespace {

// A whole number of teeth from a computed value, or an error naming --ratio.
int whole_teeth(double value, std::string_view what) {
  const double rounded = std::round(value);
  if (!(std::fabs(value - rounded) <= 1e-6 * std::max(1.0, std::fabs(value))) || rounded < 1.0 || rounded > 100000.0)
    fail("ratio", fmt::format("{} = {:.6g} is not a whole number of teeth", what, value));
  return static_cast<int>(rounded);
}

// --ratio: the tooth numbers the course derives from the ratio (and the centre distance).
// Returns true when they come from the centre distance (an unshifted pair at exactly it).
bool teeth_from_ratio(const io::po::variables_map& vm, gg::GearPairInput& in) {
  const double u = number(vm, "ratio");
  if (!(u > 0.0 && std::isfinite(u))) fail("ratio", fmt::format("expected a ratio z2/z1 > 0, found {}", u));
  if (given(vm, "z1") && given(vm, "z2")) fail("ratio", "contradicts --z1 with --z2 (the ratio follows from them)");
  if (given(vm, "z1")) {
    in.z1 = teeth(vm, "z1");
    in.z2 = whole_teeth(u * in.z1, "z2 = u z1");
    return false;
  }
  if (given(vm, "z2")) {
    in.z2 = teeth(vm, "z2");
    in.z1 = whole_teeth(in.z2 / u, "z1 = z2 / u");
    return false;
  }
  if (!given(vm, "centre-distance")) fail("ratio", "needs --z1, --z2 or --centre-distance to fix the tooth numbers");
  for (const char* key : {"x1", "x2", "split"})
    if (given(vm, key)) fail(key, "cannot be combined with --ratio without tooth numbers: the pair found is unshifted");
  const double a = length_mm(vm, "centre-distance");
  const double beta = given(vm, "helix-angle") ? angle_rad(vm, "helix-angle") : 0.0;
  const bool transverse = vm["transverse"].as<bool>();
  const double sum = transverse ? 2.0 * a / in.module : gg::teeth_sum_for_centre_distance(a, in.module, beta);
  const int total = whole_teeth(sum, "z1 + z2 = 2 a cos(beta) / m");
  in.z1 = whole_teeth(total / (1.0 + u), "z1 = (z1 + z2) / (1 + u)");
  in.z2 = total - in.z1;
  return true;
}

void read_module(const io::po::variables_map& vm, gg::GearPairInput& in) {
  require(vm, "module", "the module");
  in.module = length_mm(vm, "module");
  if (!(in.module > 0.0)) fail("module", fmt::format("expected a module > 0 mm, found {} mm", in.module));
}

void read_teeth_and_module(const io::po::variables_map& vm, gg::GearPairInput& in) {
  if (given(vm, "ratio")) {
    read_module(vm, in);  // the tooth numbers follow from the ratio and the module
    if (vm["internal"].as<bool>()) fail("ratio", "applies to external pairs only");
    if (teeth_from_ratio(vm, in)) in.centre_distance.reset();  // a = a_d: unshifted, zero mounting
  } else {
    require(vm, "z1", "the teeth of gear 1 (or --ratio)");
    in.z1 = teeth(vm, "z1");
    require(vm, "z2", "the teeth of gear 2 (or --ratio)");
    in.z2 = teeth(vm, "z2");
  }
  in.internal = vm["internal"].as<bool>();
  in.system = vm["transverse"].as<bool>() ? gg::ModuleSystem::transverse : gg::ModuleSystem::normal;
  in.apply_tip_shortening = !vm["no-tip-shortening"].as<bool>();
  if (in.internal && in.z2 <= in.z1) {
    fail("z2", fmt::format("an internal gear (ring) needs more teeth than its pinion: expected z2 > {}, found {}",
                                      in.z1, in.z2));
  }
  if (!given(vm, "ratio")) read_module(vm, in);
  if (given(vm, "pressure-angle")) {
    in.pressure_angle = angle_rad(vm, "pressure-angle");
    if (!(in.pressure_angle > 0.0 && in.pressure_angle < 45.0 * kDeg)) {
      fail("pressure-angle", fmt::format("expected an angle in (0, 45) deg, found {} deg", in.pressure_angle / kDeg));
    }
  }
  if (given(vm, "helix-angle")) {
    in.helix_angle = angle_rad(vm, "helix-angle");
    if (!(std::fabs(in.helix_angle) < 45.0 * kDeg)) {
      fail("helix-angle", fmt::format("expected an angle in (-45, 45) deg, found {} deg", in.helix_angle / kDeg));
    }
  }
}

void read_rack(const io::po::variables_map& vm, gg::GearPairInput& in) {
  if (given(vm, "addendum")) in.h_aP = number(vm, "addendum");
  if (given(vm, "dedendum")) in.h_fP = number(vm, "dedendum");
  if (given(vm, "root-radius")) in.rho_fP = number(vm, "root-radius");
  if (!(in.h_aP > 0.0)) fail("addendum", fmt::format("expected a coefficient > 0, found {}", in.h_aP));
  if (!(in.h_fP >= in.h_aP)) {
    fail("dedendum", fmt::format("expected a coefficient >= the addendum coefficient {}, found {}", in.h_aP, in.h_fP));
  }
  if (!(in.rho_fP >= 0.0)) fail("root-radius", fmt::format("expected a coefficient >= 0, found {}", in.rho_fP));
  for (int i = 0; i < 2; ++i) {
    const char* key = i == 0 ? "rack1" : "rack2";
    if (!given(vm, key)) continue;
    const std::string text = text_of(vm, key);
    double c[3] = {0, 0, 0};
    std::size_t start = 0;
    for (int k = 0; k < 3; ++k) {
      const std::size_t comma = text.find(',', start);
      if ((k < 2) == (comma == std::string::npos)) fail(key, fmt::format("expected H_aP,H_fP,RHO_fP (e.g. 1,1.25,0.38), found {}", io::quote(text)));
      const std::string part = text.substr(start, k < 2 ? comma - start : std::string::npos);
      try {
        c[k] = io::parse_quantity_si(part, io::Quantity::dimensionless, "");
      } catch (const io::QuantityError& e) {
        fail(key, e.what());
      }
      start = comma + 1;
    }
    if (!(c[0] > 0.0 && c[1] >= c[0] && c[2] >= 0.0)) {
      fail(key, fmt::format("expected h_aP* > 0, h_fP* >= h_aP*, rho_fP* >= 0, found {}", io::quote(text)));
    }
    in.tool[i] = gg::Rack{in.pressure_angle, c[0], c[1], c[2]};
  }
  for (int i = 0; i < 2; ++i) {
    for (const char* key : {i == 0 ? "tip-diameter1" : "tip-diameter2", i == 0 ? "root-diameter1" : "root-diameter2"}) {
      if (!given(vm, key)) continue;
      const double d = length_mm(vm, key);
      if (!(d > 0.0)) fail(key, fmt::format("expected a diameter > 0 mm, found {} mm", d));
      (std::string_view(key).starts_with("tip") ? in.d_a : in.d_f)[i] = d;
    }
  }
}

void read_shift(const io::po::variables_map& vm, gg::GearPairInput& in) {
  exclusive(vm, "centre-distance", "x2", "x2 follows from the centre distance (give --x1 to fix the split)");
  if (given(vm, "x1")) in.x1 = number(vm, "x1");
  if (given(vm, "x2")) in.x2 = number(vm, "x2");
  if (given(vm, "centre-distance")) {
    in.centre_distance = length_mm(vm, "centre-distance");
    if (!(*in.centre_distance > 0.0)) {
      fail("centre-distance", fmt::format("expected a centre distance > 0 mm, found {} mm", *in.centre_distance));
    }
    in.split = given(vm, "x1") ? gg::ShiftSplit::user_x1 : gg::ShiftSplit::balanced_sliding;
  }
  if (given(vm, "split")) {
    if (!in.centre_distance) fail("split", "only applies with --centre-distance");
    const std::string s = text_of(vm, "split");
    const std::map<std::string, gg::ShiftSplit> splits = {{"balanced", gg::ShiftSplit::balanced_sliding},
                                                          {"proportional", gg::ShiftSplit::proportional},
                                                          {"min-shift", gg::ShiftSplit::min_shift},
                                                          {"user", gg::ShiftSplit::user_x1}};
    const auto it = splits.find(s);
    if (it == splits.end()) fail("split", fmt::format("expected balanced, proportional, min-shift or user, found {}", io::quote(s)));
    if (given(vm, "x1") && it->second != gg::ShiftSplit::user_x1) {
      fail("split", fmt::format("'{}' contradicts --x1 (a given x1 means the user split)", s));
    }
    if (!given(vm, "x1") && it->second == gg::ShiftSplit::user_x1) fail("split", "'user' needs --x1");
    in.split = it->second;
  }
  if (given(vm, "undercut-limit")) {
    if (in.split != gg::ShiftSplit::min_shift) fail("undercut-limit", "only applies with --split min-shift");
    const std::string s = text_of(vm, "undercut-limit");
    if (s != "iso" && s != "practical") fail("undercut-limit", fmt::format("expected iso or practical, found {}", io::quote(s)));
    in.undercut_limit = s == "iso" ? gg::UndercutLimit::iso : gg::UndercutLimit::practical;
  }
}

void read_allowances(const io::po::variables_map& vm, gg::GearPairInput& in) {
  if (given(vm, "face-width")) {
    in.face_width = length_mm(vm, "face-width");
    if (!(in.face_width >= 0.0)) fail("face-width", fmt::format("expected a width >= 0 mm, found {} mm", in.face_width));
  }
  for (int i = 0; i < 2; ++i) {
    const char* key = i == 0 ? "face-width1" : "face-width2";
    if (!given(vm, key)) continue;
    in.face_widths[i] = length_mm(vm, key);
    if (!(*in.face_widths[i] >= 0.0)) fail(key, fmt::format("expected a width >= 0 mm, found {} mm", *in.face_widths[i]));
  }
  if (given(vm, "face-offset")) in.face_offset = length_mm(vm, "face-offset");
  exclusive(vm, "allowance1", "backlash", "the allowances follow from the target backlash");
  exclusive(vm, "allowance2", "backlash", "the allowances follow from the target backlash");
  if (given(vm, "backlash")) {
    in.backlash_target = length_mm(vm, "backlash");
    if (!(*in.backlash_target >= 0.0)) {
      fail("backlash", fmt::format("expected a backlash >= 0 mm, found {} mm", *in.backlash_target));
    }
  }
  if (given(vm, "allowance1")) in.A_sn1 = length_mm(vm, "allowance1");
  if (given(vm, "allowance2")) in.A_sn2 = length_mm(vm, "allowance2");
  if (given(vm, "centre-distance-deviation")) in.A_a = length_mm(vm, "centre-distance-deviation");
}

void read_pins(const io::po::variables_map& vm, gg::GearPairInput& in) {
  exclusive(vm, "pin-diameter", "pin-diameter1", "--pin-diameter already sets both gears");
  exclusive(vm, "pin-diameter", "pin-diameter2", "--pin-diameter already sets both gears");
  for (const char* key : {"pin-diameter", "pin-diameter1", "pin-diameter2"}) {
    if (!given(vm, key)) continue;
    const double D = length_mm(vm, key);
    if (!(D > 0.0)) fail(key, fmt::format("expected a diameter > 0 mm, found {} mm", D));
    const std::string k = key;
    if (k != "pin-diameter2") in.pin_diameter1 = D;
    if (k != "pin-diameter1") in.pin_diameter2 = D;
  }
}

void read_drawing(const io::po::variables_map& vm, GearCommandOptions& o) {
  o.radii = vm.count("radii") && vm["radii"].as<bool>();
  if (given(vm, "svg")) o.svg = text_of(vm, "svg");
  if (given(vm, "dxf")) o.dxf = text_of(vm, "dxf");
  if (given(vm, "draw")) {
    o.draw = text_of(vm, "draw");
    if (o.draw != "pair" && o.draw != "gear1" && o.draw != "gear2") {
      fail("draw", fmt::format("expected pair, gear1 or gear2, found {}", io::quote(o.draw)));
    }
    if (o.svg.empty() && o.dxf.empty()) fail("draw", "needs --svg or --dxf");
  }
  const io::OptionRange tolerance{1e-4 * (1.0 - 1e-9), 1.0, false, false, "a length from 0.1 um to 1 mm"};
  if (const auto t = io::quantity_option(vm, "tolerance", io::Quantity::length, "mm", tolerance)) o.tolerance = *t * 1e3;
  if (given(vm, "cutter-teeth")) o.cutter.z_0 = teeth(vm, "cutter-teeth");
  if (given(vm, "cutter-tip-radius")) {
    o.cutter.rho_a0 = length_mm(vm, "cutter-tip-radius");
    if (!(o.cutter.rho_a0 >= 0.0)) fail("cutter-tip-radius", fmt::format("expected a radius >= 0 mm, found {} mm", o.cutter.rho_a0));
  }
}

}  // namespace

GearCommandOptions read_gear_options(const io::po::variables_map& vm) {
  GearCommandOptions o;
  read_teeth_and_module(vm, o.input);
  read_rack(vm, o.input);
  const bool unshifted = given(vm, "ratio") && !given(vm, "z1") && !given(vm, "z2");
  if (!unshifted) read_shift(vm, o.input);
  read_allowances(vm, o.input);
  read_pins(vm, o.input);
  read_drawing(vm, o);
  return o;
}

void read_drawing_options(const io::po::variables_map& vm, GearCommandOptions& o) { read_drawing(vm, o); }

std::string option_for_field(const std::string& field) {
  static const std::map<std::string, std::string> options = {
      {"z1", "z1"}, {"z2", "z2"}, {"module", "module"}, {"pressure_angle", "pressure-angle"},
      {"helix_angle", "helix-angle"}, {"face_width", "face-width"}, {"x1", "x1"}, {"x2", "x2"},
      {"centre_distance", "centre-distance"}, {"backlash_target", "backlash"}, {"A_a", "centre-distance-deviation"},
      {"pin_diameter1", "pin-diameter1"}, {"pin_diameter2", "pin-diameter2"}, {"rack", "root-radius"},
      {"tool1", "rack1"}, {"tool2", "rack2"}, {"d_a1", "tip-diameter1"}, {"d_a2", "tip-diameter2"},
      {"d_f1", "root-diameter1"}, {"d_f2", "root-diameter2"}, {"face_width1", "face-width1"}, {"face_width2", "face-width2"},
      {"face_offset", "face-offset"}};
  const auto it = options.find(field);
  return it == options.end() ? field : it->second;
}

}  // namespace gearkit::plugins::gear
