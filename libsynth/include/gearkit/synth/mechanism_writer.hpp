#pragma once
// Writes a synthesised linkage as a `gearkit kin` mechanism file (docs/kin.md): ground points,
// links with their points and drawn pose, revolute and prismatic joints, one angle driver with
// its default sweep, and named outputs. The drawn pose is the exact assembly at the first
// precision position, so the solver starts on the branch the synthesis chose. Lengths are
// written in mm and angles in deg (the file format's bare-number units), to 10 significant
// digits; the sketch itself is in SI.
#include <gearkit/synth/linkage.hpp>
#include <string>
#include <vector>

namespace gearkit::synth {

struct SketchPoint {
  std::string name;
  Vec2 at{0, 0};  ///< in the link's frame (global for ground points) [m]
};

struct SketchLink {
  std::string name;
  std::vector<SketchPoint> points;  ///< the first is the frame origin (0, 0) by convention
  double angle = 0;                 ///< drawn angle of the frame's x axis [rad]
  Vec2 position{0, 0};              ///< drawn position of the frame origin [m]
};

/// A joint between two "link.point" names ("ground.O2" for ground points).
struct SketchJoint {
  std::string name;
  std::string first, second;  ///< revolute: the coinciding points; prismatic: slider point, guide point
  bool prismatic = false;
  double axis = 0;            ///< prismatic guide direction in the guide link's frame [rad]
};

/// The angle driver of one link with its default sweep.
struct SketchDriver {
  std::string name = "theta2";
  std::string link;
  double start = 0, end = 0, step = 0;  ///< [rad]; end < start sweeps clockwise; step > 0
};

struct SketchOutput {
  std::string name;
  std::string type;    ///< "angle" (of `target` = link), "x" or "y" (of `target` = link.point), "slider" (joint)
  std::string target;
};

struct MechanismSketch {
  std::string title;
  std::vector<std::string> comments;  ///< written as '#' lines at the top (where it came from)
  std::vector<SketchPoint> ground;
  std::vector<SketchLink> links;
  std::vector<SketchJoint> joints;
  SketchDriver driver;
  std::vector<SketchOutput> outputs;
};

/// The mechanism file text. @throws std::invalid_argument if a number is not finite or a name is
/// empty or not a plain identifier ([A-Za-z_][A-Za-z0-9_]*).
std::string to_mechanism_yaml(const MechanismSketch& sketch);

/// A four-bar drawn at crank angle `theta2_start` [rad] with links crank (O2, A), coupler
/// (A, B, P) and rocker (O4, B), driver `theta2` sweeping `travel` [rad] in `direction` (+1 ccw,
/// -1 cw) in 1 deg steps (finer for short travels), and outputs theta3, theta4, Px, Py.
/// @throws std::invalid_argument if the linkage cannot be assembled at theta2_start.
MechanismSketch four_bar_sketch(const FourBar& linkage, double theta2_start, double travel, int direction,
                                std::string title);

/// An offset slider-crank drawn at `theta2_start` [rad]: links crank (O2, A), rod (A, B) and
/// slider (B) on a prismatic guide through ground point G (the foot of O2 on the guide line),
/// driver theta2 over `travel` in `direction`, outputs s (slider) and theta3.
/// @throws std::invalid_argument if the rod cannot reach the guide at theta2_start.
MechanismSketch slider_crank_sketch(const SliderCrank& linkage, double theta2_start, double travel, int direction,
                                    std::string title);

}  // namespace gearkit::synth
