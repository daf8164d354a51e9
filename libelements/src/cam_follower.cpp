#include <gearkit/elements/cam_follower.hpp>

#include "checks.hpp"

#include <fmt/format.h>

#include <cmath>

namespace gearkit::elements {

namespace {

// What drawings show: the roller centre, or the flat face (translating: across the guide, in
// the guide's frame, which the follower's face keeps perpendicular to its travel).
std::optional<kin::ConstraintDrawing::Cam> cam_drawing(const CamFollowerParameters& p) {
  using Face = kin::ConstraintDrawing::Cam::Face;
  const bool translating = p.path == FollowerPath::translating;
  const std::optional<kin::BodyPoint> contact = translating ? std::optional(p.point) : p.flat_face ? p.face_point : p.roller;
  if (!contact) return std::nullopt;
  kin::ConstraintDrawing::Cam cam{p.cam, *contact, p.roller_radius, std::nullopt};
  if (p.flat_face)
    cam.face = translating ? Face{p.guide.body, Eigen::Vector2d(-std::sin(p.axis), std::cos(p.axis))}
                           : Face{p.follower, Eigen::Vector2d(std::cos(*p.face_angle), std::sin(*p.face_angle))};
  return cam;
}

class CamFollower final : public kin::Constraint {
 public:
  CamFollower(const CamFollowerParameters& p, cam::MotionProgram program)
      : translating_(p.path == FollowerPath::translating),
        follower_(translating_ ? p.point : kin::BodyPoint{p.follower, {}}),
        guide_(translating_ ? p.guide : kin::BodyPoint{p.relative_to, {}}),
        axis_(std::cos(p.axis), std::sin(p.axis)), cam_(p.cam), cam_zero_(p.cam_zero),
        sigma_(p.clockwise ? -1.0 : 1.0), base_(p.base), program_(std::move(program)) {
    drawing_.cam = cam_drawing(p);
  }

  std::string kind() const override { return "cam_follower"; }
  int equations() const override { return 1; }
  std::vector<int> bodies() const override { return {follower_.body, guide_.body, cam_}; }
  kin::ConstraintDrawing drawing() const override { return drawing_; }

  void evaluate(const kin::ConstraintInput& in, kin::ConstraintOutput& out) const override {
    const kin::BodyState& cam = in.bodies[2];
    const cam::Motion s = program_.at(sigma_ * (cam.theta - cam_zero_));
    if (translating_) {
      kin::projection_row(in, follower_.local, guide_.local, axis_, 0, out);
    } else {
      out.phi(0) = in.bodies[0].theta - in.bodies[1].theta;
      out.phi_q.setZero();
      out.phi_q(0, 2) = 1.0;
      out.phi_q(0, 5) = -1.0;
      out.phi_t(0) = 0.0;
      out.gamma(0) = 0.0;
    }
    out.phi(0) -= base_ + s.s;
    out.phi_q(0, 6) = 0.0;
    out.phi_q(0, 7) = 0.0;
    out.phi_q(0, 8) = -sigma_ * s.ds;
    // d2/dt2 s(sigma theta) = s'' omega^2 + sigma s' theta_dd; the first term goes to gamma.
    out.gamma(0) += s.d2s * cam.omega * cam.omega;
  }

  kin::Reaction reaction(const kin::ConstraintInput& in, std::span<const double> lambda) const override {
    const double l = lambda[0];
    const cam::Motion s = program_.at(sigma_ * (in.bodies[2].theta - cam_zero_));
    kin::Reaction r;
    if (translating_) {
      r.force = -l * in.bodies[1].rotated(axis_);
      r.values.push_back({"F", "N", -l, "force of the cam on the follower along its guide"});
    } else {
      r.moment = -l;
      r.values.push_back({"T_f", "N m", -l, "torque of the cam on the follower about its pivot"});
    }
    r.values.push_back({"T_cam", "N m", sigma_ * s.ds * l, "torque of the follower on the cam"});
    return r;
  }

