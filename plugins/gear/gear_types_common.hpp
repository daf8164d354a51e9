#pragma once
// What `gearkit gear rack`, `gearkit gear worm` and `gearkit gear crossed` share: reading their
// options (quantities through io::quantity_option, so a bad value names its option and exits 2)
// and formatting numbers and force vectors for the reports (docs/gear-types.md).
#include <gearkit/io/command_line.hpp>

#include <nlohmann/json.hpp>

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace gearkit::plugins::gear::types {

/// Ends the command with "option '--KEY': MESSAGE" (exit status 2).
[[noreturn]] void fail(std::string_view key, std::string_view message);

/// A whole number in [low, high] (`what` says what it counts, "teeth"), or nullopt when not given.
std::optional<int> whole(const io::po::variables_map& vm, const char* key, int low, int high, std::string_view what);

/// The same, required: a missing option is "expected WHAT, found none".
int required_whole(const io::po::variables_map& vm, const char* key, int low, int high, std::string_view what);

/// A length in mm (bare number: mm), an angle in rad (bare number: deg), a plain number.
std::optional<double> length_mm(const io::po::variables_map& vm, const char* key);
std::optional<double> angle_rad(const io::po::variables_map& vm, const char* key);
std::optional<double> number(const io::po::variables_map& vm, const char* key);

/// A torque in N m, > 0 (unit required); a speed in 1/min, signed (unit required).
std::optional<double> torque_Nm(const io::po::variables_map& vm, const char* key);
std::optional<double> speed_rpm(const io::po::variables_map& vm, const char* key);

/// One of `choices` (exact), or `fallback` when not given.
std::string choice(const io::po::variables_map& vm, const char* key, std::initializer_list<std::string_view> choices,
                   std::string_view fallback);

/// "-" for a non-finite value, else fixed-point with `digits` decimals.
std::string num(double v, int digits = 4);
/// JSON number (rounded to 12 significant digits) or null when not finite.
nlohmann::json jnum(double v);
/// A force vector: JSON [x, y, z]; text "(x, y, z)" with one decimal.
nlohmann::json jvec(const std::array<double, 3>& v);
std::string vec_text(const std::array<double, 3>& v);

}  // namespace gearkit::plugins::gear::types
