#pragma once
// Accuracy and inspection options of `gearkit gear` (ISO 1328 grade per gear, tooth thickness
// allowances, centre-distance allowances, operating temperatures) turned into a libgear
// InspectionInput. `--quality` is also read by the load-capacity rating (K_v, K_Hbeta).
#include <gearkit/gear/inspection.hpp>
#include <gearkit/io/command_line.hpp>

#include <array>
#include <optional>
#include <string>

namespace gearkit::plugins::gear {

/// Adds --quality, --iso1328-edition, --thickness-allowances1/2, --din3967, --min-backlash,
/// --centre-distance-tolerance, --centre-distance-allowances, --temperature, --expansion.
void add_tolerance_options(io::po::options_description& desc);

/// Accuracy grade of each gear from `--quality G` (both gears) or `--quality G1,G2`, checked
/// against the edition of `--iso1328-edition` (2013: 1..11, 1995: 0..12); unset if not given.
/// @throws io::InputError naming --quality (or --iso1328-edition) for malformed or out-of-range values.
std::array<std::optional<int>, 2> read_quality(const io::po::variables_map& vm);

/// The edition of --iso1328-edition (default 2013). @throws io::InputError naming the option.
gearkit::gear::Iso1328Edition read_iso1328_edition(const io::po::variables_map& vm);

/// The inspection asked for: set when --quality, --din3967 or --thickness-allowances1/2 is given.
/// @throws io::InputError naming the option for malformed values, allowances with upper < lower,
/// options that need --quality or allowances, and contradictory combinations.
std::optional<gearkit::gear::InspectionInput> read_tolerance_options(const io::po::variables_map& vm);

/// The option that corresponds to an InspectionInput field named by GeometryError ("" if none).
std::string tolerance_option_for_field(const std::string& field);

}  // namespace gearkit::plugins::gear
