#include "cam_model.hpp"

#include <gearkit/io/error.hpp>
#include <gearkit/io/yaml_model.hpp>

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <numbers>

namespace gearkit::plugins::cam {

namespace gc = gearkit::cam;

namespace {

constexpr double kMm = 1000;  // SI metres to millimetres

double length_mm(io::MapReader& r, const std::string& key, double default_mm) {
  return r.quantity_or(key, io::Quantity::length, "mm", default_mm / kMm) * kMm;
}

gc::TableEnds table_ends(const std::string& s) {
  if (s == "natural") return gc::TableEnds::natural;
  if (s == "periodic") return gc::TableEnds::periodic;
  return gc::TableEnds::zero_slope;
}

/// One motion segment. Lifts are lengths for translating followers and angles for oscillating ones.
gc::Segment read_segment(const YAML::Node& node, const std::string& file, bool angular_lift, double metres_to_model) {
  io::MapReader r(node, file, "motion segment");
  gc::Segment seg;
  const std::string type = r.choice("type", {"rise", "dwell", "return", "table"});
  seg.kind = type == "rise" ? gc::SegmentKind::rise
             : type == "dwell" ? gc::SegmentKind::dwell
             : type == "return" ? gc::SegmentKind::fall
                                : gc::SegmentKind::table;
  seg.start = r.quantity("from", io::Quantity::angle, "deg");
  seg.end = r.quantity("to", io::Quantity::angle, "deg");
  const io::Quantity lift_q = angular_lift ? io::Quantity::angle : io::Quantity::length;
  const std::string lift_unit = angular_lift ? "deg" : "mm";
  const double to_model = angular_lift ? 1 : metres_to_model;  // oscillating: rad
  if (seg.kind == gc::SegmentKind::rise || seg.kind == gc::SegmentKind::fall) {
    const auto names = gc::law_names();
    seg.law = *gc::law_from_name(r.choice("law", names, std::string("cycloidal")));
    if (seg.kind == gc::SegmentKind::rise)
      seg.lift = r.quantity("lift", lift_q, lift_unit) * to_model;
    else if (const auto lift = r.optional_quantity("lift", lift_q, lift_unit))
      seg.lift = *lift * to_model;
    else
      seg.lift = NAN;  // no lift given: back to the base circle, resolved by the caller
  }
  if (seg.kind == gc::SegmentKind::table) {
    seg.table_ends = table_ends(r.choice("ends", {"zero_slope", "natural", "periodic"}, std::string("zero_slope")));
    for (const YAML::Node& point : r.sequence("points")) {
      if (!point.IsSequence() || point.size() != 2)
        io::fail_at(io::mark_of(point, file), "expected a point [angle, value], e.g. [130 deg, 1.65 deg]");
      gc::TablePoint p;
      p.theta = io::scalar_quantity(point[0], file, io::Quantity::angle, "deg");
      p.s = io::scalar_quantity(point[1], file, lift_q, lift_unit) * to_model;
      seg.table.push_back(p);
    }
  }
  r.finish();
  return seg;
}

}  // namespace

std::vector<gc::Segment> read_motion_segments(io::MapReader& r, bool angular_lift, double metres_to_model,
                                              std::vector<io::SourceMark>* marks) {
  std::vector<gc::Segment> segments;
  double level = 0;
  for (const YAML::Node& item : r.sequence("motion")) {
    gc::Segment seg = read_segment(item, r.file(), angular_lift, metres_to_model);
    if (seg.kind == gc::SegmentKind::fall && std::isnan(seg.lift)) seg.lift = level;
    if (seg.kind == gc::SegmentKind::rise) level += seg.lift;
    if (seg.kind == gc::SegmentKind::fall) level -= seg.lift;
    if (seg.kind == gc::SegmentKind::table && !seg.table.empty()) level = seg.table.back().s;
    segments.push_back(seg);
    if (marks) marks->push_back(io::mark_of(item, r.file()));
  }
  return segments;
}

CamModel load_cam_model(const std::string& path) {
  const io::YamlDocument doc = io::load_yaml_file(path);
  io::MapReader root(doc.root, doc.file, "cam model");
  // The one-dwell program only fills the slot until the file's program is read and checked below.
  gc::Segment whole_turn;
  whole_turn.end = 2 * std::numbers::pi;
  CamModel model(gc::CamDesign{gc::MotionProgram({whole_turn}), gc::Follower{}, 1, gc::Rotation::ccw});
  model.name = root.optional_string("name").value_or("");

  io::MapReader follower = root.map("follower");
  gc::Follower& f = model.design.follower;
  f.motion = follower.choice("type", {"translating", "oscillating"}) == "oscillating"
                 ? gc::FollowerMotion::oscillating
                 : gc::FollowerMotion::translating;
  const std::string contact = follower.choice("contact", {"knife_edge", "roller", "flat_face"});
  f.contact = contact == "roller" ? gc::Contact::roller
              : contact == "flat_face" ? gc::Contact::flat_face
                                       : gc::Contact::knife_edge;
  const bool oscillating = f.motion == gc::FollowerMotion::oscillating;
  if (f.contact == gc::Contact::roller) f.roller_radius = length_mm(follower, "roller_radius", 0);
  if (!oscillating) f.offset = length_mm(follower, "offset", 0);
  if (oscillating) {
    f.pivot_distance = follower.quantity("pivot_distance", io::Quantity::length, "mm") * kMm;
    if (f.contact == gc::Contact::flat_face)
      f.face_offset = length_mm(follower, "face_offset", 0);
    else
      f.arm_length = follower.quantity("arm_length", io::Quantity::length, "mm") * kMm;
  }
  follower.finish();

  io::MapReader cam = root.map("cam");
  model.design.base_radius = cam.quantity("base_radius", io::Quantity::length, "mm") * kMm;
  model.design.rotation = cam.choice("rotation", {"ccw", "cw"}, std::string("ccw")) == "cw" ? gc::Rotation::cw
                                                                                              : gc::Rotation::ccw;
  model.omega = cam.optional_quantity("speed", io::Quantity::angular_velocity, "rpm");
  // Usual limits: 30 deg for translating followers, 45 deg for oscillating ones (Norton, sec. 8.9).
  model.pressure_angle_limit = cam.quantity_or("pressure_angle_limit", io::Quantity::angle, "deg",
                                               (oscillating ? 45.0 : 30.0) * std::numbers::pi / 180);
  cam.finish();

  std::vector<io::SourceMark> segment_marks;
  const io::SourceMark motion_mark = root.mark("motion");
  std::vector<gc::Segment> segments = read_motion_segments(root, oscillating, kMm, &segment_marks);

  if (const auto drawing = root.optional_node("output")) {
    io::MapReader out(*drawing, doc.file, "output");
    model.tolerance_mm = length_mm(out, "tolerance", 1e-3);
    if (!(model.tolerance_mm >= 1e-6 && model.tolerance_mm <= 1))
      io::fail_at(out.mark("tolerance"), fmt::format("expected a fit tolerance from 1e-6 mm to 1 mm, found {} mm",
                                                     model.tolerance_mm));
    if (const auto n = out.optional_integer("samples")) {
      if (*n < 36 || *n > 100000)
        io::fail_at(out.mark("samples"), fmt::format("expected from 36 to 100000 samples, found {}", *n));
      model.samples = static_cast<int>(*n);
    }
    model.follower_at = out.quantity_or("follower_at", io::Quantity::angle, "deg", 0);
    if (const auto rc = out.optional_quantity("cutter_radius", io::Quantity::length, "mm")) {
      model.cutter_radius_mm = *rc * kMm;
      if (!(*model.cutter_radius_mm > 0))
        io::fail_at(out.mark("cutter_radius"), fmt::format("expected a cutter radius > 0, found {} mm",
                                                           *model.cutter_radius_mm));
    }
    out.finish();
  }
  root.finish();

  try {
    model.design.program = gc::MotionProgram(std::move(segments));
  } catch (const gc::ProgramError& e) {
    const io::SourceMark where =
        e.segment() >= 0 && e.segment() < static_cast<int>(segment_marks.size()) ? segment_marks[e.segment()] : motion_mark;
    io::fail_at(where, e.what());
  }
  try {
    gc::validate(model.design);
  } catch (const gc::DesignError& e) {
    const std::map<std::string, std::pair<const char*, const char*>> where{
        {"base_radius", {"cam", "base_radius"}},       {"roller_radius", {"follower", "roller_radius"}},
        {"offset", {"follower", "offset"}},            {"pivot_distance", {"follower", "pivot_distance"}},
        {"arm_length", {"follower", "arm_length"}},    {"face_offset", {"follower", "face_offset"}}};
    io::SourceMark mark = motion_mark;
    if (const auto it = where.find(e.field()); it != where.end()) {
      io::MapReader section(doc.root[it->second.first], doc.file, it->second.first);
      mark = section.mark(it->second.second);
    }
    io::fail_at(mark, fmt::format("'{}': {}", e.field(), e.what()));
  }
  return model;
}

}  // namespace gearkit::plugins::cam
