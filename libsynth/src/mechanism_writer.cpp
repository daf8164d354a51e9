#include <gearkit/synth/mechanism_writer.hpp>

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gearkit::synth {

namespace {

constexpr double deg = std::numbers::pi / 180;

std::string number(double v, double scale) {
  if (!std::isfinite(v)) throw std::invalid_argument("mechanism sketch: a value is not finite");
  const double x = v * scale;
  return fmt::format("{:.10g}", std::abs(x) < 1e-12 ? 0.0 : x);
}
std::string mm(double metres) { return number(metres, 1000.0); }
std::string degrees(double radians) { return number(radians, 1.0 / deg) + " deg"; }
std::string pair_mm(const Vec2& v) { return "[" + mm(v.x()) + ", " + mm(v.y()) + "]"; }

const std::string& identifier(const std::string& name) {
  bool ok = !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0]));
  for (char c : name) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
  if (!ok) throw std::invalid_argument("mechanism sketch: '" + name + "' is not a plain name");
  return name;
}

std::string point_map(const std::vector<SketchPoint>& points) {
  std::string s;
  for (const SketchPoint& p : points) s += (s.empty() ? "" : ", ") + identifier(p.name) + ": " + pair_mm(p.at);
  return "{" + s + "}";
}

std::string joint_line(const SketchJoint& j) {
  if (j.prismatic)
    return fmt::format("  - {{name: {}, type: prismatic, slider: {}, guide: {}, axis: {}}}\n", identifier(j.name),
                       j.first, j.second, degrees(j.axis));
  return fmt::format("  - {{name: {}, type: revolute, at: [{}, {}]}}\n", identifier(j.name), j.first, j.second);
}

std::string output_line(const SketchOutput& o) {
  const char* key = o.type == "angle" ? "link" : o.type == "slider" ? "joint" : "point";
  return fmt::format("  - {{name: {}, type: {}, {}: {}}}\n", identifier(o.name), o.type, key, o.target);
}

// Drawn step of a sweep: 1 deg, finer so that short travels still get 60 samples.
double sweep_step(double travel) { return std::min(1.0 * deg, std::max(travel, 1e-6) / 60.0); }

}  // namespace

std::string to_mechanism_yaml(const MechanismSketch& s) {
  std::string y;
  for (const std::string& c : s.comments) y += "# " + c + "\n";
  y += "mechanism: " + (s.title.empty() ? std::string("synthesised linkage") : s.title) + "\n";
  y += "ground:\n";
  for (const SketchPoint& p : s.ground) y += "  " + identifier(p.name) + ": " + pair_mm(p.at) + "\n";
  y += "links:\n";
  for (const SketchLink& l : s.links) {
    y += "  " + identifier(l.name) + ":\n";
    y += "    points: " + point_map(l.points) + "\n";
    y += "    angle: " + degrees(l.angle) + "\n";
    y += "    position: " + pair_mm(l.position) + "\n";
  }
  y += "joints:\n";
  for (const SketchJoint& j : s.joints) y += joint_line(j);
  const SketchDriver& d = s.driver;
  y += "drivers:\n";
  y += fmt::format("  - {{name: {}, type: angle, link: {}, range: [{}, {}, {}]}}\n", identifier(d.name),
                   identifier(d.link), degrees(d.start), degrees(d.end), degrees(d.step));
  if (!s.outputs.empty()) y += "outputs:\n";
  for (const SketchOutput& o : s.outputs) y += output_line(o);
  return y;
}

MechanismSketch four_bar_sketch(const FourBar& f, double theta2_start, double travel, int direction,
                                std::string title) {
  const auto pose = pose_at(f, theta2_start);
  if (!pose) throw std::invalid_argument("four_bar_sketch: the linkage cannot be assembled at the start angle");
  MechanismSketch s;
  s.title = std::move(title);
  s.ground = {{"O2", f.O2}, {"O4", f.O4}};
  s.links = {{"crank", {{"O2", {0, 0}}, {"A", {f.crank, 0}}}, pose->theta2, f.O2},
             {"coupler", {{"A", {0, 0}}, {"B", {f.coupler, 0}}, {"P", f.coupler_point}}, pose->theta3, pose->A},
             {"rocker", {{"O4", {0, 0}}, {"B", {f.rocker, 0}}}, pose->theta4, f.O4}};
  s.joints = {{"O2", "crank.O2", "ground.O2"},
              {"A", "crank.A", "coupler.A"},
              {"B", "coupler.B", "rocker.B"},
              {"O4", "rocker.O4", "ground.O4"}};
  s.driver = {"theta2", "crank", theta2_start, theta2_start + direction * travel, sweep_step(travel)};
  s.outputs = {{"theta3", "angle", "coupler"}, {"theta4", "angle", "rocker"}, {"Px", "x", "coupler.P"},
               {"Py", "y", "coupler.P"}};
  return s;
}

MechanismSketch slider_crank_sketch(const SliderCrank& k, double theta2_start, double travel, int direction,
                                    std::string title) {
  const auto s_start = slider_position(k, theta2_start);
  if (!s_start) throw std::invalid_argument("slider_crank_sketch: the rod cannot reach the guide at the start angle");
  const Vec2 u(std::cos(k.axis_angle), std::sin(k.axis_angle)), n(-u.y(), u.x());
  const Vec2 G = k.O2 + k.offset * n;
  const Vec2 A = k.O2 + k.crank * Vec2(std::cos(theta2_start), std::sin(theta2_start));
  const Vec2 B = G + *s_start * u;
  MechanismSketch s;
  s.title = std::move(title);
  s.ground = {{"O2", k.O2}, {"G", G}};
  s.links = {{"crank", {{"O2", {0, 0}}, {"A", {k.crank, 0}}}, theta2_start, k.O2},
             {"rod", {{"A", {0, 0}}, {"B", {k.rod, 0}}}, std::atan2(B.y() - A.y(), B.x() - A.x()), A},
             {"slider", {{"B", {0, 0}}}, k.axis_angle, B}};
  s.joints = {{"O2", "crank.O2", "ground.O2"},
              {"A", "crank.A", "rod.A"},
              {"B", "rod.B", "slider.B"},
              {"guide", "slider.B", "ground.G", true, k.axis_angle}};
  s.driver = {"theta2", "crank", theta2_start, theta2_start + direction * travel, sweep_step(travel)};
  s.outputs = {{"s", "slider", "guide"}, {"theta3", "angle", "rod"}};
  return s;
}

}  // namespace gearkit::synth
