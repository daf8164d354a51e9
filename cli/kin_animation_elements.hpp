#pragma once
// What `gearkit kin --animate` draws beyond the links and joints (kin_animation.cpp): slider
// blocks on their guide lines, springs, the names of links and points, the traces of the output
// points (the coupler point's curve), and the loop time, from --speed or the file's speed.
#include "kin_analysis.hpp"

#include <gearkit/io/command_line.hpp>

#include <optional>
#include <string>
#include <vector>

namespace gearkit::cli {

/// The SVG viewport of an animation: model metres to SVG units (y down).
struct AnimationCanvas {
  double x0 = 0, y1 = 0, margin = 0, scale = 1000.0, stroke = 1.0;
  double X(double x) const { return (x - x0 + margin) * scale; }
  double Y(double y) const { return (y1 - y + margin) * scale; }
};

/// Seconds per loop: the sweep's span at `speed` (rad/s or m/s of the driver, from --speed); else
/// at `file_speed` (the driver's `speed:` in the model file, its magnitude), slowed down by the
/// power of ten that makes a loop last at least 0.5 s (25 rad/s turns a crank in 0.25 s, which no
/// one can follow); else (none, or 0: quasi-static) 25 frames per second and at least 2 s. `text`
/// says which, for the caption.
double loop_seconds(const KinAnalysis& analysis, std::optional<double> speed, std::optional<double> file_speed,
                    std::size_t frames, std::string& text);

/// --speed of `gearkit kin` in SI (rad/s for an angle driver, rpm by default; m/s for a slide,
/// mm/s by default), or nullopt. @throws io::InputError naming --speed.
std::optional<double> animation_speed(const io::po::variables_map& vm, const mechanism::Mechanism& mech, int driver);

/// Slider blocks (animated) on their guide lines (the guide's travel, animated with a moving guide).
std::string slider_elements(const kin::Model& model, const std::vector<const KinPosition*>& frames, const AnimationCanvas& c,
                            double duration);

/// A gear of a gear_mesh element: its axis (the point a revolute pins to the carrier) and pitch
/// radius [m], from the centre distance and the ratio the frames show (r2 = a / (1 + k) for the
/// mesh relation (theta_2 - theta_c) + k (theta_1 - theta_c) = const). None when the gears do not
/// turn in the frames.
struct GearCircle {
  kin::BodyPoint axis;
  double r = 0.0;
  std::string name;
};
std::vector<GearCircle> gear_circles(const kin::Model& model, const std::vector<const KinPosition*>& frames);

/// The pitch circles of the model's gear meshes about their moving axes, each with a tooth mark
/// turning with its gear; sizes from the centre distance and the ratio the frames show.
std::string gear_elements(const kin::Model& model, const std::vector<const KinPosition*>& frames, const AnimationCanvas& c,
                          double duration);

/// The model's springs as zigzags between their two points, stretching with the motion.
std::string spring_elements(const kin::Model& model, const std::vector<const KinPosition*>& frames, const AnimationCanvas& c,
                            double duration);

/// Link names at the middle of their points and point names beside them, moving with the links.
std::string name_labels(const kin::Model& model, const std::vector<const KinPosition*>& frames, const AnimationCanvas& c,
                        double duration);

/// The paths of the points the model's x/y outputs follow, as dashed lines over every position.
std::string output_traces(const mechanism::Mechanism& mech, const KinAnalysis& analysis, const AnimationCanvas& c);

}  // namespace gearkit::cli
