#pragma once
// The drawings of `gearkit gear rack --svg/--dxf` and `gearkit gear worm --svg/--dxf`
// (docs/gear-types.md): drawn with the cylindrical gear drawing's layers, circles and labels
// (gear_drawing.hpp), each with a data block and a title block.
#include <gearkit/gear/rack_pinion.hpp>
#include <gearkit/gear/worm.hpp>
#include <gearkit/io/drawing.hpp>

namespace gearkit::plugins::gear {

/// Pinion and rack in the transverse section: the pinion's generated outline (within `tolerance`
/// mm) and circles, the rack's straight-flank teeth (its whole length for a travel, else about
/// 1.6 tip diameters), its datum line, the pinion's pitch line on it, the line of action, the data
/// block. Frame of rack_pinion.hpp: pinion at the origin, rack below.
io::Drawing rack_drawing(const gearkit::gear::RackPinionInput& in, const gearkit::gear::RackPinionResult& r, double tolerance);

/// Two views of a worm pair. Left: the wheel's mid-plane, with the wheel's generated outline (the
/// worm's axial section as its generating rack, alpha_x, tip radius 0.2 m_x), its circles and the
/// outside diameter, and the worm in axial section above it (threads over the length b1 + p_x; the
/// axial section of ZN, ZI, ZK flanks drawn straight at alpha_x). Right: the section through the
/// wheel's axis with the rim, face width b2, the throat (radius r_k about the worm axis) and the
/// worm's circles. With the data block.
io::Drawing worm_drawing(const gearkit::gear::WormInput& in, const gearkit::gear::WormResult& w, double tolerance);

}  // namespace gearkit::plugins::gear
