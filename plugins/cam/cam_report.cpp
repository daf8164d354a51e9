#include "cam_report.hpp"

#include "cam_text.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <numbers>

namespace gearkit::plugins::cam {

namespace gc = gearkit::cam;

namespace {

std::string kind_name(const gc::Segment& s) {
  switch (s.kind) {
    case gc::SegmentKind::rise: return "rise";
    case gc::SegmentKind::dwell: return "dwell";
    case gc::SegmentKind::fall: return "return";
    case gc::SegmentKind::table: return "table";
    case gc::SegmentKind::polynomial: return "polynomial";
  }
  return "?";
}

/// What shapes a segment: its law, the table's interpolation, or the polynomial's degree.
std::string shape_name(const gc::Segment& s) {
  switch (s.kind) {
    case gc::SegmentKind::rise:
    case gc::SegmentKind::fall: return std::string(gc::name_of(s.law));
    case gc::SegmentKind::table:
      return s.interpolation == gc::TableInterpolation::pchip   ? "pchip (shape-preserving)"
             : s.interpolation == gc::TableInterpolation::cubic ? "cubic spline"
                                                                : "quintic B-spline";
    case gc::SegmentKind::polynomial: {
      int n = 0;
      for (const auto* e : {&s.at_start, &s.at_end}) n += e->s.has_value() + e->v.has_value() + e->a.has_value() + e->j.has_value();
      return fmt::format("polynomial of degree {}", n - (s.at_start.s ? 1 : 0));
    }
    case gc::SegmentKind::dwell: return "-";
  }
  return "-";
}

std::string contact_name(gc::Contact c) {
  return c == gc::Contact::roller ? "roller" : c == gc::Contact::flat_face ? "flat_face" : "knife_edge";
}

void program_section(const CamModel& model, io::Report& rep) {
  const gc::CamDesign& d = model.design;
  const FollowerUnits u(model);
  io::Table program{"Motion program", {"segment", "from [deg]", "to [deg]", "shape", fmt::format("lift [{}]", u.s_unit)}, {}};
  for (const gc::Segment& s : d.program.segments()) {
    const bool moves = s.kind == gc::SegmentKind::rise || s.kind == gc::SegmentKind::fall;
    program.add_row({kind_name(s), io::fixed(deg(s.start), 2), io::fixed(deg(s.end), 2), shape_name(s),
                     moves ? io::fixed(u.s_value(s.lift), 4) : "-"});
  }
  rep.tables.push_back(program);
}

void checks_section(const CamModel& model, const CamResult& r, io::Report& rep) {
  const gc::CamDesign& d = model.design;
  const bool osc = d.follower.motion == gc::FollowerMotion::oscillating;
  const gc::CamChecks& c = r.checks;
  io::Table checks{"Checks", {"quantity", "value", "at cam angle [deg]"}, {}};
  checks.add_row({"max pressure angle [deg]", io::fixed(deg(c.pressure_angle_max.value), 3),
                  io::fixed(angle_deg(c.pressure_angle_max.theta), 2)});
  checks.add_row({"pressure angle limit [deg]", io::fixed(deg(model.pressure_angle_limit), 2), "-"});
  const auto radius = [](const gc::ValueAt& v) { return std::isfinite(v.value) ? io::fixed(v.value, 3) : "none"; };
  const auto where = [](const gc::ValueAt& v) { return std::isfinite(v.value) ? io::fixed(angle_deg(v.theta), 2) : "-"; };
  if (d.follower.contact != gc::Contact::flat_face)
    checks.add_row({"min convex radius of pitch curve [mm]", radius(c.rho_pitch_min), where(c.rho_pitch_min)});
  checks.add_row({"min convex radius of profile [mm]", radius(c.rho_profile_min), where(c.rho_profile_min)});
  checks.add_row({"min concave radius of profile [mm]", radius(c.rho_concave_min), where(c.rho_concave_min)});
  checks.add_row({"undercut", c.undercut ? "yes" : "no", "-"});
  const std::string rb_criterion = d.follower.contact == gc::Contact::flat_face && !osc
                                       ? "smallest base radius for a convex profile [mm]"
                                       : fmt::format("smallest base radius for {} deg [mm]",
                                                     io::fixed(deg(model.pressure_angle_limit), 1));
  checks.add_row({rb_criterion, std::isfinite(c.base_radius_min) ? io::fixed(c.base_radius_min, 5) : "none", "-"});
  checks.add_row({"largest radius of the cam [mm]", io::fixed(c.radius_max.value, 3), io::fixed(angle_deg(c.radius_max.theta), 2)});
  if (osc) checks.add_row({"clearance to the pivot [mm]", io::fixed(pivot_clearance(model, r), 3), "-"});
  if (d.follower.contact == gc::Contact::flat_face) {
    checks.add_row({"face contact from [mm]", io::fixed(c.face_min, 3), "-"});
    checks.add_row({"face contact to [mm]", io::fixed(c.face_max, 3), "-"});
  }
  rep.tables.push_back(checks);
}

void checks_json(const CamModel& model, const CamResult& r, nlohmann::json& j) {
  const gc::CamChecks& c = r.checks;
  j["pressure_angle_max_deg"] = number(deg(c.pressure_angle_max.value));
  j["pressure_angle_max_at_deg"] = number(angle_deg(c.pressure_angle_max.theta));
  j["pressure_angle_limit_deg"] = number(deg(model.pressure_angle_limit));
  j["rho_min_mm"] = number(c.rho_profile_min.value);
  j["rho_min_at_deg"] = number(angle_deg(c.rho_profile_min.theta));
  j["rho_pitch_min_mm"] = number(c.rho_pitch_min.value);
  j["rho_pitch_min_at_deg"] = number(angle_deg(c.rho_pitch_min.theta));
  j["rho_concave_min_mm"] = number(c.rho_concave_min.value);
  j["undercut"] = c.undercut;
  j["base_radius_min_mm"] = number(c.base_radius_min);
  j["radius_max_mm"] = number(c.radius_max.value);
  j["radius_max_at_deg"] = number(angle_deg(c.radius_max.theta));
  if (model.design.follower.motion == gc::FollowerMotion::oscillating) j["pivot_clearance_mm"] = number(pivot_clearance(model, r));
  if (model.design.follower.contact == gc::Contact::flat_face) {
    j["face_contact_min_mm"] = number(c.face_min);
    j["face_contact_max_mm"] = number(c.face_max);
    j["face_width_mm"] = number(c.face_max - c.face_min);
  }
}

/// Peaks of velocity, acceleration and jerk, per radian and (with a cam speed) per second.
void peaks_section(const CamModel& model, const CamResult& r, io::Report& rep) {
  const bool osc = model.design.follower.motion == gc::FollowerMotion::oscillating;
  double peak[3] = {0, 0, 0}, at[3] = {0, 0, 0};
  for (const gc::ContactState& s : r.checks.samples) {
    const double v[3] = {s.motion.ds, s.motion.d2s, s.motion.d3s};
    for (int k = 0; k < 3; ++k)
      if (std::abs(v[k]) > std::abs(peak[k])) peak[k] = v[k], at[k] = s.theta;
  }
  const std::string u = osc ? "rad" : "mm";
  io::Table peaks{"Motion peaks", {"quantity", fmt::format("per rad [{}/rad^n]", u), "at cam angle [deg]"}, {}};
  if (model.omega) peaks.header.push_back(fmt::format("per second [{}/s^n]", u));
  const char* names[3] = {"velocity", "acceleration", "jerk"};
  const char* per_rad_keys[3] = {"velocity_max_per_rad", "acceleration_max_per_rad2", "jerk_max_per_rad3"};
  const char* per_s_keys[3] = {osc ? "omega_max_rad_s" : "v_max_mm_s", osc ? "alpha_max_rad_s2" : "a_max_mm_s2",
                               osc ? "jerk_max_rad_s3" : "j_max_mm_s3"};
  for (int k = 0; k < 3; ++k) {
    std::vector<std::string> row{names[k], fmt::format("{:.6g}", peak[k]), io::fixed(angle_deg(at[k]), 2)};
    rep.json[per_rad_keys[k]] = number(peak[k]);
    if (model.omega) {
      const double per_s = peak[k] * std::pow(*model.omega, k + 1);
      row.push_back(fmt::format("{:.6g}", per_s));
      rep.json[per_s_keys[k]] = number(per_s);
    }
    peaks.add_row(row);
  }
  rep.tables.push_back(peaks);
}

void motion_section(const CamModel& model, const CamResult& r, io::Report& rep) {
  const FollowerUnits u(model);
  io::Table motion{"Follower motion",
                   {"theta [deg]", fmt::format("{} [{}]", u.s_name, u.s_unit), fmt::format("d/dtheta [{}/rad]", u.d_unit),
                    fmt::format("d2/dtheta2 [{}/rad^2]", u.d_unit), "pressure angle [deg]"},
                   {}};
  nlohmann::json points = nlohmann::json::array();
  const int every = std::max<int>(1, static_cast<int>(r.samples.size()) / 36);
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    const gc::ContactState& s = r.samples[i];
    points.push_back({number(s.contact.x), number(s.contact.y)});
    if (i % every == 0)
      motion.add_row({io::fixed(deg(s.theta), 2), io::fixed(u.s_value(s.motion.s), 4), io::fixed(s.motion.ds, 5),
                      io::fixed(s.motion.d2s, 5), io::fixed(deg(s.pressure_angle), 3)});
  }
  rep.tables.push_back(motion);
  rep.json["profile_points"] = points;
  rep.json["profile_points_count"] = r.samples.size();
}

void profile_section(const CamModel& model, const CamResult& r, io::Report& rep) {
  std::size_t arcs = 0;
  for (const auto& loop : r.profile.profile) arcs += gc::merge_pieces(loop).size();
  io::Table prof{"Profile", {"quantity", "value"}, {}};
  prof.add_row({"biarcs fitted", std::to_string(r.profile.biarcs)});
  prof.add_row({"profile arcs (merged)", std::to_string(arcs)});
  prof.add_row({"fit tolerance [mm]", fmt::format("{:.6g}", model.tolerance_mm)});
  prof.add_row({"max deviation of the profile arcs from the analytic profile [mm]", fmt::format("{:.3e}", r.deviation_mm)});
  if (model.cutter_radius_mm) {
    prof.add_row({"cutter radius [mm]", io::fixed(*model.cutter_radius_mm, 3)});
    prof.add_row({"max deviation of the tool path [mm]", fmt::format("{:.3e}", r.profile.tool_path_error)});
  }
  rep.tables.push_back(prof);
  nlohmann::json& j = rep.json;
  j["profile_arcs"] = arcs;
  j["fit_tolerance_mm"] = number(model.tolerance_mm);
  j["profile_deviation_mm"] = number(r.deviation_mm);
  if (model.cutter_radius_mm) {
    j["cutter_radius_mm"] = number(*model.cutter_radius_mm);
    j["tool_path_deviation_mm"] = number(r.profile.tool_path_error);
  }
}

/// Where an undercut lies: "from cam angle A deg to B deg", or "at cam angle A deg" for a fold
/// narrower than the printed resolution (found between the samples).
std::string range_text(const gc::ValueAt& range) {
  const double from = angle_deg(range.theta), to = angle_deg(range.value);
  if (std::abs(std::remainder(to - from, 360.0)) < 0.01)
    return fmt::format("at cam angle {} deg (over {:.2g} deg)", io::fixed(angle_deg(0.5 * (range.theta + range.value)), 4),
                       std::abs(std::remainder(to - from, 360.0)));
  return fmt::format("from cam angle {} deg to {} deg", io::fixed(from, 2), io::fixed(to, 2));
}

void geometry_warnings(const CamModel& model, const CamResult& r, io::Report& rep) {
  const gc::CamDesign& d = model.design;
  const gc::CamChecks& c = r.checks;
  if (c.pressure_angle_exceeded) {
    rep.warnings.push_back(fmt::format("pressure angle {} deg at cam angle {} deg exceeds the limit {} deg",
                                       io::fixed(deg(c.pressure_angle_max.value), 2),
                                       io::fixed(angle_deg(c.pressure_angle_max.theta), 2),
                                       io::fixed(deg(model.pressure_angle_limit), 2)));
  }
  for (const gc::ValueAt& u : c.undercut_ranges) {
    rep.warnings.push_back(
        d.follower.contact == gc::Contact::roller
            ? fmt::format("undercut {}: the roller radius {} mm exceeds the pitch curve's "
                          "radius of curvature (min {} mm); the follower will not reproduce the motion there",
                          range_text(u),
                          io::fixed(d.follower.roller_radius, 3), io::fixed(c.rho_pitch_min.value, 3))
            : fmt::format("cusp in the flat-faced profile {} (radius of curvature <= 0, least {} mm); "
                          "enlarge the base circle to more than {} mm",
                          range_text(u), fmt::format("{:.3g}", c.rho_profile_min.value),
                          io::fixed(c.base_radius_min, 5)));
  }
  if (d.follower.motion == gc::FollowerMotion::oscillating && pivot_clearance(model, r) <= 0) {
    rep.warnings.push_back(fmt::format(
        "the cam reaches {} mm from its centre (at cam angle {} deg) but the follower's pivot{} is at {} mm: the cam "
        "would strike the pivot; increase pivot_distance or reduce the cam",
        io::fixed(c.radius_max.value, 3), io::fixed(angle_deg(c.radius_max.theta), 2),
        model.pivot_radius_mm > 0 ? fmt::format(" (boss radius {} mm)", io::fixed(model.pivot_radius_mm, 3)) : "",
        io::fixed(d.follower.pivot_distance, 3)));
  }
  if (r.profile.tool_path_trimmed) {
    rep.warnings.push_back(fmt::format("the cutter (radius {} mm) is larger than the profile's smallest concave "
                                       "radius ({} mm): it cannot finish the hollow",
                                       io::fixed(model.cutter_radius_mm.value_or(0), 3),
                                       io::fixed(c.rho_concave_min.value, 3)));
  }
  if (r.profile.profile_is_polyline) {
    rep.warnings.push_back("the flat-faced profile has cusps: exported as straight segments through the envelope");
    if (model.cutter_radius_mm) rep.warnings.push_back("no tool path: the profile with cusps cannot be offset");
  }
}

/// What a velocity jump does to a roller cam: the pitch curve has a corner there.
std::string corner_remark(const CamModel& model, const CamResult& r, double theta) {
  if (model.design.follower.contact != gc::Contact::roller) return "";
  for (const gc::PitchCorner& c : r.checks.corners) {
    if (std::abs(std::remainder(c.theta - theta, 2 * std::numbers::pi)) > 1e-9) continue;
    return c.turn > 0 ? fmt::format("; the pitch curve turns {} deg towards the cam there: the profile is cut to a "
                                    "sharp edge that the roller rounds, so the follower does not reproduce the motion",
                                    io::fixed(deg(c.turn), 2))
                      : fmt::format("; the pitch curve turns {} deg away from the cam there: the profile has a hollow of "
                                    "the roller's radius",
                                    io::fixed(deg(-c.turn), 2));
  }
  return "";
}

/// The unit of the n-th derivative of the follower's motion per radian of cam angle: "mm/rad^2".
std::string per_rad(const FollowerUnits& u, const std::string& quantity) {
  const int n = quantity == "velocity" ? 1 : quantity == "acceleration" ? 2 : quantity == "jerk" ? 3 : 0;
  return n == 0 ? u.d_unit : n == 1 ? u.d_unit + "/rad" : fmt::format("{}/rad^{}", u.d_unit, n);
}

/// Jerk jumps: a note listing them, and JSON "jerk_jumps" (at_deg, before and after per rad^3).
void jerk_remarks(const CamModel& model, const std::vector<const gc::JoinJump*>& jerks, io::Report& rep) {
  const FollowerUnits u(model);
  const std::string key = u.d_unit + "_per_rad3";
  nlohmann::json list = nlohmann::json::array();
  std::string text;
  for (const gc::JoinJump* jump : jerks) {
    text += fmt::format("{}{} deg ({:.6g} to {:.6g} {})", text.empty() ? "" : ", ", io::fixed(angle_deg(jump->theta), 2),
                        jump->before, jump->after, per_rad(u, "jerk"));
    list.push_back({{"at_deg", number(angle_deg(jump->theta))}, {"before_" + key, number(jump->before)},
                    {"after_" + key, number(jump->after)}});
  }
  rep.json["jerk_jumps"] = list;
  if (!jerks.empty())
    rep.notes.push_back(fmt::format("jerk jumps (finite steps of d3s/dtheta3, harmless at low speed) at cam angle {}", text));
}

/// Jumps of s, v, a are warnings (an acceleration jump is a force jump: shock and vibration);
/// jerk jumps are notes. The many acceleration jumps of a pchip table are one warning.
void continuity_remarks(const CamModel& model, const CamResult& r, io::Report& rep) {
  const FollowerUnits u(model);
  const auto& segs = model.design.program.segments();
  std::map<std::size_t, std::vector<const gc::JoinJump*>> table_jumps;
  std::vector<const gc::JoinJump*> jerks;
  for (const gc::JoinJump& jump : r.jumps) {
    const gc::Segment& seg = segs[jump.segment];
    if (jump.quantity == "jerk") {
      jerks.push_back(&jump);
    } else if (!jump.join && seg.kind == gc::SegmentKind::table) {
      table_jumps[jump.segment].push_back(&jump);
    } else {
      rep.warnings.push_back(fmt::format("{} jumps at cam angle {} deg{}: {:.6g} before, {:.6g} after ({}){}",
                                         jump.quantity, io::fixed(angle_deg(jump.theta), 2),
                                         jump.join ? "" : fmt::format(" inside the {} segment", kind_name(seg)),
                                         jump.before, jump.after, per_rad(u, jump.quantity),
                                         jump.quantity == "velocity" ? corner_remark(model, r, jump.theta) : ""));
    }
  }
  for (const auto& [segment, jumps] : table_jumps) {
    const gc::JoinJump* worst = jumps.front();
    for (const gc::JoinJump* j : jumps)
      if (std::abs(j->after - j->before) > std::abs(worst->after - worst->before)) worst = j;
    rep.warnings.push_back(fmt::format(
        "the table from {} deg ({}) has {} jumps of {} at its inner points, the largest at {} deg ({:.6g} to {:.6g} "
        "{}): use interpolation: bspline for continuous acceleration and jerk",
        io::fixed(deg(segs[segment].start), 2), shape_name(segs[segment]), jumps.size(), worst->quantity,
        io::fixed(angle_deg(worst->theta), 2), worst->before, worst->after, per_rad(u, worst->quantity)));
  }
  jerk_remarks(model, jerks, rep);
}

void table_remarks(const CamModel& model, io::Report& rep) {
  const FollowerUnits u(model);
  const auto& program = model.design.program;
  for (const gc::Overshoot& o : gc::table_overshoots(program)) {
    rep.warnings.push_back(fmt::format("the cubic spline through the table from {} deg reaches s = {} {} at cam angle "
                                       "{} deg, beyond its points' range ({} {}): use interpolation: pchip",
                                       io::fixed(deg(program.segments()[o.segment].start), 2), io::fixed(u.s_value(o.s), 4),
                                       u.s_unit, io::fixed(angle_deg(o.theta), 2), io::fixed(u.s_value(o.limit), 4), u.s_unit));
  }
  for (std::size_t i = 0; i < program.segments().size(); ++i) {
    const gc::Segment& s = program.segments()[i];
    if (s.kind != gc::SegmentKind::table || s.interpolation != gc::TableInterpolation::bspline) continue;
    rep.notes.push_back(fmt::format("the B-spline table from {} deg passes within {} {} of its points (they are its "
                                    "control polygon)",
                                    io::fixed(deg(s.start), 2), io::fixed(u.s_value(gc::table_fit_residual(program, i)), 4),
                                    u.s_unit));
  }
}

/// Groove cams: the outer wall; conjugate cams: the second cam. The same checks as the first.
void other_surface_section(const CamModel& model, const CamResult& r, io::Report& rep) {
  if (!r.other_checks) return;
  const bool groove = model.design.follower.closure == gc::Closure::groove;
  const std::string name = groove ? "outer wall" : "conjugate cam";
  const gc::CamChecks& c = *r.other_checks;
  const auto radius = [](const gc::ValueAt& v) { return std::isfinite(v.value) ? io::fixed(v.value, 3) : "none"; };
  const auto where = [](const gc::ValueAt& v) { return std::isfinite(v.value) ? io::fixed(angle_deg(v.theta), 2) : "-"; };
  io::Table t{"Checks of the " + name, {"quantity", "value", "at cam angle [deg]"}, {}};
  t.add_row({"max pressure angle [deg]", io::fixed(deg(c.pressure_angle_max.value), 3), where(c.pressure_angle_max)});
  t.add_row({"min convex radius [mm]", radius(c.rho_profile_min), where(c.rho_profile_min)});
  t.add_row({"min concave radius [mm]", radius(c.rho_concave_min), where(c.rho_concave_min)});
  t.add_row({"undercut", c.undercut ? "yes" : "no", "-"});
  t.add_row({"largest radius [mm]", io::fixed(c.radius_max.value, 3), where(c.radius_max)});
  nlohmann::json j;
  j["pressure_angle_max_deg"] = number(deg(c.pressure_angle_max.value));
  j["rho_min_mm"] = number(c.rho_profile_min.value);
  j["rho_concave_min_mm"] = number(c.rho_concave_min.value);
  j["undercut"] = c.undercut;
  j["radius_max_mm"] = number(c.radius_max.value);
  if (!groove && r.second_profile) {
    double least = INFINITY;
    for (const gc::ContactState& s : c.samples) least = std::min(least, std::hypot(s.contact.x, s.contact.y));
    t.add_row({"base radius (smallest radius) [mm]", io::fixed(least, 3), "-"});
    t.add_row({"max deviation of the arcs [mm]", fmt::format("{:.3e}", r.second_profile->profile_error), "-"});
    j["base_radius_mm"] = number(least);
    j["profile_deviation_mm"] = number(r.second_profile->profile_error);
  } else {
    t.add_row({"max deviation of the arcs [mm]", fmt::format("{:.3e}", r.profile.outer_error), "-"});
    j["profile_deviation_mm"] = number(r.profile.outer_error);
  }
  rep.tables.push_back(t);
  rep.json[groove ? "outer_wall" : "conjugate_cam"] = j;
  if (!groove && std::abs(c.pressure_angle_max.value) > model.pressure_angle_limit)
    rep.warnings.push_back(fmt::format("pressure angle {} deg of the conjugate cam at cam angle {} deg exceeds the limit {} deg",
                                       io::fixed(deg(c.pressure_angle_max.value), 2),
                                       io::fixed(angle_deg(c.pressure_angle_max.theta), 2),
                                       io::fixed(deg(model.pressure_angle_limit), 2)));
  const gc::Follower& f = model.design.follower;
  if (!groove && f.motion == gc::FollowerMotion::oscillating &&
      c.radius_max.value >= f.pivot_distance - model.pivot_radius_mm)
    rep.warnings.push_back(fmt::format("the conjugate cam reaches {} mm from its centre but the follower's pivot is at {} "
                                       "mm: the cam would strike the pivot",
                                       io::fixed(c.radius_max.value, 3), io::fixed(f.pivot_distance, 3)));
  for (const gc::ValueAt& u : c.undercut_ranges)
    rep.warnings.push_back(fmt::format("undercut of the {} {}: the roller ({} mm) does not "
                                       "fit its hollow; the follower will not reproduce the motion there",
                                       name, range_text(u),
                                       io::fixed(gc::roller_radius(groove ? model.design : gc::conjugate_cam_of(model.design)), 3)));
}

}  // namespace

