#pragma once
// The cam follower element: a cam on one link imposes its motion program s(theta) (libcam's
// MotionProgram) on a follower on another link.
//   translating: u . (P - Q) - base - s(sigma (theta_cam - theta_0)) = 0, where P is the follower
//     point, Q a point of the guide link and u the guide's direction;
//   oscillating: theta_f - theta_ref - base - psi(sigma (theta_cam - theta_0)) = 0.
// sigma = +1 for a cam turning counter-clockwise, -1 clockwise. One equation; its multiplier
// lambda gives the contact's effect along the follower's motion: the force F = -lambda [N]
// along u on a translating follower, the torque T_f = -lambda [N m] on an oscillating one, and
// the torque T_cam = sigma s' lambda [N m] on the cam (virtual power: F v + T_cam omega = 0).
#include <gearkit/cam/motion_program.hpp>
#include <gearkit/kin/joints.hpp>
#include <gearkit/kin/element.hpp>
#include <gearkit/kin/model.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace gearkit::elements {

enum class FollowerPath { translating, oscillating };

struct CamFollowerParameters {
  int cam = kin::kGround;  ///< body of the cam
  FollowerPath path = FollowerPath::translating;
  /// Translating: the follower point P (roller centre or knife tip) on the follower's body.
  kin::BodyPoint point;
  /// Translating: a point Q of the guide's body.
  kin::BodyPoint guide;
  /// Translating: the guide's direction u, an angle in the guide body's frame [rad].
  double axis = 0.0;
  /// Oscillating: the follower's body, and the body its angle is measured from.
  int follower = kin::kGround;
  int relative_to = kin::kGround;
  /// Follower coordinate at s = 0: u . (P - Q) [m] (translating) or theta_f - theta_ref [rad].
  double base = 0.0;
  bool clockwise = false;  ///< the cam turns clockwise (sigma = -1)
  double cam_zero = 0.0;   ///< cam angle where the program's theta = 0 [rad]
  /// The motion program: lifts in m (translating) or rad (oscillating), angles in rad.
  std::vector<cam::Segment> motion;
  /// Radius of the follower's roller [m], >= 0; 0: a knife edge. Drawing only (the motion is the
  /// program's whatever the roller), as kin::ConstraintDrawing::Cam.
  double roller_radius = 0.0;
  /// Oscillating: the roller centre (or knife tip) on the follower's body, for drawings; none:
  /// the cam is not drawn. Translating: unused, the roller centre is `point`.
  std::optional<kin::BodyPoint> roller;
  /// A flat-faced follower (drawing only, as the roller): translating, its face is the line
  /// through `point` across the guide (perpendicular to `axis`); oscillating, the line through
  /// `face_point` (a point of the follower's body) at `face_angle` [rad] in the follower's frame,
  /// both required. No roller then (`roller_radius` 0, no `roller`).
  bool flat_face = false;
  std::optional<kin::BodyPoint> face_point;
  std::optional<double> face_angle;
};

/// Builds a cam follower between bodies of `model`.
/// @throws kin::ElementError (field "cam", "point", "guide", "follower", "relative_to", "motion",
///         "roller_radius", "roller", "face_point", "face_angle") for a body not in the model, a follower on the
///         cam's body, follower and reference the same body, a motion program libcam rejects (its
///         message), a negative or non-finite roller radius, a roller centre not on the
///         follower's body; a flat face with a roller radius > 0 or a roller, an oscillating flat
///         face without a face point on the follower's body or a face angle, a face point or
///         angle without a flat face or on a translating follower.
/// Reaction values: F [N] (translating) or T_f [N m] (oscillating), and T_cam [N m].
/// drawing(): the cam, the roller centre (`point`, or `roller` when given) and the roller radius;
/// for a flat face, the face's point (`point` or `face_point`) and direction.
std::unique_ptr<kin::Constraint> make_cam_follower(const kin::Model& model, const CamFollowerParameters& p);

/// make_cam_follower added to `model` as constraint `name`. @returns its index.
int add_cam_follower(kin::Model& model, std::string name, const CamFollowerParameters& p);

}  // namespace gearkit::elements
