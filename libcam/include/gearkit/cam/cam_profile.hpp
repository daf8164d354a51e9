#pragma once
// The cam's shapes for manufacturing, as arc splines (counter-clockwise, cam frame, mm):
// - pitch curve (roller centre / knife tip path), fitted by biarcs to the analytic curve;
// - profile: roller cams: the pitch region inset by the roller radius with CGAL (exact offset of
//   the arc spline, see arc_spline.hpp); knife-edge: the pitch curve; flat faces: the envelope of
//   the face, fitted by biarcs;
// - tool path of a cutter of radius R_c running outside the profile: the profile offset outwards
//   by R_c. For roller cams this is the pitch region offset by R_c - R_r (same arcs, one CGAL
//   offset), which equals the offset of the profile wherever the profile has no undercut.
// - groove cams (Closure::groove): the outer wall too, the pitch curve offset outwards by R_r, and
//   the cutter's path along it (offset outwards by R_r - R_c; the cutter runs inside the groove).
// - conjugate cams: synthesize_profile(conjugate_cam_of(design), ...) gives the second cam.
#include <gearkit/cam/arc_spline.hpp>
#include <gearkit/cam/cam_design.hpp>

#include <optional>
#include <vector>

namespace gearkit::cam {

struct ProfileOptions {
  double tolerance = 1e-3;  ///< biarc fit: largest distance from the analytic curve [mm]
  std::optional<double> cutter_radius;  ///< [mm]; no tool path without it
};

struct CamProfile {
  std::vector<Piece> pitch_curve;                ///< empty for flat faces
  std::vector<std::vector<Piece>> profile;       ///< closed loops
  std::vector<std::vector<Piece>> tool_path;     ///< closed loops (empty without a cutter)
  bool profile_trimmed = false;    ///< the roller offset folded and was trimmed (undercut)
  bool tool_path_trimmed = false;  ///< the cutter offset folded: the cutter is too large for a hollow
  bool profile_is_polyline = false;  ///< flat face with cusps: the envelope as straight segments
  std::size_t biarcs = 0;          ///< biarcs in the fitted curve
  /// Largest distances of the exported arcs from the analytic curves [mm], found by maximisation
  /// during the fit (each within ProfileOptions::tolerance): pitch curve (flat faces: the
  /// profile), profile, tool path (0 without a cutter). Where an offset folds and is trimmed
  /// (undercut, a cutter too large for a hollow) the trimmed-away arcs are not counted.
  double pitch_error = 0, profile_error = 0, tool_path_error = 0;
  /// Groove cams: the outer wall (the pitch curve offset outwards by the roller) and the cutter's
  /// path along it; the profile and tool path above are the inner wall's.
  std::vector<std::vector<Piece>> outer_wall, outer_tool_path;
  bool outer_wall_trimmed = false, outer_tool_path_trimmed = false;
  double outer_error = 0, outer_tool_path_error = 0;
};

/// Builds the pitch curve, profile and tool path. Requires validate(design) to have passed.
/// @throws GeometryError if CGAL fails, the profile vanishes (roller larger than the cam), or
///         the arcs cannot meet the tolerance (a corner in the motion; the message gives the cam
///         angle).
CamProfile synthesize_profile(const CamDesign& design, const ProfileOptions& options);

/// Largest distance from any point to the nearest piece of `loops` (points in order along the
/// curve, so the search walks along with them) [mm].
double max_deviation(const std::vector<std::vector<Piece>>& loops, const std::vector<Vec2>& points);

}  // namespace gearkit::cam
