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

}  // namespace gearkit::cli
