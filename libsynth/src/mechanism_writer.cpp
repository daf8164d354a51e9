#include <gearkit/synth/mechanism_writer.hpp>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

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

const std::string& identifier(const std::string& name) {
  bool ok = !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0]));
  for (char c : name) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
  if (!ok) throw std::invalid_argument("mechanism sketch: '" + name + "' is not a plain name");
  return name;
}

// The emitter quotes what needs quoting (a title with ':', '#', quotes or a line break) and
// leaves names, numbers and "12.5 deg" plain; maps of points and the joint, driver and output
// entries stay in flow style, one per line, as a person would write the file.
void pair_mm(YAML::Emitter& y, const Vec2& v) { y << YAML::Flow << YAML::BeginSeq << mm(v.x()) << mm(v.y()) << YAML::EndSeq; }

void point_map(YAML::Emitter& y, const std::vector<SketchPoint>& points) {
  y << YAML::Flow << YAML::BeginMap;
  for (const SketchPoint& p : points) {
    y << YAML::Key << identifier(p.name) << YAML::Value;
    pair_mm(y, p.at);
  }
  y << YAML::EndMap;
}

void joint_entry(YAML::Emitter& y, const SketchJoint& j) {
  y << YAML::Flow << YAML::BeginMap << YAML::Key << "name" << YAML::Value << identifier(j.name);
  if (j.prismatic)
    y << YAML::Key << "type" << YAML::Value << "prismatic" << YAML::Key << "slider" << YAML::Value << j.first
      << YAML::Key << "guide" << YAML::Value << j.second << YAML::Key << "axis" << YAML::Value << degrees(j.axis);
  else
    y << YAML::Key << "type" << YAML::Value << "revolute" << YAML::Key << "at" << YAML::Value << YAML::Flow
      << YAML::BeginSeq << j.first << j.second << YAML::EndSeq;
  y << YAML::EndMap;
}

void output_entry(YAML::Emitter& y, const SketchOutput& o) {
  const char* key = o.type == "angle" ? "link" : o.type == "slider" ? "joint" : "point";
  y << YAML::Flow << YAML::BeginMap << YAML::Key << "name" << YAML::Value << identifier(o.name) << YAML::Key << "type"
    << YAML::Value << o.type << YAML::Key << key << YAML::Value << o.target << YAML::EndMap;
}

void driver_entry(YAML::Emitter& y, const SketchDriver& d) {
  y << YAML::Flow << YAML::BeginMap << YAML::Key << "name" << YAML::Value << identifier(d.name) << YAML::Key << "type"
    << YAML::Value << "angle" << YAML::Key << "link" << YAML::Value << identifier(d.link) << YAML::Key << "range"
    << YAML::Value << YAML::Flow << YAML::BeginSeq << degrees(d.start) << degrees(d.end) << degrees(d.step)
    << YAML::EndSeq << YAML::EndMap;
}

// One '#' line per comment (the emitter starts each line of a comment holding a line break with
// '#' too). It ends a comment with its line: a Newline after the last would leave a blank line.
void comment_lines(YAML::Emitter& y, const std::vector<std::string>& comments) {
  for (std::size_t i = 0; i < comments.size(); ++i) {
    if (i > 0) y << YAML::Newline;
    y << YAML::Comment(comments[i]);
  }
}

// Drawn step of a sweep: 1 deg, finer so that short travels still get 60 samples.
double sweep_step(double travel) { return std::min(1.0 * deg, std::max(travel, 1e-6) / 60.0); }

}  // namespace

std::string to_mechanism_yaml(const MechanismSketch& s) {
  YAML::Emitter y;
  comment_lines(y, s.comments);
  y << YAML::BeginMap << YAML::Key << "mechanism" << YAML::Value
    << (s.title.empty() ? std::string("synthesised linkage") : s.title);
  y << YAML::Key << "ground" << YAML::Value << YAML::BeginMap;
  for (const SketchPoint& p : s.ground) {
    y << YAML::Key << identifier(p.name) << YAML::Value;
    pair_mm(y, p.at);
  }
  y << YAML::EndMap << YAML::Key << "links" << YAML::Value << YAML::BeginMap;
  for (const SketchLink& l : s.links) {
    y << YAML::Key << identifier(l.name) << YAML::Value << YAML::BeginMap << YAML::Key << "points" << YAML::Value;
    point_map(y, l.points);
    y << YAML::Key << "angle" << YAML::Value << degrees(l.angle) << YAML::Key << "position" << YAML::Value;
    pair_mm(y, l.position);
    y << YAML::EndMap;
  }
  y << YAML::EndMap << YAML::Key << "joints" << YAML::Value << YAML::BeginSeq;
  for (const SketchJoint& j : s.joints) joint_entry(y, j);
  y << YAML::EndSeq << YAML::Key << "drivers" << YAML::Value << YAML::BeginSeq;
  driver_entry(y, s.driver);
  y << YAML::EndSeq;
  if (!s.outputs.empty()) {
    y << YAML::Key << "outputs" << YAML::Value << YAML::BeginSeq;
    for (const SketchOutput& o : s.outputs) output_entry(y, o);
    y << YAML::EndSeq;
  }
  y << YAML::EndMap;
  if (!y.good()) throw std::logic_error("mechanism sketch: " + y.GetLastError());
  return std::string(y.c_str()) + "\n";
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
