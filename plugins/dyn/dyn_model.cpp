#include "dyn_model.hpp"

#include "dyn_mechanism.hpp"

#include <gearkit/io/quantity.hpp>
#include <gearkit/io/limits.hpp>
#include <gearkit/io/yaml_model.hpp>

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <numbers>
#include <stdexcept>
#include <unistd.h>

namespace gearkit::plugins::dyn {

namespace {

// A fraction written as a plain number or a percentage ("0.005", "0.5 %").
double fraction(io::MapReader& r, const std::string& key) {
  const YAML::Node n = r.node(key);
  std::string text = io::scalar_text(n, r.file(), fmt::format("a number for '{}'", key));
  double factor = 1;
  if (const auto p = text.find('%'); p != std::string::npos && text.find_first_not_of(" \t", p + 1) == std::string::npos) {
    text.erase(p);
    factor = 0.01;
  }
  try {
    return factor * io::parse_quantity_si(text, io::Quantity::dimensionless, "");
  } catch (const io::QuantityError& e) {
    io::fail_at(r.mark(key), fmt::format("'{}': {}", key, e.what()));
  }
}

// A speed ratio as a number or a fraction of two numbers ("5/17"), as the seeds write them.
double ratio(io::MapReader& r, const std::string& key) {
  const std::string text = io::scalar_text(r.node(key), r.file(), fmt::format("a number for '{}'", key));
  const auto slash = text.find('/');
  try {
    if (slash == std::string::npos) return io::parse_quantity_si(text, io::Quantity::dimensionless, "");
    const double num = io::parse_quantity_si(text.substr(0, slash), io::Quantity::dimensionless, "");
    const double den = io::parse_quantity_si(text.substr(slash + 1), io::Quantity::dimensionless, "");
    if (den == 0) io::fail_at(r.mark(key), fmt::format("'{}': the fraction '{}' divides by zero", key, text));
    return num / den;
  } catch (const io::QuantityError& e) {
    io::fail_at(r.mark(key), fmt::format("'{}': expected a number or a fraction like 5/17: {}", key, e.what()));
  }
}

double efficiency(io::MapReader& r, const std::string& key) {
  if (!r.has(key)) return 1.0;
  const double eta = fraction(r, key);
  if (!(eta > 0 && eta <= 1))
    io::fail_at(r.mark(key), fmt::format("'{}': expected an efficiency in (0, 1], found {:g}", key, eta));
  return eta;
}

double non_negative(io::MapReader& r, const std::string& key, io::Quantity q, std::string_view unit) {
  const double v = r.quantity_or(key, q, unit, 0.0);
  if (v < 0) io::fail_at(r.mark(key), fmt::format("'{}': expected a value >= 0, found a negative one", key));
  return v;
}

double positive(io::MapReader& r, const std::string& key, io::Quantity q, std::string_view unit) {
  const double v = r.quantity(key, q, unit);
  if (!(v > 0)) io::fail_at(r.mark(key), fmt::format("'{}': expected a positive value, found {:g} (in SI units)", key, v));
  return v;
}

std::optional<double> optional_positive(io::MapReader& r, const std::string& key, io::Quantity q, std::string_view unit) {
  if (!r.has(key)) return std::nullopt;
  return positive(r, key, q, unit);
}

// A plane vector as components [x, y] or as {magnitude, angle} (angle from +x, counter-clockwise).
gd::Vec2 vector(io::MapReader& r, const std::string& key, io::Quantity q, std::string_view unit) {
  const YAML::Node n = r.node(key);
  if (n.IsSequence() && n.size() == 2)
    return {io::scalar_quantity(n[0], r.file(), q, unit), io::scalar_quantity(n[1], r.file(), q, unit)};
  if (n.IsMap()) {
    io::MapReader v(n, r.file(), "'" + key + "'");
    const double magnitude = v.quantity("magnitude", q, unit);
    const double angle = v.quantity("angle", io::Quantity::angle, "deg");
    v.finish();
    return {magnitude * std::cos(angle), magnitude * std::sin(angle)};
  }
  io::fail_at(r.mark(key), fmt::format("'{}': expected [x, y] or {{magnitude: ..., angle: ...}}", key));
}

std::optional<TorqueLaw> optional_law(io::MapReader& r, const std::string& key, const std::string& what) {
  if (const auto n = r.optional_node(key)) return read_law(*n, r.file(), what);
  return std::nullopt;
}

void read_motor(io::MapReader& root, Model& m) {
  m.motor.mark = root.mark();
  m.line.shaft_inertia = {0.0};
  m.line.shaft_names = {"motor"};
  if (!root.has("motor")) return;  // a model may ask only for a reduced force
  io::MapReader r = root.map("motor");
  m.motor.mark = r.mark();
  m.motor.speed = optional_positive(r, "speed", io::Quantity::angular_velocity, "rpm");
  m.motor.power = optional_positive(r, "power", io::Quantity::power, "W");
  m.motor.torque = optional_law(r, "torque", "motor torque");
  if (m.motor.torque && m.motor.torque->balance)
    io::fail_at(m.motor.torque->mark, "motor torque: 'scale: balance' belongs on a flywheel's torque");
  if (m.motor.power && m.motor.torque)
    io::fail_at(r.mark("torque"), "motor: give either 'power' (with 'speed') or 'torque', not both");
  if (m.motor.power && !m.motor.speed)
    io::fail_at(r.mark("power"), "motor: 'power' needs the nominal 'speed' to give the torque");
  m.line.motor_efficiency = efficiency(r, "efficiency");
  m.line.shaft_inertia = {non_negative(r, "inertia", io::Quantity::moment_of_inertia, "kg*m^2")};
  m.line.shaft_names = {"motor"};
  r.finish();
}

// The speed of the load shaft over the motor's, and so the reduced torques (its inverse) and
// inertias (its square), stay within these bounds: beyond them a product of stages under- or
// overflows a double (a thousand 20:50 stages gave 0.4^1000 = 1e-398) or a reduced value leaves
// the sizes of quantity.hpp. Real drives stay far inside (a worm of 1:100 after 1:100 is 1e-4).
constexpr double kLargestOverallRatio = 1e6;

void read_stages(io::MapReader& root, Model& m) {
  if (!root.has("stages")) return;
  double overall = 1;
  for (const YAML::Node& item : root.sequence("stages", io::limits::kDynListItems, "stages")) {
    io::MapReader r(item, root.file(), "stage");
    gd::Stage s;
    s.name = r.has("name") ? r.string("name") : fmt::format("stage {}", m.line.stages.size() + 1);
    if (r.has("teeth") == r.has("ratio"))
      io::fail_at(r.mark(), fmt::format("stage '{}': expected exactly one of 'ratio' (w_out/w_in) or 'teeth' "
                                        "[z_driving, z_driven]", s.name));
    if (r.has("teeth")) {
      const YAML::Node t = r.node("teeth");
      if (!t.IsSequence() || t.size() != 2)
        io::fail_at(r.mark("teeth"), "'teeth': expected [z_driving, z_driven]");
      double z[2];
      for (std::size_t i = 0; i < 2; ++i) {
        z[i] = io::scalar_quantity(t[i], root.file(), io::Quantity::dimensionless, "");
        if (!(z[i] >= 1) || z[i] != std::floor(z[i]))
          io::fail_at(io::mark_of(t[i], root.file()), fmt::format("'teeth': expected a whole number >= 1, found {:g}", z[i]));
      }
      s.ratio = z[0] / z[1];
    } else {
      s.ratio = ratio(r, "ratio");
      if (!std::isfinite(s.ratio) || s.ratio == 0)
        io::fail_at(r.mark("ratio"), fmt::format("'ratio': expected w_out/w_in, finite and non-zero, found {:g}", s.ratio));
    }
    overall *= s.ratio;
    if (!(std::abs(overall) <= kLargestOverallRatio && std::abs(overall) >= 1 / kLargestOverallRatio))
      io::fail_at(r.mark(), fmt::format("stage '{}': expected an overall ratio w_load/w_motor between 1e-6 and 1e6 in "
                                        "size, found {:.3g} with this stage",
                                        s.name, overall));
    s.efficiency = efficiency(r, "efficiency");
    const double inertia = non_negative(r, "inertia", io::Quantity::moment_of_inertia, "kg*m^2");
    const std::string at = r.choice("inertia_at", {"input", "output"}, std::string("output"));
    m.line.stages.push_back(s);
    m.line.shaft_inertia.push_back(0);
    m.line.shaft_names.push_back(s.name);
    (at == "output" ? m.line.shaft_inertia.back() : m.line.shaft_inertia[m.line.shaft_inertia.size() - 2]) += inertia;
    m.stage_marks.push_back(r.mark());
    r.finish();
  }
}

void read_load(io::MapReader& root, Model& m, const mechanism::ElementTypeLookup& elements) {
  if (!root.has("load")) return;
  io::MapReader r = root.map("load");
  m.load.mark = r.mark();
  if (r.has("name")) m.load.name = r.string("name");
  m.line.shaft_names.back() = m.load.name;
  m.line.shaft_inertia.back() += non_negative(r, "inertia", io::Quantity::moment_of_inertia, "kg*m^2");
  m.load.radius = optional_positive(r, "radius", io::Quantity::length, "mm");
  const double mass = non_negative(r, "mass", io::Quantity::mass, "kg");
  m.load.force = non_negative(r, "force", io::Quantity::force, "N");
  if ((mass > 0 || m.load.force > 0) && !m.load.radius)
    io::fail_at(r.mark(), "load: 'mass' and 'force' act at the rim and need the 'radius'");
  if (m.load.radius) m.line.shaft_inertia.back() += mass * *m.load.radius * *m.load.radius;
  m.load.resisting = optional_law(r, "resisting", "resisting torque of the load");
  if (r.has("mechanism")) {
    // A linkage from a `gearkit kin` model file, path relative to this file.
    if (r.has("inertia_table")) io::fail_at(r.mark("mechanism"), "load: give 'mechanism' or 'inertia_table', not both");
    m.load.inertia_table_mark = r.mark("mechanism");
    const std::string given = r.string("mechanism");
    std::filesystem::path path = given;
    if (path.is_relative()) path = std::filesystem::path(r.file()).parent_path() / path;
    // A file that cannot be read is this model's mistake: said at the value, quoted as written
    // (the mechanism file's own errors carry its own file, line and column).
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
      io::fail_at(r.mark("mechanism"), fmt::format("'mechanism': expected a mechanism file, found the folder {}", io::quote(given)));
    if (::access(path.c_str(), R_OK) != 0)
      io::fail_at(r.mark("mechanism"), fmt::format("'mechanism': cannot read {}: {}", io::quote(given),
                                                   errno == ENOENT ? "no such file" : std::strerror(errno)));
    const long long intervals = r.optional_integer("mechanism_steps").value_or(360);
    if (intervals < 36 || intervals > 36000)
      io::fail_at(r.mark("mechanism_steps"), fmt::format("'mechanism_steps': expected 36 to 36000, found {}", intervals));
    m.load.inertia_table.emplace(
        mechanism_inertia_table(path.string(), static_cast<int>(intervals), m.load.inertia_table_mark, elements));
  }
  if (r.has("inertia_table")) {
    m.load.inertia_table_mark = r.mark("inertia_table");
    std::vector<double> angle, inertia;
    for (const YAML::Node& row : r.sequence("inertia_table", io::limits::kDynTableRows, "rows")) {
      if (!row.IsSequence() || row.size() != 2)
        io::fail_at(io::mark_of(row, r.file()), "inertia_table: expected a row [angle, inertia]");
      angle.push_back(io::scalar_quantity(row[0], r.file(), io::Quantity::angle, "deg"));
      inertia.push_back(io::scalar_quantity(row[1], r.file(), io::Quantity::moment_of_inertia, "kg*m^2"));
    }
    if (!angle.empty() && std::abs(angle.front()) > 1e-12)
      io::fail_at(m.load.inertia_table_mark, "inertia_table: the first row must be at 0 deg");
    try {
      m.load.inertia_table.emplace(std::move(angle), std::move(inertia), std::vector<double>{}, true);
    } catch (const std::invalid_argument& e) {
      io::fail_at(m.load.inertia_table_mark, e.what());
    }
  }
  r.finish();
}

void read_flywheel(io::MapReader& root, Model& m) {
  if (!root.has("flywheel")) return;
  io::MapReader r = root.map("flywheel");
  FlywheelQuestion q;
  q.mark = r.mark();
  q.cycle = r.has("cycle") ? positive(r, "cycle", io::Quantity::angle, "deg") : 2 * std::numbers::pi;
  q.fluctuation = fraction(r, "fluctuation");
  q.fluctuation_mark = r.mark("fluctuation");
  if (!(q.fluctuation > 0 && q.fluctuation < 2))
    io::fail_at(q.fluctuation_mark, fmt::format("'fluctuation': expected a coefficient of speed fluctuation in (0, 2), "
                                                "found {:g}", q.fluctuation));
  q.drive = optional_law(r, "drive", "driving torque");
  q.resisting = optional_law(r, "resisting", "resisting torque");
  r.finish();
  m.flywheel = q;
}

void read_energy(io::MapReader& root, Model& m) {
  if (!root.has("energy")) return;
  io::MapReader r = root.map("energy");
  EnergyQuestion q;
  q.mark = r.mark();
  q.cycle = optional_positive(r, "cycle", io::Quantity::angle, "deg");
  q.cycle_time = optional_positive(r, "cycle_time", io::Quantity::time, "s");
  if (q.cycle.has_value() == q.cycle_time.has_value())
    io::fail_at(r.mark(), "energy: expected exactly one of 'cycle' (angle of the load shaft) or 'cycle_time'");
  q.report_time = optional_positive(r, "report_time", io::Quantity::time, "s");
  for (const YAML::Node& item : r.sequence("loads", io::limits::kDynListItems, "loads")) {
    io::MapReader l(item, root.file(), "energy load");
    EnergyLoad load;
    load.mark = l.mark();
    load.name = l.string("name");
    load.torque = optional_law(l, "torque", "torque of " + io::quote(load.name));
    load.force = non_negative(l, "force", io::Quantity::force, "N");
    load.energy = non_negative(l, "energy", io::Quantity::energy, "J");
    load.mass_to_speed = non_negative(l, "mass_to_speed", io::Quantity::mass, "kg");
    load.useful = l.boolean_or("useful", false);
    if (load.torque && load.torque->balance)
      io::fail_at(load.torque->mark, "a load's torque over the cycle cannot take 'scale: balance'");
    if (load.torque && load.torque->kind == TorqueLaw::Kind::constant_power)
      io::fail_at(load.torque->mark, "a load's torque over the cycle cannot be a constant power");
    if ((load.force > 0 || load.mass_to_speed > 0) && !m.load.radius)
      io::fail_at(l.mark(), fmt::format("load '{}': 'force' and 'mass_to_speed' act at the rim and need "
                                        "load.radius", load.name));
    l.finish();
    q.loads.push_back(std::move(load));
  }
  if (r.has("phases")) {
    for (const YAML::Node& item : r.sequence("phases", io::limits::kDynListItems, "phases")) {
      io::MapReader p(item, root.file(), "phase");
      EnergyPhase phase;
      phase.mark = p.mark();
      phase.name = p.string("name");
      phase.from = p.quantity("from", io::Quantity::angle, "deg");
      phase.to = p.quantity("to", io::Quantity::angle, "deg");
      if (!(phase.to > phase.from))
        io::fail_at(p.mark("to"), fmt::format("phase {}: 'to' must be after 'from'", io::quote(phase.name)));
      p.finish();
      q.phases.push_back(phase);
    }
  }
  r.finish();
  m.energy = std::move(q);
}

void read_motion(io::MapReader& root, Model& m) {
  if (!root.has("motion")) return;
  io::MapReader r = root.map("motion");
  MotionQuestion q;
  q.mark = r.mark();
  q.speed = non_negative(r, "speed", io::Quantity::angular_velocity, "rpm");
  q.angle = r.quantity_or("angle", io::Quantity::angle, "deg", 0.0);
  q.t_end = positive(r, "t_end", io::Quantity::time, "s");
  if (r.has("output_step")) q.output_step = positive(r, "output_step", io::Quantity::time, "s");
  if (q.t_end / (q.output_step > 0 ? q.output_step : q.t_end / 2000) > 2e6)
    io::fail_at(r.mark("output_step"), "'output_step': more than 2 000 000 samples; give a larger step");
  if (r.has("steady_tolerance")) {
    q.steady_tolerance = r.number("steady_tolerance");
    if (!(q.steady_tolerance > 0 && q.steady_tolerance < 1))
      io::fail_at(r.mark("steady_tolerance"), "'steady_tolerance': expected a number in (0, 1)");
  }
  if (r.has("acceleration_at")) {
    const YAML::Node list = r.node("acceleration_at");
    if (!list.IsSequence()) io::fail_at(r.mark("acceleration_at"), "'acceleration_at': expected a list of speeds");
    for (const YAML::Node& s : list)
      q.acceleration_at.push_back(io::scalar_quantity(s, root.file(), io::Quantity::angular_velocity, "rpm"));
  }
  q.with_flywheel_mark = r.mark("with_flywheel");
  q.with_flywheel = r.boolean_or("with_flywheel", false);
  if (q.with_flywheel && !m.flywheel)
    io::fail_at(q.with_flywheel_mark, "'with_flywheel': needs a 'flywheel' question to size the flywheel");
  r.finish();
  m.motion = q;
}

void read_reduced_force(io::MapReader& root, Model& m) {
  if (!root.has("reduced_force")) return;
  io::MapReader r = root.map("reduced_force");
  ReducedForceQuestion q;
  q.mark = r.mark();
  q.point = r.has("point") ? r.string("point") : std::string("A");
  q.point_velocity = vector(r, "point_velocity", io::Quantity::velocity, "m/s");
  if (r.has("shaft_speed")) q.shaft_speed = r.quantity("shaft_speed", io::Quantity::angular_velocity, "rad/s");
  for (const YAML::Node& item : r.sequence("terms", io::limits::kDynListItems, "terms")) {
    io::MapReader t(item, root.file(), "reduced-force term");
    ReducedForceTerm term;
    term.mark = t.mark();
    term.name = t.string("name");
    term.velocity = vector(t, "velocity", io::Quantity::velocity, "m/s");
    if (t.has("force")) term.force = vector(t, "force", io::Quantity::force, "N");
    if (t.has("mass")) {
      term.mass = non_negative(t, "mass", io::Quantity::mass, "kg");
      if (t.has("acceleration")) term.acceleration = vector(t, "acceleration", io::Quantity::acceleration, "m/s^2");
      term.gravity = t.quantity_or("gravity", io::Quantity::acceleration, "m/s^2", gd::standard_gravity);
    }
    if (!t.has("force") && !t.has("mass"))
      io::fail_at(t.mark(), fmt::format("term {}: expected a 'force', a 'mass' or both", io::quote(term.name)));
    t.finish();
    q.terms.push_back(term);
  }
  r.finish();
  m.reduced_force = q;
}

}  // namespace

Model load_model(const std::string& path, const mechanism::ElementTypeLookup& elements) {
  const io::YamlDocument doc = io::load_yaml_file(path);
  io::MapReader root(doc.root, doc.file, "dyn model");
  Model m;
  m.file = doc.file;
  m.title = root.has("title") ? root.string("title") : std::string();
  m.has_drive_line = root.has("motor") || root.has("stages") || root.has("load");
  read_motor(root, m);
  read_stages(root, m);
  read_load(root, m, elements);
  read_flywheel(root, m);
  read_energy(root, m);
  read_motion(root, m);
  read_reduced_force(root, m);
  root.finish();
  if (!m.flywheel && !m.energy && !m.motion && !m.reduced_force)
    io::fail_at(root.mark(), "dyn model: expected at least one question: 'flywheel', 'energy', 'motion' or "
                             "'reduced_force'");
  try {
    gd::validate(m.line);
  } catch (const std::invalid_argument& e) {
    io::fail_at(root.mark(), e.what());
  }
  return m;
}

}  // namespace gearkit::plugins::dyn
