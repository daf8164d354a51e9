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

// Pieces the drawings of the other gear types reuse (gear_types_drawing.cpp).

/// The layers of the gear drawings (gear1, gear2, the four circles, working_pitch, centres,
/// labels, data_block, title_block, frame).
const std::vector<io::Layer>& gear_drawing_layers();
/// A closed tooth outline on `layer`.
io::Polyline outline_polyline(const std::vector<gearkit::gear::ProfileVertex>& outline, std::string layer);
/// A centre cross of half-size `size` at (cx, cy) on layer "centres".
void draw_centre_mark(io::Drawing& d, double cx, double cy, double size);
/// The tip, reference, base and root circles of `g` (its d_a, d, d_b, d_f) centred at (cx, cy),
/// labelled with their diameters in a column to the left (side < 0) or right (side > 0); text height h.
void draw_gear_circles(io::Drawing& d, const gearkit::gear::GearResult& g, double cx, double cy, double side, double h);

}  // namespace gearkit::plugins::gear