double pivot_clearance(const CamModel& model, const CamResult& r) {
  return model.design.follower.pivot_distance - model.pivot_radius_mm - r.checks.radius_max.value;
}

// An angle [rad] as course notes write it: a fraction of Pi with a small denominator ("2*Pi/3"),
// else its decimal value.
std::string angle_text(double rad) {
  for (int q = 1; q <= 36; ++q) {
    const double p = rad / std::numbers::pi * q;
    if (std::abs(p - std::round(p)) > 1e-9 * std::max(1.0, std::abs(p))) continue;
    const long n = std::lround(p);
    if (n == 0) return "0";
    const std::string num = n == 1 ? "Pi" : n == -1 ? "-Pi" : fmt::format("{}*Pi", n);
    return q == 1 ? num : fmt::format("{}/{}", num, q);
  }
  return fmt::format("{:.15g}", rad);
}

// s(theta) and ds/dtheta of every segment as formulas in theta [rad] (course notes' form,
// OTM 2015 problem 2 a): a rise or fall s0 +- L y(u), u = (theta - theta0)/beta; a law pieced
// together (parabolic, modified trapezoid, modified sine) one row per piece.
void formulas_section(const CamModel& model, io::Report& rep) {
  const gc::MotionProgram& program = model.design.program;
  const FollowerUnits units(model);
  io::Table t{"Motion formulas (theta in rad)", {"segment", "from [deg]", "to [deg]", fmt::format("{}(theta) [{}]", units.s_name, units.d_unit),
                                                 fmt::format("d{}/dtheta [{}/rad]", units.s_name, units.d_unit)}, {}};
  nlohmann::json all = nlohmann::json::array();
  // `piece`: "2/3" for the second of three pieces of a law, empty for a whole segment.
  const auto add = [&](const gc::Segment& seg, const std::string& piece, double from, double to, const std::string& s_text,
                       const std::string& ds_text) {
    const bool moves = seg.kind == gc::SegmentKind::rise || seg.kind == gc::SegmentKind::fall;
    t.add_row({piece.empty() ? kind_name(seg) : kind_name(seg) + " " + piece, io::fixed(deg(from), 2), io::fixed(deg(to), 2),
               s_text, ds_text});
    all.push_back({{"kind", kind_name(seg)}, {"from_deg", deg(from)}, {"to_deg", deg(to)},
                   {"law", moves ? std::string(gc::name_of(seg.law)) : "dwell"}, {"s", s_text}, {"ds_dtheta", ds_text},
                   {"unit", units.d_unit}});
    if (!piece.empty()) all.back()["piece"] = piece;
  };
  for (const gc::Segment& seg : program.segments()) {
    const double s0 = program.at(seg.start).s;
    if (seg.kind == gc::SegmentKind::dwell) add(seg, "", seg.start, seg.end, fmt::format("{:.15g}", s0), "0");
    if (seg.kind != gc::SegmentKind::rise && seg.kind != gc::SegmentKind::fall) continue;  // tables, polynomials: no closed law here
    const std::string beta = angle_text(seg.end - seg.start), theta0 = angle_text(seg.start);
    const std::string u = (theta0 == "0" ? std::string("theta") : "theta-" + theta0) + ")/(" + beta;
    const std::vector<gc::LawPiece> pieces = gc::law_pieces(seg.law, "(" + u + ")");
    const char* sign = seg.kind == gc::SegmentKind::rise ? "+" : "-";
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      const gc::LawFormula& f = pieces[k].formula;
      const std::string s_text = fmt::format("{}{}{:.15g}*({})", s0 == 0.0 ? "" : fmt::format("{:.15g}", s0),
                                             s0 == 0.0 && *sign == '+' ? "" : sign, seg.lift, f.y);
      const std::string ds_text = fmt::format("{}{:.15g}/({})*({})", *sign == '-' ? "-" : "", seg.lift, beta, f.dy);
      const double span = seg.end - seg.start;  // the ends exactly, not seg.start + 1 * span
      const double from = k == 0 ? seg.start : seg.start + pieces[k].u0 * span;
      const double to = k + 1 == pieces.size() ? seg.end : seg.start + pieces[k].u1 * span;
      add(seg, pieces.size() == 1 ? "" : fmt::format("{}/{}", k + 1, pieces.size()), from, to, s_text, ds_text);
    }
  }
  rep.tables.push_back(std::move(t));
  rep.json["motion_formulas"] = all;
}

