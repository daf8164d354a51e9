#include "cam_export.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace gearkit::plugins::cam {

namespace gc = gearkit::cam;

namespace {

constexpr double deg_per_rad = 180 / std::numbers::pi;

bool oscillating(const CamModel& m) { return m.design.follower.motion == gc::FollowerMotion::oscillating; }

io::Polyline rotated(io::Polyline p, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  for (io::Vertex& v : p.vertices) {
    const double x = v.x, y = v.y;
    v.x = c * x - s * y;
    v.y = s * x + c * y;
  }
  return p;
}

void draw_follower(const CamModel& model, io::Drawing& d) {
  const gc::CamDesign& design = model.design;
  const gc::Follower& f = design.follower;
  const gc::ContactState c = gc::contact_at(design, model.follower_at);
  const double stem = design.base_radius;
  const gc::Vec2 p = c.follower_point;
  const char* layer = "follower";
  if (f.contact == gc::Contact::flat_face) {
    const double half = 0.5 * (design.base_radius + std::abs(f.offset));
    if (f.motion == gc::FollowerMotion::translating) {
      d.lines.push_back({layer, f.offset + std::min(c.face_position, -half) - 2, p.y,
                         f.offset + std::max(c.face_position, half) + 2, p.y});
      d.lines.push_back({layer, f.offset, p.y, f.offset, p.y + stem});
    } else {
      // The face line through pivot + face_offset N, along u.
      const double a = f.pivot_distance;
      const double beta = std::asin((f.face_offset - design.base_radius) / a) - c.motion.s;
      const double ux = std::cos(beta), uy = std::sin(beta), nx = -uy, ny = ux;
      const double t0 = std::min(c.face_position, -a) - 5, t1 = 5;
      d.lines.push_back({layer, a + f.face_offset * nx + t0 * ux, f.face_offset * ny + t0 * uy,
                         a + f.face_offset * nx + t1 * ux, f.face_offset * ny + t1 * uy});
      d.circles.push_back({layer, a, 0, 2});
    }
    return;
  }
  if (f.contact == gc::Contact::roller) d.circles.push_back({layer, p.x, p.y, f.roller_radius});
  if (f.motion == gc::FollowerMotion::translating) {
    d.lines.push_back({layer, p.x, p.y, p.x, p.y + stem});
  } else {
    d.lines.push_back({layer, f.pivot_distance, 0, p.x, p.y});
    d.circles.push_back({layer, f.pivot_distance, 0, 2});
  }
  if (f.closure == gc::Closure::conjugate) {  // the second roller, on the same slider or arm
    const gc::CamDesign second = gc::conjugate_cam_of(design);
    const gc::Vec2 q = gc::contact_at(second, model.follower_at).follower_point;
    d.circles.push_back({layer, q.x, q.y, gc::roller_radius(second)});
    if (f.motion == gc::FollowerMotion::translating)
      d.lines.push_back({layer, q.x, q.y, p.x, p.y});
    else
      d.lines.push_back({layer, f.pivot_distance, 0, q.x, q.y});
  }
}

}  // namespace

io::Polyline polyline_of(const std::vector<gc::Piece>& loop, const std::string& layer) {
  io::Polyline out{layer, {}, true};
  for (const gc::BulgeVertex& v : gc::bulge_vertices(loop)) out.vertices.push_back({v.x, v.y, v.bulge});
  return out;
}

io::Drawing cam_drawing(const CamModel& model, const gc::CamProfile& profile, bool with_follower,
                        const gc::CamProfile* second) {
  io::Drawing d;
  d.layers = {{"profile", 7, "#000", false},
              {"pitch_curve", 5, "#2255cc", true},
              {"base_circle", 8, "#888", true},
              {"tool_path", 3, "#118811", false},
              {"follower", 1, "#cc2222", false},
              {"center", 8, "#888", false}};
  const double turn = with_follower ? gc::rotation_sign(model.design.rotation) * model.follower_at : 0;
  auto add = [&](const std::vector<std::vector<gc::Piece>>& loops, const char* layer) {
    for (const auto& loop : loops) d.polylines.push_back(rotated(polyline_of(loop, layer), turn));
  };
  add(profile.profile, "profile");
  if (!profile.pitch_curve.empty() && model.design.follower.contact == gc::Contact::roller)
    d.polylines.push_back(rotated(polyline_of(profile.pitch_curve, "pitch_curve"), turn));
  add(profile.tool_path, "tool_path");
  if (!profile.outer_wall.empty()) {  // groove: the second wall and the cutter along it
    d.layers.push_back({"outer_wall", 7, "#000", false});
    d.layers.push_back({"outer_tool_path", 3, "#118811", false});
    add(profile.outer_wall, "outer_wall");
    add(profile.outer_tool_path, "outer_tool_path");
  }
  if (second) {  // the conjugate cam, on the same shaft
    d.layers.push_back({"conjugate_profile", 6, "#8a2be2", false});
    d.layers.push_back({"conjugate_pitch_curve", 5, "#2255cc", true});
    d.layers.push_back({"conjugate_tool_path", 3, "#118811", false});
    add(second->profile, "conjugate_profile");
    if (!second->pitch_curve.empty())
      d.polylines.push_back(rotated(polyline_of(second->pitch_curve, "conjugate_pitch_curve"), turn));
    add(second->tool_path, "conjugate_tool_path");
  }
  d.circles.push_back({"base_circle", 0, 0, model.design.base_radius});
  const double mark = 0.1 * model.design.base_radius;
  d.lines.push_back({"center", -mark, 0, mark, 0});
  d.lines.push_back({"center", 0, -mark, 0, mark});
  if (with_follower) draw_follower(model, d);
  return d;
}

