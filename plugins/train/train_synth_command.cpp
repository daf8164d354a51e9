#include "train_synth_command.hpp"

#include <gearkit/io/command_line.hpp>
#include <gearkit/io/limits.hpp>
#include <gearkit/io/error.hpp>
#include <gearkit/io/quantity.hpp>
#include <gearkit/io/report.hpp>
#include <gearkit/train/synthesis.hpp>

#include <fmt/format.h>

#include <charconv>
#include <ostream>

namespace gearkit::plugins::train {

namespace gt = gearkit::train;
namespace po = boost::program_options;

namespace {

constexpr std::string_view usage =
    "gearkit train synth reducer --m1 MODULE --m2 MODULE --ratio RATIO [--z1 Z] [--equal-stages] [--tolerance T] "
    "[--z-min Z] [--z-max Z] [--max-results N]\n"
    "       gearkit train synth planetary --ratio RATIO [--planets N] [--fixed sun|carrier|ring] "
    "[--input sun|carrier|ring] [--output-member sun|carrier|ring] [--tolerance T] [--z-min Z] [--z-max Z] "
    "[--z-ring-max Z] [--max-results N]";

bool parse_long(std::string_view s, long long& v) {
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

// "1/16", "-2/5", "0.0625" (a decimal becomes the simplest fraction within 1e-12).
gt::Rational parse_ratio(const std::string& text) {
  const auto slash = text.find('/');
  if (slash != std::string::npos) {
    long long num = 0, den = 0;
    if (!parse_long(text.substr(0, slash), num) || !parse_long(text.substr(slash + 1), den) || den == 0)
      io::fail_option("--ratio", fmt::format("expected a fraction such as 1/16 or a decimal, found {}", io::quote(text)));
    return gt::make_rational(num, den);
  }
  try {
    const double v = io::parse_quantity_si(text, io::Quantity::dimensionless, "");
    if (std::abs(v) > 1e9) io::fail_option("--ratio", fmt::format("expected a ratio below 1e9 in size, found {}", io::quote(text)));
    return gt::rational_from_double(v, 1e-12 * std::max(1.0, std::abs(v)));
  } catch (const io::QuantityError& e) {
    io::fail_option("--ratio", fmt::format("expected a fraction such as 1/16 or a decimal, found {}", io::quote(text)));
  }
}

int integer_option(const po::variables_map& vm, const char* key, int fallback, int lo, int hi) {
  if (!vm.count(key)) return fallback;
  const long long v = vm[key].as<long long>();
  if (v < lo || v > hi) io::fail_option(std::string("--") + key, fmt::format("expected a whole number from {} to {}, found {}", lo, hi, v));
  return static_cast<int>(v);
}

double tolerance_option(const po::variables_map& vm) { return vm.count("tolerance") ? vm["tolerance"].as<double>() : 1e-6; }

double module_option(const po::variables_map& vm, const char* key) {
  if (!vm.count(key)) io::fail_option(std::string("--") + key, "missing: the module of the stage (mm by default)");
  double m = 0;
  try {
    m = io::parse_quantity_si(vm[key].as<std::string>(), io::Quantity::length, "mm") * 1000.0;
  } catch (const io::QuantityError& e) {
    io::fail_option(std::string("--") + key, e.what());
  }
  if (!(m > 0) || m > 1000) io::fail_option(std::string("--") + key, fmt::format("expected a module in (0, 1000] mm, found {} mm", m));
  return m;
}

gt::PlanetaryMember member_option(const po::variables_map& vm, const char* key, gt::PlanetaryMember fallback) {
  if (!vm.count(key)) return fallback;
  const std::string v = vm[key].as<std::string>();
  if (v == "sun") return gt::PlanetaryMember::sun;
  if (v == "carrier") return gt::PlanetaryMember::carrier;
  if (v == "ring") return gt::PlanetaryMember::ring;
  io::fail_option(std::string("--") + key, fmt::format("expected sun, carrier or ring, found {}", io::quote(v)));
}

std::string exact(long long num, long long den) {
  return den == 1 ? std::to_string(num) : fmt::format("{}/{}", num, den);
}

void add_common_synth_options(po::options_description& desc) {
  desc.add_options()
      ("kind", po::value<std::string>()->value_name("reducer|planetary"), "what to synthesise")
      ("ratio", po::value<std::string>()->value_name("RATIO"), "target w_out/w_in, e.g. 1/16 or 0.0625")
      ("tolerance", io::number_in({0, io::limits::kSynthTolerance, false, false, "a relative tolerance from 0 to 0.1"})
                        ->value_name("T"),
       "accepted relative ratio error (default 1e-6)")
      ("z-min", po::value<long long>()->value_name("Z"), "fewest teeth (default 12)")
      ("z-max", po::value<long long>()->value_name("Z"), "most teeth (default 150, or the --z-min value if that is larger)")
      ("max-results", po::value<long long>()->value_name("N"), "candidates listed (default 20)");
}

int run_reducer(plugin::CommandContext& context, const po::variables_map& vm, const io::CommonOptions& common) {
  gt::CoaxialReducerSpec spec;
  spec.module_1_mm = module_option(vm, "m1");
  spec.module_2_mm = module_option(vm, "m2");
  if (!vm.count("ratio")) io::fail_option("--ratio", "missing: the target ratio w_out/w_in, e.g. 1/16");
  spec.target_ratio = parse_ratio(vm["ratio"].as<std::string>());
  if (spec.target_ratio <= 0)
    io::fail_option("--ratio", "expected a positive ratio (two external stages turn the output the same way)");
  spec.tolerance = tolerance_option(vm);
  constexpr int teeth = io::limits::kSynthReducerTeeth;
  spec.z_min = integer_option(vm, "z-min", 12, 1, teeth);
  spec.z_max = integer_option(vm, "z-max", std::min(teeth, std::max(150, spec.z_min)), spec.z_min, teeth);
  if (vm.count("z1")) spec.z1 = integer_option(vm, "z1", 0, spec.z_min, spec.z_max);
  spec.equal_stages = vm.count("equal-stages") > 0;
  spec.max_results = static_cast<std::size_t>(integer_option(vm, "max-results", 20, 1, io::limits::kSynthResults));

  const auto found = gt::synthesise_coaxial_reducer(spec);
  io::Report report;
  report.title = fmt::format("Two-stage coaxial reducer: w4/w1 = {} (m1 = {:g} mm, m2 = {:g} mm)",
                             gt::to_fraction_and_decimal(spec.target_ratio), spec.module_1_mm, spec.module_2_mm);
  io::Table table{"Candidates, best first (ratio error, then equal stages, then size)",
                  {"z1", "z2", "z3", "z4", "ratio", "relative error", "a [mm]"}, {}};
  nlohmann::json j = nlohmann::json::array();
  for (const auto& c : found) {
    const std::string r = exact(c.ratio_numerator, c.ratio_denominator);
    table.add_row({std::to_string(c.z1), std::to_string(c.z2), std::to_string(c.z3), std::to_string(c.z4),
                   fmt::format("{} = {:.6f}", r, static_cast<double>(c.ratio_numerator) / c.ratio_denominator),
                   fmt::format("{:.3e}", c.relative_error), io::fixed(c.centre_distance_mm, 3)});
    j.push_back({{"z1", c.z1}, {"z2", c.z2}, {"z3", c.z3}, {"z4", c.z4}, {"ratio_exact", r},
                 {"ratio", static_cast<double>(c.ratio_numerator) / c.ratio_denominator},
                 {"relative_error", c.relative_error}, {"centre_distance_mm", c.centre_distance_mm}});
  }
  report.tables.push_back(std::move(table));
  report.json["kind"] = "reducer";
  report.json["target_exact"] = gt::to_fraction_string(spec.target_ratio);
  report.json["candidates"] = j;
  if (found.empty())
    report.warnings.push_back("no tooth counts within the bounds meet the ratio and coaxiality; widen the tolerance or the bounds");
  return io::emit(report, common, context.out);
}

int run_planetary(plugin::CommandContext& context, const po::variables_map& vm, const io::CommonOptions& common) {
  gt::PlanetarySpec spec;
  if (!vm.count("ratio")) io::fail_option("--ratio", "missing: the target ratio w_out/w_in, e.g. 1/4");
  spec.target_ratio = parse_ratio(vm["ratio"].as<std::string>());
  if (spec.target_ratio == 0) io::fail_option("--ratio", "expected a non-zero ratio");
  spec.tolerance = tolerance_option(vm);
  spec.planets = integer_option(vm, "planets", 3, 1, 100);
  constexpr int teeth = io::limits::kSynthPlanetaryTeeth;
  spec.z_min = integer_option(vm, "z-min", 12, 1, teeth);
  spec.z_max = integer_option(vm, "z-max", std::min(teeth, std::max(150, spec.z_min)), spec.z_min, teeth);
  spec.z_ring_max = integer_option(vm, "z-ring-max", 400, 1, teeth);
  spec.fixed = member_option(vm, "fixed", gt::PlanetaryMember::ring);
  spec.input = member_option(vm, "input", gt::PlanetaryMember::sun);
  spec.output = member_option(vm, "output-member", gt::PlanetaryMember::carrier);
  if (spec.fixed == spec.input || spec.fixed == spec.output || spec.input == spec.output)
    io::fail_option("--fixed", "expected --fixed, --input and --output-member to name three different members");
  spec.max_results = static_cast<std::size_t>(integer_option(vm, "max-results", 20, 1, io::limits::kSynthResults));

  const auto found = gt::synthesise_planetary(spec);
  const auto name = [](gt::PlanetaryMember m) {
    return m == gt::PlanetaryMember::sun ? "sun" : m == gt::PlanetaryMember::carrier ? "carrier" : "ring";
  };
  io::Report report;
  report.title = fmt::format("Simple planetary, {} planets, {} fixed: w_{}/w_{} = {}", spec.planets, name(spec.fixed),
                             name(spec.output), name(spec.input), gt::to_fraction_and_decimal(spec.target_ratio));
  io::Table table{"Candidates, best first (coaxial, equally spaced, neighbours clear)",
                  {"z_sun", "z_planet", "z_ring", "ratio", "relative error"}, {}};
  nlohmann::json j = nlohmann::json::array();
  for (const auto& c : found) {
    const std::string r = exact(c.ratio_numerator, c.ratio_denominator);
    table.add_row({std::to_string(c.z_sun), std::to_string(c.z_planet), std::to_string(c.z_ring),
                   fmt::format("{} = {:.6f}", r, static_cast<double>(c.ratio_numerator) / c.ratio_denominator),
                   fmt::format("{:.3e}", c.relative_error)});
    j.push_back({{"z_sun", c.z_sun}, {"z_planet", c.z_planet}, {"z_ring", c.z_ring}, {"ratio_exact", r},
                 {"ratio", static_cast<double>(c.ratio_numerator) / c.ratio_denominator},
                 {"relative_error", c.relative_error}});
  }
  report.tables.push_back(std::move(table));
  report.json["kind"] = "planetary";
  report.json["target_exact"] = gt::to_fraction_string(spec.target_ratio);
  report.json["candidates"] = j;
  if (found.empty())
    report.warnings.push_back("no simple planetary within the bounds meets the ratio with equally spaced planets");
  return io::emit(report, common, context.out);
}

}  // namespace

int run_train_synth_command(plugin::CommandContext& context, const std::vector<std::string>& args) {
  po::options_description desc("gearkit train synth options");
  add_common_synth_options(desc);
  desc.add_options()
      ("m1", po::value<std::string>()->value_name("MODULE"), "reducer: module of stage 1-2 (bare number: mm)")
      ("m2", po::value<std::string>()->value_name("MODULE"), "reducer: module of stage 3-4 (bare number: mm)")
      ("z1", po::value<long long>()->value_name("Z"), "reducer: fix the input pinion's teeth")
      ("equal-stages", "reducer: both stages with the same ratio")
      ("planets", po::value<long long>()->value_name("N"), "planetary: number of planets (default 3)")
      ("fixed", po::value<std::string>()->value_name("MEMBER"), "planetary: member held (default ring)")
      ("input", po::value<std::string>()->value_name("MEMBER"), "planetary: input member (default sun)")
      ("output-member", po::value<std::string>()->value_name("MEMBER"), "planetary: output member (default carrier)")
      ("z-ring-max", po::value<long long>()->value_name("Z"), "planetary: most ring teeth (default 400)");
  io::add_common_options(desc);
  po::positional_options_description positional;
  positional.add("kind", 1);
  po::variables_map vm;
  if (!io::parse_command_line(args, desc, positional, vm, usage, context.out)) return 0;
  const io::CommonOptions common = io::common_options(vm);
  const std::string kind = vm.count("kind") ? vm["kind"].as<std::string>() : "";
  if (kind == "reducer") return run_reducer(context, vm, common);
  if (kind == "planetary") return run_planetary(context, vm, common);
  throw io::InputError(fmt::format(
      "train synth: expected 'reducer' or 'planetary', found {} (see gearkit train synth --help)", io::quote(kind)));
}

}  // namespace gearkit::plugins::train
