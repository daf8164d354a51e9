#pragma once
// The gear drawing of `gearkit gear --svg/--dxf`: the tooth outlines (within --tolerance), the
// reference, base, tip and root circles on named layers and labelled, the gear data block in the
// arrangement of ISO 1340 / DIN 3966-1 (with the inspection values when the accuracy options are
// given) and a title block with the units.
#include "gear_options.hpp"

#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/gear/inspection.hpp>
#include <gearkit/gear/tooth_form.hpp>
#include <gearkit/io/drawing.hpp>
#include <gearkit/io/drawing_annotation.hpp>
#include <gearkit/io/report.hpp>

#include <optional>
#include <vector>

namespace gearkit::plugins::gear {

/// The data block of the gears `which` (0, 1 or both): rows of quantity, symbol and one value
/// column per gear, numbers as in the report (mm to 3 decimals, angles to 3). `inspection` adds
/// the W_k and M_d limits, the thickness allowances, the accuracy grade and the centre-distance
/// allowances; without it W_k and M_d are nominal (and with allowances A_sn, actual).
io::TextTable gear_data_table(const gearkit::gear::GearPairInput& input, const gearkit::gear::GearPairResult& result,
                              const gearkit::gear::InspectionResult* inspection, const std::vector<int>& which);

/// The drawing named by options.draw ("pair", "gear1", "gear2").
/// @throws io::InputError naming --cutter-teeth or --cutter-tip-radius when the ring's cutter does not fit.
io::Drawing gear_drawing(const gearkit::gear::GearPairInput& input, const gearkit::gear::GearPairResult& result,
                         const GearCommandOptions& options, const gearkit::gear::InspectionResult* inspection);

/// For a ring: how its cutter cuts it (ring_cutting) as a report table, JSON "ring_cutter" and
/// warnings for involute or tip interference of the cutter. Nothing for an external pair.
/// @throws io::InputError as gear_drawing.
void add_ring_cutting_report(io::Report& report, const gearkit::gear::GearPairInput& input,
                             const gearkit::gear::GearPairResult& result, const GearCommandOptions& options);

}  // namespace gearkit::plugins::gear
