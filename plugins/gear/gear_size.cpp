#include "gear_size.hpp"

#include "gear_rating_options.hpp"

#include <gearkit/gear/sizing.hpp>
#include <gearkit/io/command_line.hpp>
#include <gearkit/io/error.hpp>
#include <gearkit/io/quantity.hpp>

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <numbers>

namespace gearkit::plugins::gear {

namespace gg = gearkit::gear;

namespace {

constexpr std::string_view kUsage =
    "gearkit gear size --ratio U --torque1 TORQUE | --power POWER --speed1 SPEED --material1 M --material2 M [--quality 6] [--life 20000] "
    "[--ratio-tolerance 0.02] [--modules 2,2.5,3] [--z1-min 14] [--z1-max 40] [--shifts 0,0.2,0.4] [--helix-angle 0] "
    "[--pressure-angle 20] [--width-ratio-max 1] [--width-module-min 8] [--centre-distance A] [--hunting-tooth] [--count 5] "
    "[--format text|json|csv|md|html]";

[[noreturn]] void fail(std::string_view key, std::string_view message) { io::fail_option(fmt::format("--{}", key), message); }

double number(const std::string& key, std::string_view text) {
  double v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v)) {
    fail(key, fmt::format("expected a number, found '{}'", text.substr(0, 60)));
  }
  return v;
}

