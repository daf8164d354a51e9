#include "gear_types_common.hpp"

#include <gearkit/io/error.hpp>
#include <gearkit/io/quantity.hpp>
#include <gearkit/io/report.hpp>

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace gearkit::plugins::gear::types {

void fail(std::string_view key, std::string_view message) { io::fail_option(fmt::format("--{}", key), message); }

std::optional<int> whole(const io::po::variables_map& vm, const char* key, int low, int high, std::string_view what) {
  const std::optional<double> v = number(vm, key);
  if (!v) return std::nullopt;
  if (*v != std::floor(*v)) fail(key, fmt::format("expected a whole number of {}, found {}", what, io::quote(vm[key].as<std::string>())));
  if (*v < low || *v > high) fail(key, fmt::format("expected {} to {} {}, found {:g}", low, high, what, *v));
  return static_cast<int>(*v);
}

int required_whole(const io::po::variables_map& vm, const char* key, int low, int high, std::string_view what) {
  const std::optional<int> v = whole(vm, key, low, high, what);
  if (!v) fail(key, fmt::format("expected the number of {}, found none", what));
  return *v;
}

std::optional<double> length_mm(const io::po::variables_map& vm, const char* key) {
  const std::optional<double> v = io::quantity_option(vm, key, io::Quantity::length, "mm");
  return v ? std::optional<double>(*v * 1000.0) : std::nullopt;
}

std::optional<double> angle_rad(const io::po::variables_map& vm, const char* key) {
  return io::quantity_option(vm, key, io::Quantity::angle, "deg");
}

std::optional<double> number(const io::po::variables_map& vm, const char* key) {
  return io::quantity_option(vm, key, io::Quantity::dimensionless, "");
}

std::optional<double> torque_Nm(const io::po::variables_map& vm, const char* key) {
  const std::optional<double> T = io::quantity_option(vm, key, io::Quantity::torque, "N*m");
  if (T && !(*T > 0.0)) fail(key, fmt::format("expected a torque > 0, found {}", io::quote(vm[key].as<std::string>())));
  return T;
}

std::optional<double> speed_rpm(const io::po::variables_map& vm, const char* key) {
  const std::optional<double> w = io::quantity_option(vm, key, io::Quantity::angular_velocity, "rpm");
  return w ? std::optional<double>(*w * 30.0 / std::numbers::pi) : std::nullopt;
}

std::string choice(const io::po::variables_map& vm, const char* key, std::initializer_list<std::string_view> choices,
                   std::string_view fallback) {
  if (!vm.count(key)) return std::string(fallback);
  const std::string& s = vm[key].as<std::string>();
  std::string list;
  for (std::string_view c : choices) {
    if (s == c) return s;
    list += (list.empty() ? "" : "|") + std::string(c);
  }
  fail(key, fmt::format("expected {}, found {}", list, io::quote(s)));
}

std::string num(double v, int digits) { return std::isfinite(v) ? io::fixed(v, digits) : std::string("-"); }

nlohmann::json jnum(double v) { return io::json_number(v); }

nlohmann::json jvec(const std::array<double, 3>& v) { return nlohmann::json::array({jnum(v[0]), jnum(v[1]), jnum(v[2])}); }

std::string vec_text(const std::array<double, 3>& v) { return fmt::format("({}, {}, {})", num(v[0], 1), num(v[1], 1), num(v[2], 1)); }

}  // namespace gearkit::plugins::gear::types
