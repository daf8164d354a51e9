#pragma once
// A cam and its follower, and the geometry of their contact at any cam angle.
//
// Frames and units: lengths in mm, angles in rad. The cam turns about the origin. In the fixed
// frame a translating follower moves along +y on the line x = offset; an oscillating follower's
// pivot is at (pivot_distance, 0) and its arm reaches up and to the left towards the cam, the
// roller centre at pivot + arm_length (-cos gamma, sin gamma), where gamma = gamma_0 + psi grows
// as the follower rises (psi = the motion program's s, in rad). The cam frame turns with the cam;
// profiles are given in it, at cam angle 0 aligned with the fixed frame.
#include <gearkit/cam/motion_program.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace gearkit::cam {

enum class FollowerMotion { translating, oscillating };
enum class Contact { knife_edge, roller, flat_face };
enum class Rotation { ccw, cw };

/// How the follower is kept on the cam: by its spring (force closure), or by the cam itself
/// (form closure): a groove whose two walls take the roller, or a conjugate cam pushing a second
/// roller of the same follower back.
enum class Closure { spring, groove, conjugate };

/// Which surface contact_at() describes: the cam (the groove's inner wall), the groove's outer
/// wall, or the conjugate cam (the second roller's).
enum class Surface { cam, groove_outer_wall, conjugate_cam };

/// The second roller of a conjugate pair, on the same follower.
struct SecondRoller {
  double roller_radius = 0;  ///< [mm]; 0: the same as the first roller
  double arm_length = 0;     ///< oscillating: pivot to second roller centre [mm]
  double arm_angle = 0;      ///< oscillating: angle of the second arm from the first, about the pivot, in the sense
                             ///< psi grows [rad]
  double distance = 0;       ///< translating: centre distance between the rollers along the axis, the second
                             ///< roller on the cam centre's far side [mm]
};

struct Follower {
  FollowerMotion motion = FollowerMotion::translating;
  Contact contact = Contact::roller;
  double roller_radius = 0;   ///< roller [mm]
  double offset = 0;          ///< translating: follower axis at x = offset [mm]
  double pivot_distance = 0;  ///< oscillating: cam centre to pivot [mm]
  double arm_length = 0;      ///< oscillating: pivot to roller centre (or knife tip) [mm]
  double face_offset = 0;     ///< oscillating flat face: signed distance pivot to face line [mm]
  Closure closure = Closure::spring;
  SecondRoller second;        ///< conjugate cams (roller followers)
  Surface surface = Surface::cam;  ///< the surface contact_at() describes (see outer_wall_of, conjugate_cam_of)
};

struct CamDesign {
  MotionProgram program;
  Follower follower;
  double base_radius = 0;  ///< base circle of the profile (smallest radius of the cam) [mm]
  Rotation rotation = Rotation::ccw;
};

/// An impossible design; `field` names the offending quantity ("roller_radius", "base_radius",
/// "offset", "pivot_distance", "arm_length", "face_offset", "motion").
class DesignError : public std::invalid_argument {
 public:
  DesignError(std::string field, const std::string& message)
      : std::invalid_argument(message), field_(std::move(field)) {}
  const std::string& field() const { return field_; }

 private:
  std::string field_;
};

/// The same design seen on the groove's outer wall (contact_at gives the outer wall's contact:
/// the normal reversed, the contact R_r beyond the roller centre).
CamDesign outer_wall_of(const CamDesign& design);
/// The same design seen on the conjugate cam (contact_at gives the second roller's contact).
CamDesign conjugate_cam_of(const CamDesign& design);

/// Checks that the follower can touch the cam everywhere.
/// @throws DesignError for a negative or non-finite radius or length; a base circle not larger
///         than zero or smaller than the roller; a translating offset not smaller than the prime
///         circle radius; an oscillating follower whose roller cannot reach the prime circle
///         (|pivot_distance - arm_length| >= prime radius or pivot_distance + arm_length <= it),
///         or whose arm would swing through the line of centres (gamma_0 + max psi >= 180 deg);
///         an oscillating flat face that cannot touch the base circle; a groove or conjugate
///         cam without a roller; a second roller that is missing, would reach the cam centre
///         (closer than its radius) or would push the follower the same way as the first.
void validate(const CamDesign& design);

struct Vec2 {
  double x = 0, y = 0;
};

/// The contact at one cam angle (all vectors in the cam frame unless noted).
struct ContactState {
  double theta = 0;       ///< cam angle [rad]
  Motion motion;          ///< follower coordinate and derivatives per rad
  Vec2 pitch;             ///< roller centre or knife tip (flat face: the contact point)
  Vec2 pitch_tangent;     ///< d(pitch)/dtheta
  Vec2 contact;           ///< point of the profile touched (the analytic profile)
  Vec2 follower_point;    ///< roller centre / knife tip / contact point in the fixed frame
  double pressure_angle = 0;   ///< signed angle between the contact normal and the follower's path [rad]
  double curvature_pitch = 0;  ///< 1/rho of the pitch curve, > 0 convex [1/mm]
  double curvature_profile = 0;  ///< 1/rho of the profile, > 0 convex [1/mm]
  double face_position = 0;  ///< flat face: contact along the face from the follower axis or pivot [mm]
  bool envelope_regular = true;  ///< oscillating flat face: the face normal turns monotonically here
  bool folds = false;        ///< the profile folds here (undercut: the roller larger than the curve's radius,
                             ///< a flat face's envelope with rho <= 0)
  // Statics (fixed frame): what the dynamics needs.
  Vec2 contact_fixed;        ///< the contact point [mm]
  Vec2 normal;               ///< unit normal at the contact, from the cam into the follower
  Vec2 point_per_s;          ///< displacement of the follower's point carrying the force (roller centre, knife
                             ///< tip, face point at the contact) per unit of s [mm per mm or per rad]
  double spin_per_s = 0;     ///< the follower's rotation per unit of s [rad per rad]: 0 translating, -1 oscillating
};

/// The contact geometry at cam angle theta. Requires validate(design) to have passed.
ContactState contact_at(const CamDesign& design, double theta);

/// The same for a given follower motion at theta: at a break of the program, its limit from
/// either side (MotionProgram::limits_at).
ContactState contact_at(const CamDesign& design, double theta, const Motion& motion);

/// A corner of the pitch curve (the knife edge's profile), where the follower's velocity jumps.
struct PitchCorner {
  double theta = 0;        ///< cam angle [rad], as in MotionProgram::breaks (start .. start + 2 pi)
  Vec2 point;              ///< the corner, cam frame [mm]
  Vec2 before, after;      ///< unit tangents d(pitch)/dtheta just before and after it (cam frame)
  double turn = 0;         ///< angle from `before` to `after`, > 0 where the curve turns towards the
                           ///< cam (a convex corner: a roller cannot follow it, the profile is cut
                           ///< sharp there), < 0 away from it (the profile has a hollow of the
                           ///< roller's radius) [rad]
};

/// Every corner of the pitch curve of the surface the design describes (none for flat faces,
/// whose velocity jumps make a straight flank or a cusp of the envelope instead).
std::vector<PitchCorner> pitch_corners(const CamDesign& design);

/// The radius of the roller touching the surface contact_at() describes (the second roller's on
/// the conjugate cam); 0 for knife edges and flat faces [mm].
double roller_radius(const CamDesign& design);

/// +1 for a counter-clockwise cam, -1 for clockwise.
inline double rotation_sign(Rotation r) { return r == Rotation::ccw ? 1.0 : -1.0; }

}  // namespace gearkit::cam
