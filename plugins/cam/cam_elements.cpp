// The `cam_follower` element: a cam on one link imposes its motion program s(theta) (libcam's
// MotionProgram) on a follower on another link.
//   translating follower: axis . (P - Q) - base - s(sigma (theta_cam - theta_0)) = 0, where P is
//     the follower point, Q a point of the guide link, axis the guide direction;
//   oscillating follower: theta_f - theta_ref - base - psi(sigma (theta_cam - theta_0)) = 0.
// sigma = +1 for a cam turning counter-clockwise, -1 clockwise. Lifts are lengths (mm by
// default) for a translating follower and angles (deg) for an oscillating one.
#include "cam_elements.hpp"
#include "cam_model.hpp"

#include <gearkit/cam/motion_law.hpp>
#include <gearkit/cam/motion_program.hpp>
#include <gearkit/io/yaml_model.hpp>
#include <gearkit/kin/joints.hpp>

#include <fmt/format.h>

#include <cmath>

namespace gearkit::plugins::cam {

namespace {

using gearkit::cam::MotionProgram;

class CamFollower final : public kin::Constraint {
 public:
  CamFollower(bool translating, kin::BodyPoint follower, kin::BodyPoint guide, Eigen::Vector2d axis, int cam,
              double cam_zero, double sigma, double base, MotionProgram program)
      : translating_(translating), follower_(follower), guide_(guide), axis_(axis.normalized()), cam_(cam),
        cam_zero_(cam_zero), sigma_(sigma), base_(base), program_(std::move(program)) {}

  std::string kind() const override { return "cam_follower"; }
  int equations() const override { return 1; }
  std::vector<int> bodies() const override { return {follower_.body, guide_.body, cam_}; }

  void evaluate(const kin::ConstraintInput& in, kin::ConstraintOutput& out) const override {
    const kin::BodyState& cam = in.bodies[2];
    const gearkit::cam::Motion s = program_.at(sigma_ * (cam.theta - cam_zero_));
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

 private:
  bool translating_;
  kin::BodyPoint follower_, guide_;
  Eigen::Vector2d axis_;
  int cam_;
  double cam_zero_, sigma_, base_;
  MotionProgram program_;
};

std::unique_ptr<kin::Constraint> create_cam_follower(const kin::ElementRequest& request) {
  io::MapReader r(request.node, request.file, "cam_follower");
  r.string("type");
  r.optional_string("name");
  const int cam = request.body_index(r.string("cam"));
  const bool translating = r.choice("follower_type", {"translating", "oscillating"}) == "translating";
  const double sigma = r.choice("direction", {"ccw", "cw"}, std::string("ccw")) == "ccw" ? 1.0 : -1.0;
  const double cam_zero = r.quantity_or("cam_zero", io::Quantity::angle, "deg", 0.0);
  kin::BodyPoint follower, guide;
  Eigen::Vector2d axis(1.0, 0.0);
  double base = 0.0;
  if (translating) {
    follower = request.body_point(r.node("point"));
    guide = request.body_point(r.node("guide"));
    const double a = r.quantity("axis", io::Quantity::angle, "deg");
    axis = {std::cos(a), std::sin(a)};
    base = r.quantity("base", io::Quantity::length, "mm");
  } else {
    follower.body = request.body_index(r.string("follower"));
    guide.body = r.has("relative_to") ? request.body_index(r.string("relative_to")) : kin::kGround;
    base = r.quantity("base", io::Quantity::angle, "deg");
  }
  if (follower.body == cam) io::fail_at(r.mark(), "expected the follower on another link than the cam");
  const io::SourceMark program_mark = r.mark("motion");
  // The solver works in SI: translating lifts stay in metres.
  std::vector<gearkit::cam::Segment> segments = read_motion_segments(r, !translating, 1.0);
  r.finish();
  try {
    return std::make_unique<CamFollower>(translating, follower, guide, axis, cam, cam_zero, sigma, base,
                                         MotionProgram(std::move(segments)));
  } catch (const gearkit::cam::ProgramError& e) {
    io::fail_at(program_mark, fmt::format("invalid cam program: {}", e.what()));
  }
}

}  // namespace

void register_elements(kin::PluginRegistrar& registrar) {
  registrar.add_element_type({"cam_follower",
                              "A cam on one link driving a translating or oscillating follower by its motion program "
                              "s(theta) (libcam)",
                              &create_cam_follower});
}

}  // namespace gearkit::plugins::cam
