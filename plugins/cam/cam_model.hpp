#pragma once
// Reading a cam model file (YAML, documented in docs/cam.md) into a libcam design.
#include <gearkit/cam/cam_design.hpp>
#include <gearkit/cam/follower_dynamics.hpp>
#include <gearkit/io/yaml_model.hpp>

#include <optional>
#include <string>
#include <vector>

namespace gearkit::plugins::cam {

/// Largest length accepted in a cam model [mm] (docs/cli.md): 10 m keeps the 1e-6 mm fit
/// tolerance far above the rounding of coordinates (1e-16 relative).
inline constexpr double kMaxLengthMm = 10000;

/// Largest jump margin (a factor over the design speed) accepted.
inline constexpr double kMaxJumpMargin = 10;

/// Limits of the work-setting inputs of the dynamics (docs/cli.md).
inline constexpr int kMinDynamicsSamples = 36, kMaxDynamicsSamples = 36000;
inline constexpr int kMaxSweepSteps = 1000;
inline constexpr double kMaxSpeedRpm = 1e6;

/// A speed sweep for the jump: the least contact force at `steps` + 1 speeds from..to [rad/s].
struct SpeedSweepInput {
  double from = 0, to = 0;
  int steps = 0;
};

/// The `dynamics:` section (docs/cam.md), in SI (see gearkit/cam/follower_dynamics.hpp).
struct DynamicsInput {
  gearkit::cam::FollowerTrain train;     ///< spring rate and preload as given (0 if sized)
  std::optional<double> spring_rate, preload;  ///< given; the missing ones are sized
  std::optional<double> damping_ratio;   ///< else train.damping
  double min_force = 0;                  ///< [N], sizing target and jump criterion
  double design_speed = 0;               ///< [rad/s], the analysis
  /// A sized spring holds the contact up to design_speed x jump_margin (>= 1; default 1, the
  /// design speed itself): the follower then jumps no earlier than that speed.
  double jump_margin = 1.0;
  double jump_search_to = 0;             ///< [rad/s]
  std::optional<SpeedSweepInput> sweep;
  int samples = 3600;                    ///< cam angles per turn
  double fluctuation = 0.02;             ///< coefficient of speed fluctuation for the --dyn handover
  io::SourceMark mark;                   ///< of the section, for messages about it
};

/// The `contact:` section: Hertz stress.
struct ContactInput {
  gearkit::cam::ContactMaterial material;
  std::optional<double> allowable;  ///< [Pa]
};

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
  io::SourceMark cutter_radius_mark;  ///< of output.cutter_radius in the file (line 0 if not there)
  double pivot_radius_mm = 0;         ///< oscillating: pivot boss radius, for the clearance check
  std::optional<DynamicsInput> dynamics;
  std::optional<ContactInput> contact;
};

/// The model's sections beyond the geometry (cam_model_dynamics.cpp): the second roller of a
/// conjugate cam, `dynamics:` and `contact:`. @throws io::InputError with file:line:column.
void read_second_roller(io::MapReader& follower, CamModel& model);
void read_dynamics(io::MapReader& root, CamModel& model);
/// What is wrong with a jump margin (dynamics.jump_margin, --jump-margin) for this design speed
/// [rad/s], as the message's "expected ..., found ..." text; nullopt when it is accepted.
std::optional<std::string> jump_margin_problem(double design_speed, double margin);
void read_contact(io::MapReader& root, CamModel& model);

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
