#pragma once
// The gear table as an io::Report (text/md/csv tables like the OTM 2015 problem 3 solution
// table, JSON with unit-suffixed keys); the drawing is in gear_drawing.hpp.
#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/io/report.hpp>

#include <string>

namespace gearkit::plugins::gear {

/// @param radii print the table's sizes as radii (r, r_w, r_b, r_a, r_f) and add them to the
///              JSON (`r_mm`, `r_w_mm`, `r_b_mm`, `r_a_mm`, `r_f_mm`), as course notes print them.
io::Report gear_report(const gearkit::gear::GearPairInput& input, const gearkit::gear::GearPairResult& result,
                       bool radii = false);

}  // namespace gearkit::plugins::gear
