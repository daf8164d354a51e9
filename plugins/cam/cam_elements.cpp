// The `cam_follower` entry of mechanism files (docs/kin.md), read into
// gearkit::elements::CamFollowerParameters and built by make_cam_follower. The motion program
// is written exactly as in `gearkit cam` files (cam_model.hpp). Lifts are lengths (mm by
// default) for a translating follower and angles (deg) for an oscillating one.
#include "cam_elements.hpp"
#include "cam_model.hpp"

#include <gearkit/elements/cam_follower.hpp>
#include <gearkit/mechanism/element_type.hpp>

namespace gearkit::plugins::cam {

namespace {

std::unique_ptr<kin::Constraint> read_cam_follower(mechanism::ElementReader& reader) {
  io::MapReader& keys = reader.keys();
  elements::CamFollowerParameters p;
  p.cam = reader.link("cam");
  const bool translating = keys.choice("follower_type", {"translating", "oscillating"}) == "translating";
  p.path = translating ? elements::FollowerPath::translating : elements::FollowerPath::oscillating;
  p.clockwise = keys.choice("direction", {"ccw", "cw"}, std::string("ccw")) == "cw";
  p.cam_zero = keys.quantity_or("cam_zero", io::Quantity::angle, "deg", 0.0);
  if (translating) {
    p.point = reader.point("point");
    p.guide = reader.point("guide");
    p.axis = keys.quantity("axis", io::Quantity::angle, "deg");
    p.base = keys.quantity("base", io::Quantity::length, "mm");
  } else {
    p.follower = reader.link("follower");
    p.relative_to = reader.link_or("relative_to", kin::kGround);
    p.base = keys.quantity("base", io::Quantity::angle, "deg");
    if (keys.has("roller")) p.roller = reader.point("roller");
  }
  p.roller_radius = keys.quantity_or("roller_radius", io::Quantity::length, "mm", 0.0);
  p.flat_face = keys.choice("face", {"roller", "flat"}, std::string("roller")) == "flat";
  // Read whenever given, so that the builder says why they do not belong (a roller follower, a
  // translating one) rather than "unknown key".
  if (keys.has("face_point")) p.face_point = reader.point("face_point");
  p.face_angle = keys.optional_quantity("face_angle", io::Quantity::angle, "deg");
  // The solver works in SI: translating lifts stay in metres.
  p.motion = read_motion_segments(keys, !translating, 1.0);
  return elements::make_cam_follower(reader.model(), p);
}

}  // namespace

void register_elements(plugin::PluginRegistrar& registrar) {
  registrar.add_element_type({"cam_follower",
                              "A cam on one link driving a translating or oscillating follower by its motion program "
                              "s(theta) (libcam)",
                              &read_cam_follower});
}

}  // namespace gearkit::plugins::cam