 private:
  bool translating_;
  kin::BodyPoint follower_, guide_;
  Eigen::Vector2d axis_;
  int cam_;
  double cam_zero_, sigma_, base_;
  cam::MotionProgram program_;
  kin::ConstraintDrawing drawing_;
};

std::string body_name(const kin::Model& model, int b) {
  return b == kin::kGround ? std::string("ground") : model.bodies()[static_cast<std::size_t>(b)].name;
}

// The drawing keys: a roller or a flat face, each on the follower.
void check_drawing(const kin::Model& model, const CamFollowerParameters& p) {
  if (!(p.roller_radius >= 0.0) || !std::isfinite(p.roller_radius))
    throw kin::ElementError("roller_radius", fmt::format("'roller_radius': expected a radius >= 0, found {:g} mm", 1e3 * p.roller_radius));
  if (p.flat_face && p.roller_radius > 0.0)
    throw kin::ElementError("roller_radius", fmt::format("'roller_radius': expected none with face: flat (the face touches the cam), "
                                                         "found {:g} mm", 1e3 * p.roller_radius));
  if (p.flat_face && p.roller)
    throw kin::ElementError("roller", "'roller': expected none with face: flat (face_point gives the face), found a roller centre");
  const bool oscillating_face = p.flat_face && p.path == FollowerPath::oscillating;
  for (const auto& [given, key] : {std::pair{p.face_point.has_value(), "face_point"}, std::pair{p.face_angle.has_value(), "face_angle"}})
    if (given && !oscillating_face)
      throw kin::ElementError(key, fmt::format("'{}': {}", key,
                                               p.flat_face ? "expected none on a translating follower (its face is the line through "
                                                             "'point' across the guide), found one"
                                                           : "expected it with face: flat only, found a roller follower"));
  if (oscillating_face) {
    if (!p.face_point) throw kin::ElementError("face_point", "expected 'face_point' (a point of the follower's face) with face: flat");
    if (!p.face_angle || !std::isfinite(*p.face_angle))
      throw kin::ElementError("face_angle", "expected 'face_angle' (the face's direction on the follower, deg) with face: flat");
    check_body(model, p.face_point->body, "face_point", true);
    if (p.face_point->body != p.follower)
      throw kin::ElementError("face_point", fmt::format("'face_point': expected a point of the follower '{}', found a point of '{}'",
                                                        body_name(model, p.follower), body_name(model, p.face_point->body)));
  }
}

void check_parameters(const kin::Model& model, const CamFollowerParameters& p) {
  check_body(model, p.cam, "cam", true);
  if (p.path == FollowerPath::translating) {
    check_body(model, p.point.body, "point", false);
    check_body(model, p.guide.body, "guide", true);
    if (p.point.body == p.cam) throw kin::ElementError("point", "expected the follower on another link than the cam");
    if (p.point.body == p.guide.body) throw kin::ElementError("guide", "expected the guide on another link than the follower");
  } else {
    check_body(model, p.follower, "follower", false);
    check_body(model, p.relative_to, "relative_to", true);
    if (p.follower == p.cam) throw kin::ElementError("follower", "expected the follower on another link than the cam");
    if (p.follower == p.relative_to)
      throw kin::ElementError("relative_to", "expected the follower's angle relative to another link");
    if (p.roller && p.roller->body != p.follower) {
      check_body(model, p.roller->body, "roller", true);
      throw kin::ElementError("roller", fmt::format("'roller': expected a point of the follower '{}', found a point of '{}'",
                                                    body_name(model, p.follower), body_name(model, p.roller->body)));
    }
  }
  check_drawing(model, p);
}

}  // namespace

std::unique_ptr<kin::Constraint> make_cam_follower(const kin::Model& model, const CamFollowerParameters& p) {
  check_parameters(model, p);
  try {
    return std::make_unique<CamFollower>(p, cam::MotionProgram(p.motion));
  } catch (const cam::ProgramError& e) {
    throw kin::ElementError("motion", fmt::format("invalid cam program: {}", e.what()));
  }
}

int add_cam_follower(kin::Model& model, std::string name, const CamFollowerParameters& p) {
  return add_element(model, std::move(name), make_cam_follower(model, p));
}

}  // namespace gearkit::elements
