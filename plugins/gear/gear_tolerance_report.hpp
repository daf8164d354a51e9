#pragma once
// The accuracy and inspection sections of the `gearkit gear` report: flank tolerances per gear,
// tooth thickness allowances, span and pin limits with their measuring conditions, centre-distance
// allowances and the backlash range (tables, notes, warnings and JSON; also what the drawing's
// data block shows).
#include <gearkit/gear/inspection.hpp>
#include <gearkit/io/report.hpp>

namespace gearkit::plugins::gear {

/// Appends the inspection tables and notes to `report`, its warnings, and the JSON fields
/// gears[i].tolerances, gears[i].W_k_max_mm ..., pair.backlash {j_n_min_mm, ...}.
void add_inspection_report(io::Report& report, const gearkit::gear::InspectionResult& inspection);

}  // namespace gearkit::plugins::gear
