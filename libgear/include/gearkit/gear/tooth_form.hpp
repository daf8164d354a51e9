#pragma once
// The tooth form of a generated gear, in the transverse section, lengths in mm.
//
// External gears: the exact profile cut by the basic rack (hob or rack cutter) - an involute
// flank from the form circle to the tip, and the root fillet, which is the envelope of the
// rack's tip rounding - with undercut trimmed exactly where the fillet crosses the involute.
// Helical gears: the transverse section of the normal-section tool, whose tip rounding is an
// ellipse (semi-axes rho_fP m_n / cos(beta) and rho_fP m_n).
// Internal gears (rings): involute flanks and the root fillet cut by a pinion-type (shaper)
// cutter of z_0 teeth with a tip rounding, meshing with the ring at the generating centre
// distance a_0 of zero backlash and reaching its root circle.
//
// Every curve is sampled so that the outline stays within `ToothFormSpec::tolerance` of the
// exact generated form (chords; the root and tip circles are exact arcs).
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

/// The pinion-type cutter that cuts a ring (transverse section).
struct ShaperCutter {
  int z_0 = 0;            ///< number of teeth; 0: the default (ring_cutting)
  double rho_a0 = -1.0;   ///< tip rounding radius, mm; negative: rho_fP* m_n, or 3/4 of the largest that fits if smaller
  double x_0 = 0.0;       ///< profile shift coefficient of the cutter
};

/// The nominal cutter a ring is drawn with when none is given: about 100 mm reference diameter
/// (z_0 = 100 mm / m_t rounded, a common disc shaper cutter size), at
/// least 10 teeth and at most |z| - 10 (|z| - 3 for small rings). The cutter used is the first
/// from this one downwards that cuts the ring cleanly (ring_cutting).
/// @throws std::invalid_argument for a ring of fewer than 8 teeth.
int default_cutter_teeth(int z_ring, double m_t);

struct ToothFormSpec {
  int z = 0;            ///< signed number of teeth (negative: internal gear)
  double m_n = 0;       ///< normal module, mm
  double beta = 0;      ///< helix angle, rad
  double x = 0;         ///< profile shift coefficient
  double A_sn = 0;      ///< normal thickness allowance, mm (the rack is fed deeper by A_sn / (2 tan alpha_n))
  double d_a = 0;       ///< tip diameter (signed, with tip shortening)
  Rack rack;            ///< basic rack; rack.alpha_P is the normal pressure angle
  double tolerance = 1e-3;  ///< largest distance of the outline from the generated form, mm, in [1e-7, 1]
  ShaperCutter cutter;      ///< rings only
};

/// The spec of gear i (0 or 1) of a computed pair.
ToothFormSpec tooth_form_spec(const GearPairInput& input, const GearPairResult& result, int i);

/// One side of tooth space 0 (the side with x > 0), from the root (on the root circle) to the
/// tip circle: fillet points first, then the involute.
/// @throws std::invalid_argument if the spec is not a valid gear (z == 0, m_n <= 0, tolerance
/// outside [1e-7, 1] mm, a ring cutter that does not fit: see ring_cutting).
std::vector<Point2> space_flank(const ToothFormSpec& spec);

/// How a ring is cut by its shaper cutter (ISO 21771 internal-gear relations, transverse section).
struct RingCutting {
  int z_0 = 0;
  double x_0 = 0, rho_a0 = 0;    ///< cutter shift coefficient and tip rounding radius, mm
  double d_a0 = 0;               ///< cutter tip diameter that cuts the ring's root circle, mm
  double a_0 = 0;                ///< generating centre distance, mm
  double alpha_w0 = 0;           ///< generating working pressure angle, rad
  /// How far the ring's tip reaches past the cutter's interference point along the line of
  /// action, mm (0: none). Positive: the cutter's flank root cuts the ring's tips (involute
  /// interference of the generating mesh).
  double involute_interference = 0;
  /// Deepest cut of the cutter's tip rounding into the ring teeth outside the generated flank,
  /// measured normal to the involute, mm (0: none): tip (trochoid) interference of the cutter.
  double tip_interference = 0;
};

/// The generating mesh of a ring (spec.z < 0) and its interference checks. With spec.cutter.z_0
/// = 0 the cutter is the first of default_cutter_teeth, one tooth fewer, ... 5 teeth that cuts
/// the ring cleanly (no involute interference, tip interference below 1e-7 mm: a cutter of
/// nearly the ring's size trims the ring's teeth, and a thick-toothed ring with positive x may
/// leave it no generating mesh at all); if none does, the largest that cuts it at all.
/// @throws std::invalid_argument if spec is not a ring or the cutter cannot cut it, each message
/// naming the cutter's z_0 and its reason: z_0 >= |z| or fewer than 5 teeth, its tip below its
/// base circle, a tip rounding that does not fit the tooth, teeth too thick for the ring's spaces
/// (inv alpha_w0 <= 0), a tip that never reaches the ring's flank.
RingCutting ring_cutting(const ToothFormSpec& spec);

/// Closed outline of the whole gear, counter-clockwise, with exact arcs (bulges) on the root and
/// tip circles.
std::vector<ProfileVertex> gear_outline(const ToothFormSpec& spec);

/// Rotates by `angle` (rad, counter-clockwise) about the origin and then translates by (dx, dy).
std::vector<ProfileVertex> placed(std::vector<ProfileVertex> outline, double angle, double dx, double dy);

/// Both gears of a pair placed in mesh at the working centre distance: gear 1 at the origin
/// with a tooth on the +x axis, gear 2 centred at (a, 0) (external) or (-a, 0) (ring) with a
/// space facing gear 1; `tolerance` (mm) as in ToothFormSpec, `cutter` for a ring.
std::array<std::vector<ProfileVertex>, 2> pair_outlines(const GearPairInput& input, const GearPairResult& result,
                                                        double tolerance = 1e-3, const ShaperCutter& cutter = {});

/// Centre of gear 2 in pair_outlines.
Point2 second_gear_centre(const GearPairInput& input, const GearPairResult& result);

}  // namespace gearkit::gear
