#pragma once
// Reading a cam model file (YAML, documented in docs/cam.md) into a libcam design.
#include <gearkit/cam/cam_design.hpp>
#include <gearkit/io/yaml_model.hpp>

#include <optional>
#include <string>
#include <vector>

namespace gearkit::plugins::cam {

/// Largest length accepted in a cam model [mm] (docs/cli.md): 10 m keeps the 1e-6 mm fit
/// tolerance far above the rounding of coordinates (1e-16 relative).
inline constexpr double kMaxLengthMm = 10000;

struct CamModel {
  explicit CamModel(gearkit::cam::CamDesign d) : design(std::move(d)) {}

  gearkit::cam::CamDesign design;
  std::string name;
  std::optional<double> omega;        ///< cam speed [rad/s], for per-second values
  double pressure_angle_limit = 0;    ///< [rad]
  double tolerance_mm = 1e-3;         ///< arc fit tolerance
  int samples = 360;                  ///< cam angles in the report's profile points and CSV
  double follower_at = 0;             ///< cam angle of the follower in the SVG drawing [rad]
  std::optional<double> cutter_radius_mm;
  double pivot_radius_mm = 0;         ///< oscillating: pivot boss radius, for the clearance check
};

/// Reads the `motion:` list of a mapping (docs/cam.md): the one syntax for motion programs, in
/// `gearkit cam` files and in `cam_follower` elements of mechanism files. Returns without `lift`
/// go back to the base circle. Translating lifts are SI lengths times `metres_to_model` (1000
/// for libcam's millimetres, 1 for the SI solver); oscillating lifts are radians.
/// @param marks if not null, receives each segment's position for later messages.
/// @throws io::InputError for unknown keys, laws or units, with file:line:column.
std::vector<gearkit::cam::Segment> read_motion_segments(io::MapReader& r, bool angular_lift, double metres_to_model,
                                                        std::vector<io::SourceMark>* marks = nullptr);

/// Loads and validates a cam model.
/// @throws io::InputError "file:line:col: expected ..., found ..." for malformed YAML, unknown
///         keys, bad quantities, segments that leave gaps or overlap or do not cover 360 deg,
///         zero-duration segments, negative radii, a base circle smaller than the roller, or a
///         follower that cannot reach the cam.
CamModel load_cam_model(const std::string& path);

}  // namespace gearkit::plugins::cam
