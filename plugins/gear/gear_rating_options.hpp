#pragma once
// The load-capacity options of `gearkit gear` (docs/rating.md): load, materials, lubrication,
// accuracy, method and imposed factors, turned into a libgear RatingInput.
#include <gearkit/gear/rating.hpp>
#include <gearkit/io/command_line.hpp>

#include <optional>
#include <string>

namespace gearkit::plugins::gear {

/// Adds the rating options to `desc` (`--quality` only if no other part of the command defines it).
void add_rating_options(io::po::options_description& desc);

/// True if any option that asks for a rating was given (--torque1, --power).
bool rating_requested(const io::po::variables_map& vm);

/// True if any rating option at all was given (a pair file excludes them).
bool any_rating_option(const io::po::variables_map& vm);

/// Reads the rating options. @throws io::InputError naming the option for malformed values,
/// unknown materials or factor names, and missing or contradictory load options.
gearkit::gear::RatingInput read_rating_options(const io::po::variables_map& vm);

/// Parses "NAME=VALUE" of --factor into `factors`. @throws std::invalid_argument with the reason.
void parse_factor(std::string_view text, gearkit::gear::ImposedFactors& factors);

/// The option that corresponds to a RatingError field ("T_1" -> "--torque1").
std::string option_for_rating_field(const std::string& field);

/// Material by name as the options and pair files accept it. @throws std::invalid_argument.
gearkit::gear::Material material_named(std::string_view name);

}  // namespace gearkit::plugins::gear
