#pragma once
// Design checks of a cam over one turn: pressure angle, radii of curvature, undercut, flat face
// width, and the smallest base circle that meets a pressure-angle limit.
#include <gearkit/cam/cam_design.hpp>

#include <vector>

namespace gearkit::cam {

struct CheckOptions {
  int samples = 3600;                   ///< cam angles checked, evenly over the turn
  double pressure_angle_limit = 0.5236;  ///< [rad]; 30 deg, the usual limit for translating followers
};

/// A value and the cam angle where it occurs [rad].
struct ValueAt {
  double value = 0;
  double theta = 0;
};

struct CamChecks {
  std::vector<ContactState> samples;  ///< the contact at every checked cam angle
  ValueAt pressure_angle_max;         ///< largest |pressure angle| (value keeps its sign) [rad]
  bool pressure_angle_exceeded = false;
  ValueAt rho_pitch_min;    ///< smallest convex radius of curvature of the pitch curve [mm] (inf if none)
  ValueAt rho_profile_min;  ///< smallest radius of the profile where it is convex [mm]; < 0 means undercut
  ValueAt rho_concave_min;  ///< smallest radius where the profile is concave [mm] (inf if none): the
                            ///< largest cutter that can finish it
  bool undercut = false;    ///< the profile folds (roller larger than the pitch curve's convex radius,
                            ///< flat face with rho <= 0): the follower cannot follow the motion there
  std::vector<ValueAt> undercut_ranges;  ///< start angle in theta, end angle in value [rad]
  double face_min = 0, face_max = 0;     ///< flat face: contact positions along the face [mm]
  double base_radius_min = 0;  ///< smallest base circle meeting the limit (pressure angle; flat: rho > 0) [mm]
  ValueAt radius_max;          ///< largest radius of the profile (the circle the cam sweeps) [mm]
  std::vector<PitchCorner> corners;  ///< corners of the pitch curve (velocity jumps), see pitch_corners
};

/// Evaluates the design at options.samples cam angles; the extremes (pressure angle, radii of
/// curvature, largest radius) are then found near the sampled ones by golden-section search, so
/// they are the curve's, not the samples'. Requires validate(design) to have passed.
CamChecks check_design(const CamDesign& design, const CheckOptions& options);

/// The largest distance of the profile from the cam centre and its cam angle [mm, rad]: the
/// circle the turning cam sweeps (for clearance with the follower's pivot and frame).
ValueAt largest_radius(const CamDesign& design);

/// Smallest base circle radius for which the largest |pressure angle| stays within `limit` (and,
/// for flat faces, the profile stays convex: rho > 0). Closed form for translating followers:
/// tan(phi) = (s' - sigma e) / (s0 + s) <= tan(limit) for all theta gives s0, and
/// R_b = sqrt(s0^2 + e^2) - R_r; flat face: R_b > sup(-(s + s'')). The supremum over the turn is
/// found piece by piece between the program's breaks (sampled with `samples` per turn to
/// bracket it, then golden-section search), so a base circle just above the result is convex
/// (flat face) or within the limit. Oscillating followers: bisection on the base radius, the
/// largest pressure angle found the same way at each trial.
/// @throws DesignError if no base circle up to the follower's reach meets the limit.
double smallest_base_radius(const CamDesign& design, double limit, int samples);

}  // namespace gearkit::cam
