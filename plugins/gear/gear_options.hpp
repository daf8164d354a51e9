#pragma once
// Command-line options of `gearkit gear` turned into a libgear GearPairInput (values with
// units: bare numbers are mm and degrees), plus the drawing options.
#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/gear/tooth_form.hpp>
#include <gearkit/io/command_line.hpp>

#include <string>

namespace gearkit::plugins::gear {

struct GearCommandOptions {
  gearkit::gear::GearPairInput input;
  std::string svg, dxf;  ///< drawing files ("" = none)
  std::string draw = "pair";  ///< pair | gear1 | gear2
  double tolerance = 1e-3;    ///< outline tolerance, mm (--tolerance)
  gearkit::gear::ShaperCutter cutter;  ///< the ring's cutter (--cutter-teeth, --cutter-tip-radius)
  bool radii = false;         ///< --radii: the table in radii, as course notes print it
};

/// Adds the gear options to `desc`.
void add_gear_options(io::po::options_description& desc);

/// Reads the parsed options. @throws io::InputError naming the option for malformed values,
/// out-of-range values and contradictory combinations.
GearCommandOptions read_gear_options(const io::po::variables_map& vm);

/// Reads only the drawing options --svg, --dxf, --draw, --tolerance, --cutter-* and --radii (with a gear-pair file).
void read_drawing_options(const io::po::variables_map& vm, GearCommandOptions& o);

/// The command-line option that corresponds to a GearPairInput field named by GeometryError.
std::string option_for_field(const std::string& field);

}  // namespace gearkit::plugins::gear
