#include "cam_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace gearkit::plugins::cam {

namespace gc = gearkit::cam;

namespace {

constexpr double deg_per_rad = 180 / std::numbers::pi;

double deg(double rad) { return rad * deg_per_rad; }
/// A cam angle in [0, 360) deg.
double angle_deg(double rad) {
  const double d = std::fmod(deg(rad), 360.0);
  return d < 0 ? d + 360 : d;
}

std::string kind_name(gc::SegmentKind k) {
  switch (k) {
    case gc::SegmentKind::rise: return "rise";
    case gc::SegmentKind::dwell: return "dwell";
    case gc::SegmentKind::fall: return "return";
    case gc::SegmentKind::table: return "table";
  }
  return "?";
}

nlohmann::json finite_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

std::string contact_name(gc::Contact c) {
  return c == gc::Contact::roller ? "roller" : c == gc::Contact::flat_face ? "flat_face" : "knife_edge";
}

}  // namespace

io::Report cam_report(const CamModel& model, const CamResult& r, const std::string& file) {
  const gc::CamDesign& d = model.design;
  const bool osc = d.follower.motion == gc::FollowerMotion::oscillating;
  const std::string s_unit = osc ? "deg" : "mm";
  const auto s_value = [&](double s) { return osc ? deg(s) : s; };
  io::Report rep;
  rep.title = fmt::format("Cam {}", model.name.empty() ? file : model.name);
  nlohmann::json& j = rep.json;
  j["file"] = file;
  j["follower"] = {{"type", osc ? "oscillating" : "translating"}, {"contact", contact_name(d.follower.contact)}};
  j["rotation"] = d.rotation == gc::Rotation::ccw ? "ccw" : "cw";
  j["base_radius_mm"] = d.base_radius;

  io::Table program{"Motion program", {"segment", "from [deg]", "to [deg]", "law", fmt::format("lift [{}]", s_unit)}, {}};
  for (const gc::Segment& s : d.program.segments()) {
    const bool moves = s.kind == gc::SegmentKind::rise || s.kind == gc::SegmentKind::fall;
    program.add_row({kind_name(s.kind), io::fixed(deg(s.start), 2), io::fixed(deg(s.end), 2),
                     moves ? std::string(gc::name_of(s.law)) : s.kind == gc::SegmentKind::table ? "cubic spline" : "-",
                     moves ? io::fixed(s_value(s.lift), 4) : "-"});
  }
  rep.tables.push_back(program);

  const gc::CamChecks& c = r.checks;
  io::Table checks{"Checks", {"quantity", "value", "at cam angle [deg]"}, {}};
  checks.add_row({"max pressure angle [deg]", io::fixed(deg(c.pressure_angle_max.value), 3),
                  io::fixed(angle_deg(c.pressure_angle_max.theta), 2)});
  checks.add_row({"pressure angle limit [deg]", io::fixed(deg(model.pressure_angle_limit), 2), "-"});
  const auto radius = [](const gc::ValueAt& v) { return std::isfinite(v.value) ? io::fixed(v.value, 3) : "none"; };
  const auto where = [](const gc::ValueAt& v) { return std::isfinite(v.value) ? io::fixed(angle_deg(v.theta), 2) : "-"; };
  if (d.follower.contact != gc::Contact::flat_face) {
    checks.add_row({"min convex radius of pitch curve [mm]", radius(c.rho_pitch_min), where(c.rho_pitch_min)});
  }
  checks.add_row({"min convex radius of profile [mm]", radius(c.rho_profile_min), where(c.rho_profile_min)});
  checks.add_row({"min concave radius of profile [mm]", radius(c.rho_concave_min), where(c.rho_concave_min)});
  checks.add_row({"undercut", c.undercut ? "yes" : "no", "-"});
  const std::string rb_criterion = d.follower.contact == gc::Contact::flat_face && !osc
                                       ? "smallest base radius for a convex profile [mm]"
                                       : fmt::format("smallest base radius for {} deg [mm]",
                                                     io::fixed(deg(model.pressure_angle_limit), 1));
  checks.add_row({rb_criterion, std::isfinite(c.base_radius_min) ? io::fixed(c.base_radius_min, 3) : "none", "-"});
  if (d.follower.contact == gc::Contact::flat_face) {
    checks.add_row({"face contact from [mm]", io::fixed(c.face_min, 3), "-"});
    checks.add_row({"face contact to [mm]", io::fixed(c.face_max, 3), "-"});
  }
  rep.tables.push_back(checks);

  j["pressure_angle_max_deg"] = deg(c.pressure_angle_max.value);
  j["pressure_angle_max_at_deg"] = angle_deg(c.pressure_angle_max.theta);
  j["pressure_angle_limit_deg"] = deg(model.pressure_angle_limit);
  j["rho_min_mm"] = finite_or_null(c.rho_profile_min.value);
  j["rho_min_at_deg"] = angle_deg(c.rho_profile_min.theta);
  j["rho_pitch_min_mm"] = finite_or_null(c.rho_pitch_min.value);
  j["rho_pitch_min_at_deg"] = angle_deg(c.rho_pitch_min.theta);
  j["rho_concave_min_mm"] = finite_or_null(c.rho_concave_min.value);
  j["undercut"] = c.undercut;
  j["base_radius_min_mm"] = finite_or_null(c.base_radius_min);
  if (d.follower.contact == gc::Contact::flat_face) {
    j["face_contact_min_mm"] = c.face_min;
    j["face_contact_max_mm"] = c.face_max;
    j["face_width_mm"] = c.face_max - c.face_min;
  }

  // Peaks of velocity, acceleration and jerk, per radian and (with a cam speed) per second.
  {
    double peak[3] = {0, 0, 0}, at[3] = {0, 0, 0};
    for (const gc::ContactState& s : c.samples) {
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
      j[per_rad_keys[k]] = peak[k];
      if (model.omega) {
        const double per_s = peak[k] * std::pow(*model.omega, k + 1);
        row.push_back(fmt::format("{:.6g}", per_s));
        j[per_s_keys[k]] = per_s;
      }
      peaks.add_row(row);
    }
    rep.tables.push_back(peaks);
  }

  io::Table motion{"Follower motion",
                   {"theta [deg]", fmt::format("{} [{}]", osc ? "psi" : "s", s_unit),
                    fmt::format("d/dtheta [{}/rad]", osc ? "rad" : "mm"), fmt::format("d2/dtheta2 [{}/rad^2]", osc ? "rad" : "mm"),
                    "pressure angle [deg]"},
                   {}};
  nlohmann::json points = nlohmann::json::array();
  const int every = std::max<int>(1, static_cast<int>(r.samples.size()) / 36);
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    const gc::ContactState& s = r.samples[i];
    points.push_back({s.contact.x, s.contact.y});
    if (i % every == 0)
      motion.add_row({io::fixed(deg(s.theta), 2), io::fixed(s_value(s.motion.s), 4), io::fixed(s.motion.ds, 5),
                      io::fixed(s.motion.d2s, 5), io::fixed(deg(s.pressure_angle), 3)});
  }
  rep.tables.push_back(motion);
  j["profile_points"] = points;
  j["profile_points_count"] = r.samples.size();

  const std::size_t arcs = [&] {
    std::size_t n = 0;
    for (const auto& loop : r.profile.profile) n += gc::merge_pieces(loop).size();
    return n;
  }();
  io::Table prof{"Profile", {"quantity", "value"}, {}};
  prof.add_row({"biarcs fitted", std::to_string(r.profile.biarcs)});
  prof.add_row({"profile arcs (merged)", std::to_string(arcs)});
  prof.add_row({"fit tolerance [mm]", fmt::format("{}", model.tolerance_mm)});
  prof.add_row({"max deviation from analytic profile [mm]", fmt::format("{:.2e}", r.deviation_mm)});
  if (model.cutter_radius_mm) prof.add_row({"cutter radius [mm]", io::fixed(*model.cutter_radius_mm, 3)});
  rep.tables.push_back(prof);
  j["profile_arcs"] = arcs;
  j["fit_tolerance_mm"] = model.tolerance_mm;
  j["profile_deviation_mm"] = finite_or_null(r.deviation_mm);
  if (model.cutter_radius_mm) j["cutter_radius_mm"] = *model.cutter_radius_mm;

  if (c.pressure_angle_exceeded) {
    rep.warnings.push_back(fmt::format("pressure angle {} deg at cam angle {} deg exceeds the limit {} deg",
                                       io::fixed(deg(c.pressure_angle_max.value), 2),
                                       io::fixed(angle_deg(c.pressure_angle_max.theta), 2),
                                       io::fixed(deg(model.pressure_angle_limit), 2)));
  }
  for (const gc::ValueAt& u : c.undercut_ranges) {
    rep.warnings.push_back(
        d.follower.contact == gc::Contact::roller
            ? fmt::format("undercut from cam angle {} deg to {} deg: the roller radius {} mm exceeds the pitch curve's "
                          "radius of curvature (min {} mm); the follower will not reproduce the motion there",
                          io::fixed(angle_deg(u.theta), 2), io::fixed(angle_deg(u.value), 2),
                          io::fixed(d.follower.roller_radius, 3), io::fixed(c.rho_pitch_min.value, 3))
            : fmt::format("cusp in the flat-faced profile from cam angle {} deg to {} deg (radius of curvature <= 0); "
                          "enlarge the base circle to at least {} mm",
                          io::fixed(angle_deg(u.theta), 2), io::fixed(angle_deg(u.value), 2),
                          io::fixed(c.base_radius_min, 3)));
  }
  for (const gc::JoinJump& jump : r.jumps) {
    rep.warnings.push_back(fmt::format("{} jumps at cam angle {} deg: {:.6g} before, {:.6g} after (per rad{})",
                                       jump.quantity, io::fixed(angle_deg(jump.theta), 2), jump.before, jump.after,
                                       jump.quantity == "acceleration" ? "^2" : ""));
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
  if (model.omega) {
    j["speed_rad_s"] = *model.omega;
    rep.notes.push_back(fmt::format("cam speed {} rad/s ({} rpm): per-second values in --csv and --plot",
                                    io::fixed(*model.omega, 4), io::fixed(*model.omega * 30 / std::numbers::pi, 2)));
  }
  return rep;
}

}  // namespace gearkit::plugins::cam
