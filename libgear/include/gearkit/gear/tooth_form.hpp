#pragma once
// The tooth form of a generated gear, in the transverse section, lengths in mm.
//
// External gears: the exact profile cut by the basic rack (hob or rack cutter) - an involute
// flank from the form circle to the tip, and the root fillet, which is the envelope of the
// rack's tip rounding (an offset of the trochoid described by its centre) - with undercut
// trimmed where the fillet cuts into the involute. For helical gears the transverse section
// of the tool tip rounding (an ellipse) is approximated by a circle of radius rho_fP* m_n.
// Internal gears (rings): involute flanks from the tip circle to the root circle; the root
// fillet depends on the shaper cutter and is not generated (the flank meets the root circle).
//
// Coordinates: gear centre at the origin, tooth space number 0 centred on the +y axis, spaces
// numbered counter-clockwise.
#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/gear/rack.hpp>

#include <array>
#include <vector>

namespace gearkit::gear {

struct Point2 {
  double x = 0, y = 0;
};

/// A polyline vertex; `bulge` = tan(theta/4) of the arc that starts here (DXF convention,
/// positive counter-clockwise), 0 for a straight segment.
struct ProfileVertex {
  double x = 0, y = 0, bulge = 0;
};

struct ToothFormSpec {
  int z = 0;            ///< signed number of teeth (negative: internal gear)
  double m_n = 0;       ///< normal module, mm
  double beta = 0;      ///< helix angle, rad
  double x = 0;         ///< profile shift coefficient
  double A_sn = 0;      ///< normal thickness allowance, mm (the rack is fed deeper by A_sn / (2 tan alpha_n))
  double d_a = 0;       ///< tip diameter (signed, with tip shortening)
  Rack rack;            ///< basic rack; rack.alpha_P is the normal pressure angle
  int fillet_points = 24;
  int flank_points = 48;  // chord error of the involute polyline about 1e-4 m_n
};

/// The spec of gear i (0 or 1) of a computed pair.
ToothFormSpec tooth_form_spec(const GearPairInput& input, const GearPairResult& result, int i);

/// One side of tooth space 0 (the side with x > 0), from the root (on the root circle) to the
/// tip circle: fillet points first, then the involute.
/// @throws std::invalid_argument if the spec is not a valid gear (z == 0, m_n <= 0).
std::vector<Point2> space_flank(const ToothFormSpec& spec);

/// Closed outline of the whole gear, counter-clockwise, with exact arcs (bulges) on the root and
/// tip circles.
std::vector<ProfileVertex> gear_outline(const ToothFormSpec& spec);

/// Rotates by `angle` (rad, counter-clockwise) about the origin and then translates by (dx, dy).
std::vector<ProfileVertex> placed(std::vector<ProfileVertex> outline, double angle, double dx, double dy);

/// Both gears of a pair placed in mesh at the working centre distance: gear 1 at the origin
/// with a tooth on the +x axis, gear 2 centred at (a, 0) (external) or (-a, 0) (ring) with a
/// space facing gear 1.
std::array<std::vector<ProfileVertex>, 2> pair_outlines(const GearPairInput& input, const GearPairResult& result);

/// Centre of gear 2 in pair_outlines.
Point2 second_gear_centre(const GearPairInput& input, const GearPairResult& result);

}  // namespace gearkit::gear
