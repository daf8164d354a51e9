#include "gear_tolerance_options.hpp"

#include <gearkit/gear/iso286.hpp>
#include <gearkit/io/error.hpp>
#include <gearkit/io/quantity.hpp>

#include <fmt/format.h>

#include <charconv>
#include <map>
#include <vector>

namespace gearkit::plugins::gear {

namespace gg = gearkit::gear;

namespace {

[[noreturn]] void reject(std::string_view key, std::string_view message) {
  io::fail_option(fmt::format("--{}", key), message);
}

bool has(const io::po::variables_map& vm, const char* key) { return vm.count(key) > 0; }

// The comma-separated items of an option's value, each trimmed.
std::vector<std::string> items(const io::po::variables_map& vm, const char* key) {
  const std::string text = vm[key].as<std::string>();
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    item.erase(0, item.find_first_not_of(" \t"));
    item.erase(item.find_last_not_of(" \t") + 1);
    out.push_back(item);
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

std::string shown(std::string_view s) { return s.size() > 60 ? fmt::format("'{}...'", s.substr(0, 57)) : fmt::format("'{}'", s); }

double value_of(std::string_view key, const std::string& item, io::Quantity q, const char* unit, double scale) {
  try {
    return io::parse_quantity_si(item, q, unit) * scale;
  } catch (const io::QuantityError& e) {
    reject(key, e.what());
  }
}

// Two lengths "UPPER,LOWER" in mm with upper >= lower.
gg::ThicknessAllowances limits(const io::po::variables_map& vm, const char* key) {
  const auto parts = items(vm, key);
  if (parts.size() != 2) {
    reject(key, fmt::format("expected UPPER,LOWER (two lengths, mm), found {}", shown(vm[key].as<std::string>())));
  }
  const gg::ThicknessAllowances a{value_of(key, parts[0], io::Quantity::length, "mm", 1000.0),
                                  value_of(key, parts[1], io::Quantity::length, "mm", 1000.0)};
  if (!(a.A_sne >= a.A_sni)) {
    reject(key, fmt::format("expected upper allowance >= lower allowance, found {} mm < {} mm", a.A_sne, a.A_sni));
  }
  if (std::fabs(a.A_sne) > 100.0 || std::fabs(a.A_sni) > 100.0) {
    reject(key, fmt::format("expected allowances within +-100 mm, found {} mm, {} mm", a.A_sne, a.A_sni));
  }
  return a;
}

int whole_number(std::string_view key, const std::string& item, std::string_view what) {
  int value = 0;
  const auto [end, ec] = std::from_chars(item.data(), item.data() + item.size(), value);
  if (item.empty() || ec != std::errc() || end != item.data() + item.size()) {
    reject(key, fmt::format("expected {}, found {}", what, shown(item)));
  }
  return value;
}

void operating_temperatures(const io::po::variables_map& vm, gg::InspectionInput& ii) {
  if (!has(vm, "temperature")) return;
  const auto parts = items(vm, "temperature");
  if (parts.size() > 2) reject("temperature", "expected T_GEARS[,T_HOUSING] in deg C");
  std::array<double, 2> T{};
  for (std::size_t i = 0; i < parts.size(); ++i) {
    T[i] = value_of("temperature", parts[i], io::Quantity::dimensionless, "", 1.0);
    if (!(T[i] >= -100.0 && T[i] <= 500.0)) {
      reject("temperature", fmt::format("expected a temperature in -100..500 deg C, found {}", T[i]));
    }
  }
  ii.T_gears = T[0];
  ii.T_housing = parts.size() == 2 ? T[1] : T[0];
}

void expansion_coefficients(const io::po::variables_map& vm, gg::InspectionInput& ii) {
  if (!has(vm, "expansion")) return;
  if (!has(vm, "temperature")) reject("expansion", "only applies with --temperature");
  const auto parts = items(vm, "expansion");
  if (parts.size() != 3) reject("expansion", "expected ALPHA_GEAR1,ALPHA_GEAR2,ALPHA_HOUSING in 1/K (steel 11.5e-6)");
  double* target[] = {&ii.alpha_gear1, &ii.alpha_gear2, &ii.alpha_housing};
  for (int i = 0; i < 3; ++i) {
    *target[i] = value_of("expansion", parts[i], io::Quantity::dimensionless, "", 1.0);
    if (!(*target[i] >= 0.0 && *target[i] <= 1e-4)) {
      reject("expansion", fmt::format("expected a coefficient in 0..1e-4 1/K, found {}", *target[i]));
    }
  }
}

void din3967_designations(const io::po::variables_map& vm, gg::InspectionInput& ii) {
  if (!has(vm, "din3967")) return;
  for (const char* other : {"thickness-allowances1", "thickness-allowances2"}) {
    if (has(vm, other)) reject("din3967", fmt::format("cannot be combined with --{}: give one of them", other));
  }
  const auto parts = items(vm, "din3967");
  if (parts.size() > 2) reject("din3967", "expected DESIGNATION or DESIGNATION1,DESIGNATION2, e.g. 27cd or 25e,26d");
  for (std::size_t i = 0; i < parts.size(); ++i) {
    try {
      ii.din3967[i] = gg::parse_din3967(parts[i]);
    } catch (const std::invalid_argument& e) {
      reject("din3967", e.what());
    }
  }
  if (parts.size() == 1) ii.din3967[1] = ii.din3967[0];
}

void centre_distance_options(const io::po::variables_map& vm, gg::InspectionInput& ii) {
  if (has(vm, "centre-distance-tolerance") && has(vm, "centre-distance-allowances")) {
    reject("centre-distance-allowances", "cannot be combined with --centre-distance-tolerance: give one of them");
  }
  if (has(vm, "centre-distance-allowances")) ii.centre_distance_allowances = limits(vm, "centre-distance-allowances");
  if (!has(vm, "centre-distance-tolerance")) return;
  const std::string field = vm["centre-distance-tolerance"].as<std::string>();
  const std::string digits = field.starts_with("js") ? field.substr(2) : "";
  const int it = digits.empty() ? -1 : whole_number("centre-distance-tolerance", digits, "an ISO 286 js field js5..js11");
  if (it < gg::kMinItGrade || it > gg::kMaxItGrade) {
    reject("centre-distance-tolerance", fmt::format("expected an ISO 286 js field js5..js11, found {}", shown(field)));
  }
  ii.centre_distance_it = it;
}

}  // namespace

void add_tolerance_options(io::po::options_description& desc) {
  namespace po = io::po;
  desc.add_options()
      ("quality", po::value<std::string>()->value_name("Q[,Q2]"),
       "ISO 1328-1 accuracy grade of both gears, or of gear 1 and gear 2 (2013: 1..11; 1995: 0..12)")
      ("iso1328-edition", po::value<std::string>()->value_name("2013|1995"), "edition of ISO 1328-1 (default 2013)")
      ("thickness-allowances1", po::value<std::string>()->value_name("UPPER,LOWER"),
       "normal tooth thickness allowances A_sne,A_sni of gear 1 (default: ISO/TR 10064-2 from --quality) (bare number: mm)")
      ("thickness-allowances2", po::value<std::string>()->value_name("UPPER,LOWER"),
       "normal tooth thickness allowances A_sne,A_sni of gear 2 (bare number: mm)")
      ("din3967", po::value<std::string>()->value_name("TS[,TS2]"),
       "DIN 3967 tooth thickness allowances of both gears or of gear 1 and gear 2, e.g. 27cd (tolerance series "
       "21..30, deviation series a..h)")
      ("min-backlash", po::value<std::string>()->value_name("LEN"),
       "minimum normal backlash the allowances must leave (default ISO/TR 10064-2) (bare number: mm)")
      ("centre-distance-tolerance", po::value<std::string>()->value_name("jsN"),
       "ISO 286 js field of the centre distance, js5..js11 (default from the grade)")
      ("centre-distance-allowances", po::value<std::string>()->value_name("UPPER,LOWER"),
       "centre distance allowances A_ae,A_ai (bare number: mm)")
      ("temperature", po::value<std::string>()->value_name("T[,T_HOUSING]"),
       "operating temperature of the gears (and of the housing), plain numbers: backlash when warm (bare number: deg C)")
      ("expansion", po::value<std::string>()->value_name("A1,A2,AH"),
       "linear expansion coefficients of gear 1, gear 2 and housing, plain numbers (default steel 11.5e-6) (bare number: 1/K)");
}

gg::Iso1328Edition read_iso1328_edition(const io::po::variables_map& vm) {
  if (!has(vm, "iso1328-edition")) return gg::Iso1328Edition::iso2013;
  const std::string e = vm["iso1328-edition"].as<std::string>();
  if (e == "2013") return gg::Iso1328Edition::iso2013;
  if (e == "1995") return gg::Iso1328Edition::iso1995;
  reject("iso1328-edition", fmt::format("expected 2013 or 1995, found {}", shown(e)));
}

std::array<std::optional<int>, 2> read_quality(const io::po::variables_map& vm) {
  const gg::Iso1328Edition edition = read_iso1328_edition(vm);
  if (!has(vm, "quality")) return {};
  const auto parts = items(vm, "quality");
  if (parts.size() > 2) reject("quality", fmt::format("expected Q or Q1,Q2, found {}", shown(vm["quality"].as<std::string>())));
  const int lo = gg::min_grade(edition), hi = gg::max_grade(edition);
  std::array<std::optional<int>, 2> q;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const int g = whole_number("quality", parts[i], "a whole accuracy grade");
    if (g < lo || g > hi) {
      reject("quality", fmt::format("expected a grade {}..{} ({}), found {}", lo, hi, gg::to_string(edition), g));
    }
    q[i] = g;
  }
  if (parts.size() == 1) q[1] = q[0];
  return q;
}

std::optional<gg::InspectionInput> read_tolerance_options(const io::po::variables_map& vm) {
  gg::InspectionInput ii;
  ii.edition = read_iso1328_edition(vm);
  ii.grade = read_quality(vm);
  if (has(vm, "thickness-allowances1")) ii.allowances[0] = limits(vm, "thickness-allowances1");
  if (has(vm, "thickness-allowances2")) ii.allowances[1] = limits(vm, "thickness-allowances2");
  din3967_designations(vm, ii);
  const bool wanted = ii.grade[0] || ii.allowances[0] || ii.allowances[1] || ii.din3967[0];
  for (const char* key : {"iso1328-edition", "min-backlash", "centre-distance-tolerance", "centre-distance-allowances",
                          "temperature", "expansion"}) {
    if (has(vm, key) && !wanted) reject(key, "needs --quality, --din3967 or --thickness-allowances1/2");
  }
  if (!wanted) return std::nullopt;
  if (has(vm, "min-backlash")) {
    ii.j_bn_min = value_of("min-backlash", vm["min-backlash"].as<std::string>(), io::Quantity::length, "mm", 1000.0);
    if (!(*ii.j_bn_min >= 0.0 && *ii.j_bn_min <= 100.0)) {
      reject("min-backlash", fmt::format("expected a backlash in 0..100 mm, found {} mm", *ii.j_bn_min));
    }
  }
  centre_distance_options(vm, ii);
  operating_temperatures(vm, ii);
  expansion_coefficients(vm, ii);
  return ii;
}

std::string tolerance_option_for_field(const std::string& field) {
  static const std::map<std::string, std::string> options = {
      {"grade1", "quality"}, {"grade2", "quality"}, {"allowances1", "thickness-allowances1"},
      {"allowances2", "thickness-allowances2"}, {"centre_distance_allowances", "centre-distance-allowances"},
      {"centre_distance_it", "centre-distance-tolerance"}, {"din3967_1", "din3967"}, {"din3967_2", "din3967"}};
  const auto it = options.find(field);
  return it == options.end() ? "" : it->second;
}

}  // namespace gearkit::plugins::gear
