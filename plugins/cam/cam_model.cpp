#include "cam_model.hpp"

#include <gearkit/io/error.hpp>
#include <gearkit/io/limits.hpp>
#include <gearkit/io/yaml_model.hpp>

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <numbers>

namespace gearkit::plugins::cam {

namespace gc = gearkit::cam;

namespace {

constexpr double kMm = 1000;  // SI metres to millimetres
constexpr double kDeg = std::numbers::pi / 180;

double length_mm(io::MapReader& r, const std::string& key, double default_mm) {
  return r.quantity_or(key, io::Quantity::length, "mm", default_mm / kMm) * kMm;
}

/// A length of the cam's geometry: finite, and at most kMaxLengthMm (docs/cli.md), so that the
/// fit tolerance stays far above the rounding of coordinates.
void check_length(io::MapReader& r, const std::string& key, double mm) {
  if (std::abs(mm) > kMaxLengthMm)
    io::fail_at(r.mark(key), fmt::format("expected a length of at most {} mm, found {:.6g} mm", kMaxLengthMm, mm));
}

gc::TableEnds table_ends(const std::string& s) {
  if (s == "natural") return gc::TableEnds::natural;
  if (s == "periodic") return gc::TableEnds::periodic;
  return gc::TableEnds::zero_slope;
}

gc::TableInterpolation interpolation(const std::string& s) {
  if (s == "cubic") return gc::TableInterpolation::cubic;
  if (s == "bspline") return gc::TableInterpolation::bspline;
  return gc::TableInterpolation::pchip;
}

/// How the follower value and its derivatives are read: lengths (translating, into the model's
/// unit) or angles (oscillating, in rad).
struct LiftUnit {
  io::Quantity quantity;
  std::string unit;
  double to_model;
};

void read_table(io::MapReader& r, const LiftUnit& lift, gc::Segment& seg) {
  seg.table_ends = table_ends(r.choice("ends", {"zero_slope", "natural", "periodic"}, std::string("zero_slope")));
  seg.interpolation = interpolation(r.choice("interpolation", {"pchip", "cubic", "bspline"}, std::string("pchip")));
  for (const YAML::Node& point : r.sequence("points", io::limits::kCamTablePoints, "points")) {
    if (!point.IsSequence() || point.size() != 2)
      io::fail_at(io::mark_of(point, r.file()), "expected a point [angle, value], e.g. [130 deg, 1.65 deg]");
    gc::TablePoint p;
    p.theta = io::scalar_quantity(point[0], r.file(), io::Quantity::angle, "deg");
    p.s = io::scalar_quantity(point[1], r.file(), lift.quantity, lift.unit) * lift.to_model;
    seg.table.push_back(p);
  }
}

/// `start:` or `end:` of a polynomial segment: s in the lift's unit, v, a, j plain numbers in
/// the lift's unit per radian^n of cam angle.
gc::EndConditions read_conditions(io::MapReader& parent, const std::string& key, const LiftUnit& lift, bool required) {
  gc::EndConditions e;
  const auto node = parent.optional_node(key);
  if (!node) {
    if (required) io::fail_at(parent.mark(), fmt::format("expected '{}: {{s: ..., v: 0, a: 0}}'", key));
    return e;
  }
  io::MapReader r(*node, parent.file(), key);
  if (const auto s = r.optional_quantity("s", lift.quantity, lift.unit)) e.s = *s * lift.to_model;
  // Derivatives per radian of cam angle, in the lift's unit: deg/rad^n for oscillating followers.
  const double scale = lift.quantity == io::Quantity::angle ? kDeg : lift.to_model / kMm;
  if (const auto v = r.optional_number("v")) e.v = *v * scale;
  if (const auto a = r.optional_number("a")) e.a = *a * scale;
  if (const auto j = r.optional_number("j")) e.j = *j * scale;
  r.finish();
  return e;
}

/// One motion segment. Lifts are lengths for translating followers and angles for oscillating ones.
gc::Segment read_segment(const YAML::Node& node, const std::string& file, bool angular_lift, double metres_to_model) {
  io::MapReader r(node, file, "motion segment");
  gc::Segment seg;
  const std::string type = r.choice("type", {"rise", "dwell", "return", "table", "polynomial"});
  seg.kind = type == "rise"     ? gc::SegmentKind::rise
             : type == "dwell"  ? gc::SegmentKind::dwell
             : type == "return" ? gc::SegmentKind::fall
             : type == "table"  ? gc::SegmentKind::table
                                : gc::SegmentKind::polynomial;
  seg.start = r.quantity("from", io::Quantity::angle, "deg");
  seg.end = r.quantity("to", io::Quantity::angle, "deg");
  const LiftUnit lift = angular_lift ? LiftUnit{io::Quantity::angle, "deg", 1.0}
                                     : LiftUnit{io::Quantity::length, "mm", metres_to_model};
  if (seg.kind == gc::SegmentKind::rise || seg.kind == gc::SegmentKind::fall) {
    const auto names = gc::law_names();
    seg.law = *gc::law_from_name(r.choice("law", names, std::string("cycloidal")));
    if (seg.kind == gc::SegmentKind::rise)
      seg.lift = r.quantity("lift", lift.quantity, lift.unit) * lift.to_model;
    else if (const auto l = r.optional_quantity("lift", lift.quantity, lift.unit))
      seg.lift = *l * lift.to_model;
    else
      seg.lift = NAN;  // no lift given: back to the base circle, resolved by the caller
  }
  if (seg.kind == gc::SegmentKind::table) read_table(r, lift, seg);
  if (seg.kind == gc::SegmentKind::polynomial) {
    seg.at_start = read_conditions(r, "start", lift, false);
    seg.at_end = read_conditions(r, "end", lift, true);
  }
  r.finish();
  return seg;
}

void read_follower(io::MapReader& root, CamModel& model) {
  io::MapReader follower = root.map("follower");
  gc::Follower& f = model.design.follower;
  f.motion = follower.choice("type", {"translating", "oscillating"}) == "oscillating" ? gc::FollowerMotion::oscillating
                                                                                      : gc::FollowerMotion::translating;
  const std::string contact = follower.choice("contact", {"knife_edge", "roller", "flat_face"});
  f.contact = contact == "roller"      ? gc::Contact::roller
              : contact == "flat_face" ? gc::Contact::flat_face
                                       : gc::Contact::knife_edge;
  const bool oscillating = f.motion == gc::FollowerMotion::oscillating;
  auto length = [&](const std::string& key, std::optional<double> default_mm) {
    const double mm = default_mm ? length_mm(follower, key, *default_mm)
                                 : follower.quantity(key, io::Quantity::length, "mm") * kMm;
    check_length(follower, key, mm);
    return mm;
  };
  if (f.contact == gc::Contact::roller) f.roller_radius = length("roller_radius", 0.0);
  if (!oscillating) f.offset = length("offset", 0.0);
  if (oscillating) {
    f.pivot_distance = length("pivot_distance", std::nullopt);
    if (f.contact == gc::Contact::flat_face)
      f.face_offset = length("face_offset", 0.0);
    else
      f.arm_length = length("arm_length", std::nullopt);
    model.pivot_radius_mm = length("pivot_radius", 0.0);
    if (model.pivot_radius_mm < 0)
      io::fail_at(follower.mark("pivot_radius"), fmt::format("expected a pivot radius >= 0, found {:.6g} mm",
                                                             model.pivot_radius_mm));
  }
  read_second_roller(follower, model);
  follower.finish();
}

void read_cam(io::MapReader& root, CamModel& model) {
  io::MapReader cam = root.map("cam");
  model.design.base_radius = cam.quantity("base_radius", io::Quantity::length, "mm") * kMm;
  check_length(cam, "base_radius", model.design.base_radius);
  model.design.rotation = cam.choice("rotation", {"ccw", "cw"}, std::string("ccw")) == "cw" ? gc::Rotation::cw
                                                                                              : gc::Rotation::ccw;
  const std::string type = cam.choice("type", {"plate", "groove", "conjugate"}, std::string("plate"));
  const gc::Closure closure = type == "groove"      ? gc::Closure::groove
                              : type == "conjugate" ? gc::Closure::conjugate
                                                    : gc::Closure::spring;
  gc::Follower& f = model.design.follower;
  if (closure == gc::Closure::conjugate && f.second.arm_length == 0 && f.second.distance == 0)
    io::fail_at(cam.mark("type"), "a conjugate cam needs follower.second_roller (distance, or arm_length and arm_angle)");
  if (closure != gc::Closure::conjugate && (f.second.arm_length != 0 || f.second.distance != 0))
    io::fail_at(cam.mark("type"), "follower.second_roller is for cam type conjugate");
  f.closure = closure;
  model.omega = cam.optional_quantity("speed", io::Quantity::angular_velocity, "rpm");
  if (model.omega && !(*model.omega > 0))
    io::fail_at(cam.mark("speed"), fmt::format("expected a cam speed > 0 rpm (the sense of rotation is cam.rotation), "
                                               "found {:.6g} rpm", *model.omega * 30 / std::numbers::pi));
  // Usual limits: 30 deg for translating followers, 45 deg for oscillating ones (Norton, sec. 8.9).
  const bool oscillating = model.design.follower.motion == gc::FollowerMotion::oscillating;
  model.pressure_angle_limit = cam.quantity_or("pressure_angle_limit", io::Quantity::angle, "deg",
                                               (oscillating ? 45.0 : 30.0) * kDeg);
  if (!(model.pressure_angle_limit > 0 && model.pressure_angle_limit < 90 * kDeg))
    io::fail_at(cam.mark("pressure_angle_limit"),
                fmt::format("expected a pressure angle limit between 0 and 90 deg, found {:.6g} deg",
                            model.pressure_angle_limit / kDeg));
  cam.finish();
}

void read_output(io::MapReader& root, CamModel& model) {
  const auto node = root.optional_node("output");
  if (!node) return;
  io::MapReader out(*node, root.file(), "output");
  model.tolerance_mm = length_mm(out, "tolerance", 1e-3);
  if (!(model.tolerance_mm >= 1e-6 && model.tolerance_mm <= 1))
    io::fail_at(out.mark("tolerance"),
                fmt::format("expected a fit tolerance from 1e-6 mm to 1 mm, found {:.6g} mm", model.tolerance_mm));
  if (const auto n = out.optional_integer("samples")) {
    if (*n < 36 || *n > 100000)
      io::fail_at(out.mark("samples"), fmt::format("expected from 36 to 100000 samples, found {}", *n));
    model.samples = static_cast<int>(*n);
  }
  model.follower_at = out.quantity_or("follower_at", io::Quantity::angle, "deg", 0);
  if (const auto rc = out.optional_quantity("cutter_radius", io::Quantity::length, "mm")) {
    model.cutter_radius_mm = *rc * kMm;
    model.cutter_radius_mark = out.mark("cutter_radius");
    if (!(*model.cutter_radius_mm > 0))
      io::fail_at(out.mark("cutter_radius"),
                  fmt::format("expected a cutter radius > 0, found {:.6g} mm", *model.cutter_radius_mm));
    check_length(out, "cutter_radius", *model.cutter_radius_mm);
  }
  out.finish();
}

void build_program(CamModel& model, std::vector<gc::Segment> segments, const std::vector<io::SourceMark>& marks,
                   const io::SourceMark& motion_mark) {
  const bool oscillating = model.design.follower.motion == gc::FollowerMotion::oscillating;
  const gc::ValueUnit unit = oscillating ? gc::ValueUnit{"deg", 1 / kDeg} : gc::ValueUnit{"mm", 1};
  try {
    model.design.program = gc::MotionProgram(std::move(segments), unit);
  } catch (const gc::ProgramError& e) {
    const io::SourceMark where =
        e.segment() >= 0 && e.segment() < static_cast<int>(marks.size()) ? marks[e.segment()] : motion_mark;
    io::fail_at(where, e.what());
  }
  if (!oscillating && model.design.program.max_s() > kMaxLengthMm)
    io::fail_at(motion_mark, fmt::format("expected a lift of at most {} mm, found {:.6g} mm", kMaxLengthMm,
                                         model.design.program.max_s()));
}

void validate_design(const io::YamlDocument& doc, const io::SourceMark& motion_mark, const CamModel& model) {
  try {
    gc::validate(model.design);
  } catch (const gc::DesignError& e) {
    const std::map<std::string, std::pair<const char*, const char*>> where{
        {"base_radius", {"cam", "base_radius"}},       {"roller_radius", {"follower", "roller_radius"}},
        {"offset", {"follower", "offset"}},            {"pivot_distance", {"follower", "pivot_distance"}},
        {"arm_length", {"follower", "arm_length"}},    {"face_offset", {"follower", "face_offset"}},
        {"second_roller", {"follower", "second_roller"}}, {"closure", {"cam", "type"}}};
    io::SourceMark mark = motion_mark;
    if (const auto it = where.find(e.field()); it != where.end()) {
      io::MapReader section(doc.root[it->second.first], doc.file, it->second.first);
      mark = section.mark(it->second.second);
    }
    io::fail_at(mark, fmt::format("'{}': {}", e.field(), e.what()));
  }
}

}  // namespace

std::vector<gc::Segment> read_motion_segments(io::MapReader& r, bool angular_lift, double metres_to_model,
                                              std::vector<io::SourceMark>* marks) {
  std::vector<gc::Segment> segments;
  double level = 0;
  std::size_t table_points = 0;
  for (const YAML::Node& item : r.sequence("motion", io::limits::kCamSegments, "segments")) {
    gc::Segment seg = read_segment(item, r.file(), angular_lift, metres_to_model);
    table_points += seg.table.size();
    if (table_points > io::limits::kCamTablePoints)
      io::fail_at(io::mark_of(item["points"], r.file()),
                  fmt::format("expected at most {} table points in the motion program (all tables together), found "
                              "{} up to this table (docs/cli.md, Limits)",
                              io::limits::kCamTablePoints, table_points));
    if (seg.kind == gc::SegmentKind::fall && std::isnan(seg.lift)) seg.lift = level;
    if (seg.kind == gc::SegmentKind::rise) level += seg.lift;
    if (seg.kind == gc::SegmentKind::fall) level -= seg.lift;
    if (seg.kind == gc::SegmentKind::table && !seg.table.empty()) level = seg.table.back().s;
    if (seg.kind == gc::SegmentKind::polynomial && seg.at_end.s) level = *seg.at_end.s;
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
  read_follower(root, model);
  read_cam(root, model);
  std::vector<io::SourceMark> segment_marks;
  const io::SourceMark motion_mark = root.mark("motion");
  const bool oscillating = model.design.follower.motion == gc::FollowerMotion::oscillating;
  std::vector<gc::Segment> segments = read_motion_segments(root, oscillating, kMm, &segment_marks);
  read_output(root, model);
  read_dynamics(root, model);
  read_contact(root, model);
  root.finish();
  build_program(model, std::move(segments), segment_marks, motion_mark);
  validate_design(doc, motion_mark, model);
  return model;
}

}  // namespace gearkit::plugins::cam
