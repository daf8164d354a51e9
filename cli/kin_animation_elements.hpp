#pragma once
// What `gearkit kin --animate` draws beyond the links and joints (kin_animation.cpp): slider
// blocks on their guide lines, springs, the names of links and points, the traces of the output
// points (the coupler point's curve), and the loop time, from --speed or the file's speed.
#include "kin_analysis.hpp"

#include <gearkit/io/command_line.hpp>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace gearkit::cli {

/// Where a body's point is at coordinates q [m] (the ground's for kin::kGround).
inline Eigen::Vector2d point_at(const Eigen::VectorXd& q, int body, const Eigen::Vector2d& local) {
  return kin::Model::point_position(q, {body, local});
}
/// A body's angle at coordinates q [rad] (0 for kin::kGround).
inline double angle_of(const Eigen::VectorXd& q, int body) { return body == kin::kGround ? 0.0 : q(3 * body + 2); }

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

/// --speed of `gearkit kin` in SI (rad/s for an angle driver, m/s for a slide), or nullopt. The
/// value needs its unit ("60rpm", "200 mm/s"; docs/cli.md, "Quantity options").
/// @throws io::InputError naming --speed, for a bare number too.
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

/// The point of `body` a revolute pins to the ground, else to another link; none if no revolute
/// holds it.
std::optional<kin::BodyPoint> pivot_of(const kin::Model& model, int body);

/// A cam of a cam_follower element (kin::ConstraintDrawing::Cam), in the cam's frame [m]: the
/// pitch curve is the path of the roller centre in that frame over the sweep (one turn at most;
/// `closed` when the sweep turns the cam a whole turn, else only the traced part, `turned` [rad]);
/// the profile its inner envelope, offset by the roller radius along the normal towards the cam;
/// for a flat-faced follower, the envelope of the face's lines seen from the cam.
struct CamPicture {
  std::string name;
  kin::ConstraintDrawing::Cam drawing;
  std::vector<Eigen::Vector2d> pitch, profile;
  Eigen::Vector2d axis = Eigen::Vector2d::Zero();  ///< the cam's pivot in its frame (its origin if none)
  bool closed = false;
  double turned = 0.0;
  double reach = 0.0;  ///< the farthest point of both curves from the cam's frame origin [m]
  /// A flat face: the drawn segment's ends along the face from its point [m], the contact's
  /// travel along it and a tenth of `reach` beyond each end.
  std::optional<std::pair<double, double>> face_span;
};
std::vector<CamPicture> cam_pictures(const kin::Model& model, const std::vector<KinPosition>& positions);

/// Each cam as one group in its body's frame (profile filled, pitch curve dashed) moved by the
/// body's pose (animateTransform translate, then rotate added), and its roller circle or its flat
/// face (a segment moving with the follower).
std::string cam_elements(const std::vector<CamPicture>& cams, const std::vector<const KinPosition*>& frames, const AnimationCanvas& c,
                         double duration);

/// For the caption: which cams show only part of their profile (empty if none).
std::string cam_notes(const std::vector<CamPicture>& cams);

/// An epicyclic_train element drawn as a schematic: its central members' pitch circles about the
/// common axis, radii in proportion to their teeth, on a notional scale (the element has no
/// module) that puts the arm's farthest point midway between the smallest and largest circle (true
/// scale for a sun-planet-ring train); the arm as a radial line to that point.
struct TrainPicture {
  std::string name;
  std::vector<GearCircle> central;  ///< each axis a point of the member's body on the common axis
  kin::BodyPoint arm_axis, arm_end;   ///< on the arm's body (the ground for a fixed arm)
};
std::vector<TrainPicture> train_pictures(const kin::Model& model, const std::vector<const KinPosition*>& frames);
std::string train_elements(const std::vector<TrainPicture>& trains, const std::vector<const KinPosition*>& frames,
                           const AnimationCanvas& c, double duration);

/// The model's springs as zigzags between their two points, stretching with the motion.
std::string spring_elements(const kin::Model& model, const std::vector<const KinPosition*>& frames, const AnimationCanvas& c,
                            double duration);

/// Where each link's name goes in one frame (text start and baseline, SVG units; zero for a link
/// with no point): the first candidate about the link's middle (below right of it, above right,
/// below left, above left; then about the points halfway to each point) whose box meets no joint
/// circle, ground pivot, point name or link name placed before; `choice` (one per link) keeps
/// the previous frame's candidate while it stays clear, so names do not jump between frames.
std::vector<Eigen::Vector2d> link_label_positions(const kin::Model& model, const Eigen::VectorXd& q, const AnimationCanvas& c,
                                                  std::vector<std::size_t>& choice);

/// Link names at the middle of their points and point names beside them, moving with the links.
std::string name_labels(const kin::Model& model, const std::vector<const KinPosition*>& frames, const AnimationCanvas& c,
                        double duration);

/// The paths of the points the model's x/y outputs follow, as dashed lines over every position.
std::string output_traces(const mechanism::Mechanism& mech, const KinAnalysis& analysis, const AnimationCanvas& c);

}  // namespace gearkit::cli