io::Report cam_report(const CamModel& model, const CamResult& result, const std::string& file) {
  const gc::CamDesign& d = model.design;
  const bool osc = d.follower.motion == gc::FollowerMotion::oscillating;
  io::Report rep;
  rep.title = fmt::format("Cam {}", model.name.empty() ? file : model.name);
  nlohmann::json& j = rep.json;
  j["file"] = file;
  j["follower"] = {{"type", osc ? "oscillating" : "translating"}, {"contact", contact_name(d.follower.contact)}};
  j["rotation"] = d.rotation == gc::Rotation::ccw ? "ccw" : "cw";
  j["type"] = d.follower.closure == gc::Closure::groove ? "groove" : d.follower.closure == gc::Closure::conjugate ? "conjugate" : "plate";
  j["base_radius_mm"] = number(d.base_radius);
  program_section(model, rep);
  formulas_section(model, rep);
  checks_section(model, result, rep);
  checks_json(model, result, j);
  peaks_section(model, result, rep);
  motion_section(model, result, rep);
  profile_section(model, result, rep);
  other_surface_section(model, result, rep);
  geometry_warnings(model, result, rep);
  continuity_remarks(model, result, rep);
  table_remarks(model, rep);
  if (result.dynamics) dynamics_report(model, *result.dynamics, rep);
  if (model.omega) {
    j["speed_rad_s"] = number(*model.omega);
    j["speed_rpm"] = number(*model.omega * 30 / std::numbers::pi);
    rep.notes.push_back(fmt::format("cam speed {} rad/s ({} rpm): per-second values in --csv and --plot",
                                    io::fixed(*model.omega, 4), io::fixed(*model.omega * 30 / std::numbers::pi, 2)));
  }
  return rep;
}

}  // namespace gearkit::plugins::cam
