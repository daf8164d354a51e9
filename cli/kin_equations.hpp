#pragma once
// `gearkit kin FILE --equations`: the constraint equations in the coordinates the file's
// `equations:` section names (libsym), symbolic and evaluated at the analysed position, as
// report tables (text), LaTeX cells (md) and a JSON object "equations".
#include "kin_analysis.hpp"

#include <gearkit/io/report.hpp>

#include <string>

namespace gearkit::cli {

/// Adds the equations section to `report` for the first analysed position of `analysis`.
/// Without an `equations:` section the coordinates are each moving link's angle (phi1, phi2...
/// in the file's order, along the line through its first two points) and each slide (s1, ...).
/// @throws io::InputError for a malformed section (file:line:column).
void add_equations_section(io::Report& report, const mechanism::Mechanism& mech, const KinAnalysis& analysis, io::Format format);

/// The same, from the executable: the function lives in the module gearkit-kin-equations.so
/// (cli/CMakeLists.txt says why), opened by its absolute path beside the executable's libraries
/// the first time it is called and kept open until the process ends.
/// @throws std::runtime_error when the module cannot be opened (a broken installation).
void add_equations_section_from_module(io::Report& report, const mechanism::Mechanism& mech, const KinAnalysis& analysis,
                                       io::Format format);

/// The module's entry point: add_equations_section with C linkage, so dlsym finds it by name.
using AddEquationsSection = void (*)(io::Report&, const mechanism::Mechanism&, const KinAnalysis&, io::Format);
inline constexpr const char* kAddEquationsSectionSymbol = "gearkit_add_equations_section";

}  // namespace gearkit::cli