std::vector<gc::ContactState> sample_turn(const CamModel& model) {
  std::vector<gc::ContactState> out;
  for (int i = 0; i < model.samples; ++i) {
    out.push_back(gc::contact_at(model.design, model.design.program.start() + 2 * std::numbers::pi * i / model.samples));
  }
  return out;
}

io::Plot motion_plot(const CamModel& model, const std::vector<gc::ContactState>& samples) {
  const bool osc = oscillating(model);
  const bool timed = model.omega.has_value();
  const double w = model.omega.value_or(1);
  const std::string s_unit = osc ? "deg" : "mm";
  const std::string d_unit = osc ? "rad" : "mm";
  const std::string per = timed ? "s" : "rad";
  io::Plot plot;
  // Every plot states its speed (issue 32): the per-second values are at cam.speed, the
  // dynamics plot at the design speed.
  const std::string speed = timed ? fmt::format("at cam speed {:.6g} rpm", w * 30 / std::numbers::pi)
                                  : "per radian of cam angle (no cam speed given)";
  plot.title = fmt::format("Follower motion {}{}", speed, model.name.empty() ? "" : ": " + model.name);
  plot.x_label = "cam angle theta [deg]";
  io::PlotPanel s{fmt::format("{} [{}]", osc ? "psi" : "s", s_unit), {}, {}};
  io::PlotPanel v{fmt::format("velocity [{}/{}]", d_unit, per), {}, {}};
  io::PlotPanel a{fmt::format("acceleration [{}/{}^2]", d_unit, per), {}, {}};
  io::PlotPanel j{fmt::format("jerk [{}/{}^3]", d_unit, per), {}, {}};
  io::Series ss{s.y_label, {}, {}, ""}, vs{v.y_label, {}, {}, ""}, as{a.y_label, {}, {}, ""}, js{j.y_label, {}, {}, ""};
  for (std::size_t i = 0; i <= samples.size(); ++i) {
    const gc::ContactState& c = samples[i % samples.size()];
    const double theta = c.theta * deg_per_rad + (i == samples.size() ? 360.0 : 0.0);  // closes the turn
    const gc::MotionPerSecond m = gc::per_second(c.motion, w);
    for (io::Series* series : {&ss, &vs, &as, &js}) series->x.push_back(theta);
    ss.y.push_back(osc ? m.s * deg_per_rad : m.s);
    vs.y.push_back(m.v);
    as.y.push_back(m.a);
    js.y.push_back(m.j);
  }
  s.series.push_back(ss);
  v.series.push_back(vs);
  a.series.push_back(as);
  j.series.push_back(js);
  plot.panels = {s, v, a, j};
  return plot;
}

std::string motion_csv(const CamModel& model, const std::vector<gc::ContactState>& samples, const CamDynamics* dyn) {
  const bool osc = oscillating(model);
  std::string out = osc ? "theta_deg,psi_deg,dpsi_dtheta,d2psi_dtheta2,d3psi_dtheta3"
                        : "theta_deg,s_mm,ds_dtheta_mm,d2s_dtheta2_mm,d3s_dtheta3_mm";
  if (model.omega) out += osc ? ",omega_rad_s,alpha_rad_s2,jerk_rad_s3" : ",v_mm_s,a_mm_s2,j_mm_s3";
  out += ",pressure_angle_deg,rho_pitch_mm,pitch_x_mm,pitch_y_mm,profile_x_mm,profile_y_mm";
  const gc::ContactMaterial* material = model.contact ? &model.contact->material : nullptr;
  // Q beside F_n: the translating follower's axial force F_c = F_n cos phi, or the oscillating
  // arm's torque (cam_report_dynamics.cpp, axial_rows).
  if (dyn) out += fmt::format(",contact_force_N,{},camshaft_torque_N_m,power_W{}", osc ? "arm_torque_N_m" : "axial_force_N",
                              material ? ",hertz_stress_MPa" : "");
  out += "\n";
  for (const gc::ContactState& c : samples) {
    out += fmt::format("{:.6f},{:.9g},{:.9g},{:.9g},{:.9g}", c.theta * deg_per_rad,
                       osc ? c.motion.s * deg_per_rad : c.motion.s, c.motion.ds, c.motion.d2s, c.motion.d3s);
    if (model.omega) {
      const gc::MotionPerSecond m = gc::per_second(c.motion, *model.omega);
      out += fmt::format(",{:.9g},{:.9g},{:.9g}", m.v, m.a, m.j);
    }
    const double rho = c.curvature_pitch == 0 ? INFINITY : 1 / c.curvature_pitch;
    out += fmt::format(",{:.6f},{},{:.9f},{:.9f},{:.9f},{:.9f}", c.pressure_angle * deg_per_rad,
                       std::isfinite(rho) ? fmt::format("{:.6f}", rho) : std::string("inf"), c.pitch.x, c.pitch.y,
                       c.contact.x, c.contact.y);
    if (dyn) {
      const gc::DynamicState s = gc::dynamic_state(model.design, dyn->train, dyn->omega, c.theta, material);
      const double force = s.wall == 0 ? s.force / s.lever : s.contact_force * s.wall;
      out += fmt::format(",{:.9g},{:.9g},{:.9g},{:.9g}", force, s.force, s.torque, s.power);
      if (material) out += std::isnan(s.hertz_stress) ? std::string(",") : fmt::format(",{:.9g}", s.hertz_stress / 1e6);
    }
    out += "\n";
  }
  return out;
}

}  // namespace gearkit::plugins::cam