std::vector<double> list(const io::po::variables_map& vm, const char* key) {
  const std::string s = vm[key].as<std::string>();
  std::vector<double> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = s.find(',', start);
    out.push_back(number(key, std::string_view(s).substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (out.size() > 50) fail(key, fmt::format("expected at most 50 values, found {}", out.size()));
  return out;
}

double angle(const io::po::variables_map& vm, const char* key) {
  try {
    return io::parse_quantity_si(vm[key].as<std::string>(), io::Quantity::angle, "deg");
  } catch (const io::QuantityError& e) {
    fail(key, e.what());
  }
}

gg::SizingInput read_sizing(const io::po::variables_map& vm) {
  gg::SizingInput s;
  if (!vm.count("ratio")) fail("ratio", "is required: the gear ratio z2/z1");
  if (!rating_requested(vm)) fail("torque1", "the sizing needs the load: --torque1 or --power (with --speed1)");
  s.load = read_rating_options(vm);
  if (s.load.scuffing.fzg_stage) fail("fzg-stage", "gear size does not size for scuffing: rate the chosen pair with gearkit gear");
  if (!s.load.quality && std::isnan(s.load.f_pb)) s.load.quality = 6;
  s.ratio = number("ratio", vm["ratio"].as<std::string>());
  auto opt_number = [&](const char* key, double& field) {
    if (vm.count(key)) field = number(key, vm[key].as<std::string>());
  };
  auto opt_int = [&](const char* key, int& field) {
    if (!vm.count(key)) return;
    const double v = number(key, vm[key].as<std::string>());
    if (v != std::floor(v) || std::fabs(v) > 1e6) fail(key, fmt::format("expected a whole number, found {}", v));
    field = static_cast<int>(v);
  };
  opt_number("ratio-tolerance", s.ratio_tolerance);
  opt_number("width-ratio-max", s.width_ratio_max);
  opt_number("width-module-min", s.width_module_min);
  opt_int("z1-min", s.z1_min);
  opt_int("z1-max", s.z1_max);
  opt_int("count", s.count);
  if (vm.count("modules")) s.modules = list(vm, "modules");
  if (vm.count("shifts")) s.shifts = list(vm, "shifts");
  if (vm.count("helix-angle")) s.helix_angle = angle(vm, "helix-angle");
  if (vm.count("pressure-angle")) s.pressure_angle = angle(vm, "pressure-angle");
  if (vm.count("centre-distance")) {
    try {
      s.centre_distance = io::parse_quantity_si(vm["centre-distance"].as<std::string>(), io::Quantity::length, "mm") * 1000.0;
    } catch (const io::QuantityError& e) {
      fail("centre-distance", e.what());
    }
  }
  s.hunting_tooth = vm["hunting-tooth"].as<bool>();
  return s;
}

std::string accuracy_text(const gg::RatingInput& load) {
  return load.quality ? fmt::format("{} grade {}", gg::to_string(load.iso1328_edition), *load.quality) : std::string("deviations as given");
}

// Every design input, so that a table of candidates never travels without what it was sized for.
std::string sizing_heading(const gg::SizingInput& in) {
  constexpr double kDeg = 180.0 / std::numbers::pi;
  const gg::RatingInput& l = in.load;
  return fmt::format("Gear sizing: u = {:g} (+-{:g} %), T_1 = {:.1f} N m at {:g} 1/min, K_A = {:g}, alpha_n = {:g} deg, beta = {:g} deg, "
                     "{}, life {:g} h, {} / {}, {}, a = {}{}",
                     in.ratio, 100.0 * in.ratio_tolerance, l.T_1, l.n_1, l.K_A, in.pressure_angle * kDeg, in.helix_angle * kDeg,
                     accuracy_text(l), l.life_h, l.material[0].name, l.material[1].name, gg::to_string(l.method),
                     in.centre_distance ? fmt::format("{:g} mm", *in.centre_distance) : std::string("free (V-0)"),
                     in.hunting_tooth ? ", hunting-tooth pairs only (gcd(z1, z2) = 1)" : "");
}

io::Report sizing_report(const gg::SizingInput& in, const gg::SizingResult& r) {
  io::Report report;
  report.title = sizing_heading(in);
  io::Table t{"Smallest pairs that meet S_Hmin and S_F,min (by volume)",
              {"m_n [mm]", "z1", "z2", "u", "x1", "x2", "b [mm]", "a [mm]", "d1 [mm]", "S_H", "S_F", "volume [cm^3]"}, {}};
  nlohmann::json list = nlohmann::json::array();
  for (const auto& c : r.best) {
    t.add_row({io::fixed(c.m_n, 2), std::to_string(c.z1), std::to_string(c.z2), io::fixed(c.u, 4), io::fixed(c.x1, 2), io::fixed(c.x2, 2),
               io::fixed(c.b, 0), io::fixed(c.a, 3), io::fixed(c.d1, 3), io::fixed(c.S_H, 3), io::fixed(c.S_F, 3), io::fixed(c.volume / 1000.0, 1)});
    list.push_back({{"m_n_mm", c.m_n}, {"z1", c.z1}, {"z2", c.z2}, {"u", c.u}, {"x1", c.x1}, {"x2", c.x2}, {"b_mm", c.b},
                    {"a_mm", c.a}, {"d1_mm", c.d1}, {"d2_mm", c.d2}, {"S_H", c.S_H}, {"S_F", c.S_F}, {"volume_mm3", c.volume}});
  }
  report.tables.push_back(std::move(t));
  const std::string tried = in.centre_distance ? fmt::format("module, z1 and z2 with the shift sum for a = {:g} mm (x1 + x2 in [{:g}, {:g}])",
                                                              *in.centre_distance, in.x_sum_min, in.x_sum_max)
                                               : std::string("module, z1 and V-0 shift");
  report.notes.push_back(fmt::format("{} combinations of {} tried, {} ratings; S_Hmin = {:g}, S_Fmin = {:g}; "
                                     "{}; candidates with undercut, interference or a contact ratio below 1 are left out.",
                                     r.combinations, tried, r.evaluated, in.load.S_Hmin, in.load.S_Fmin, accuracy_text(in.load)));
  if (r.best.empty()) report.warnings.push_back("no candidate meets the required safety factors: allow larger modules, wider faces or a stronger material");
  report.json["sizing"] = {{"candidates", list}, {"combinations", r.combinations}, {"ratings", r.evaluated}};
  return report;
}

}  // namespace

int run_gear_size_command(plugin::CommandContext& context) {
  io::po::options_description desc("gearkit gear size options");
  add_rating_options(desc);
  auto text = [] { return io::po::value<std::string>(); };
  desc.add_options()("ratio", text()->value_name("U"), "required gear ratio z2/z1")
      ("ratio-tolerance", text()->value_name("TOL"), "relative ratio tolerance (default 0.02)")
      ("modules", text()->value_name("LIST"), "normal modules to try, plain numbers (default ISO 54 series I, 1..25) (bare number: mm)")
      ("z1-min", text()->value_name("N"), "smallest pinion tooth count (default 14)")
      ("z1-max", text()->value_name("N"), "largest pinion tooth count (default 40)")
      ("shifts", text()->value_name("LIST"), "x1 of the V-0 shift split, x2 = -x1 (default 0,0.2,0.4)")
      ("helix-angle", text()->value_name("ANGLE"), "helix angle (default 0) (bare number: deg)")
      ("pressure-angle", text()->value_name("ANGLE"), "normal pressure angle (default 20 deg) (bare number: deg)")
      ("width-ratio-max", text()->value_name("B/D1"), "largest face width over pinion diameter (default 1)")
      ("width-module-min", text()->value_name("B/M"), "smallest face width over module (default 8)")
      ("centre-distance", text()->value_name("LEN"), "required working centre distance: the shift sum follows from it (default free, V-0) (bare number: mm)")
      ("hunting-tooth", io::po::bool_switch(), "only hunting-tooth pairs, gcd(z1, z2) = 1 (every z2 within the ratio tolerance is tried)")
      ("count", text()->value_name("N"), "candidates shown (default 5)");
  io::add_common_options(desc);
  io::po::positional_options_description none;
  io::po::variables_map vm;
  std::vector<std::string> args(context.args.begin() + 1, context.args.end());
  if (!io::parse_command_line(args, desc, none, vm, kUsage, context.out)) return 0;
  const gg::SizingInput input = read_sizing(vm);
  const io::CommonOptions common = io::common_options(vm);
  gg::SizingResult result;
  try {
    result = gg::size_gear_pair(input);
  } catch (const gg::RatingError& e) {
    const std::string f = e.field();
    const std::string option = f == "centre_distance" ? "centre-distance" : f == "ratio_tolerance" ? "ratio-tolerance" : f == "width_ratio" ? "width-ratio-max" : f == "width_module" ? "width-module-min" : f == "z1" ? "z1-min"
                               : (f == "ratio" || f == "modules" || f == "shifts" || f == "count") ? f : option_for_rating_field(f);
    io::fail_option(fmt::format("--{}", option), e.what());
  }
  return io::emit(sizing_report(input, result), common, context.out);
}

}  // namespace gearkit::plugins::gear
