#pragma once
// The drawing of `gearkit gear bevel --svg/--dxf`: the bevel pair in the axial section (the plane
// of both axes): each gear's tooth zone and blank on both sides of its axis, the axes, pitch cones
// and back cones, the angles delta1, delta2 and Sigma, the face width and the outer tip
// diameters labelled, and a data block of both gears.
#include <gearkit/gear/bevel.hpp>
#include <gearkit/io/drawing.hpp>
#include <gearkit/io/drawing_annotation.hpp>
#include <gearkit/io/report.hpp>

namespace gearkit::plugins::gear {

/// The data block: quantity, symbol and one column per gear (mm to 3 decimals, deg to 4).
io::TextTable bevel_data_table(const gearkit::gear::BevelPairInput& input, const gearkit::gear::BevelPairResult& result);

/// The pair in axial section with the data block. The pitch apex is the origin, gear 1's axis
/// points along +x, gear 2's at Sigma from it (counter-clockwise).
io::Drawing bevel_drawing(const gearkit::gear::BevelPairInput& input, const gearkit::gear::BevelPairResult& result);

}  // namespace gearkit::plugins::gear
