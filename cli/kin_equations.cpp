#include "kin_equations.hpp"

#include <gearkit/io/error.hpp>
#include <gearkit/io/yaml_model.hpp>
#include <gearkit/kin/joints.hpp>
#include <gearkit/sym/equations_file.hpp>
#include <gearkit/sym/loop_equations.hpp>

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace gearkit::cli {

namespace {

using sym::Expression;

// Every moving link's angle and every slide, when the file names no coordinates.
sym::EquationsInput default_coordinates(const kin::Model& m) {
  sym::EquationsInput in;
  for (std::size_t b = 0; b < m.bodies().size(); ++b) {
    const auto& pts = m.bodies()[b].points;
    if (pts.size() < 2 || (pts[0].second - pts[1].second).norm() < 1e-12) continue;
    sym::Coordinate c;
    c.name = fmt::format("phi{}", in.coordinates.size() + 1);
    c.angle.from = {static_cast<int>(b), pts[0].second};
    c.angle.to = {static_cast<int>(b), pts[1].second};
    in.coordinates.push_back(c);
  }
  int slides = 0;
  for (std::size_t k = 0; k < m.constraints().size(); ++k)
    if (const auto* p = dynamic_cast<const kin::Prismatic*>(m.constraints()[k].constraint.get())) {
      sym::Coordinate c;
      c.name = fmt::format("s{}", ++slides);
      c.is_angle = false;
      c.displacement.joint = static_cast<int>(k);
      c.displacement.origin = p->guide().local;
      in.coordinates.push_back(c);
    }
  return in;
}

std::string cell(const Expression& e, io::Format f) { return f == io::Format::md ? "$" + e.latex + "$" : e.text; }
std::string value(double v) { return std::isfinite(v) ? io::fixed(v, 6) : "singular"; }
nlohmann::json expr_json(const Expression& e, double v) {
  nlohmann::json j = {{"text", e.text}, {"latex", e.latex}};
  j["value"] = std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
  return j;
}

std::string unit_of(const sym::Coordinate& c, int order) {
  static const char* angle[] = {"rad", "rad/s", "rad/s^2"};
  static const char* length[] = {"mm", "mm/s", "mm/s^2"};
  return c.is_angle ? angle[order] : length[order];
}

void coordinate_table(io::Report& r, const sym::EquationsInput& in, const sym::CoordinateState& s, nlohmann::json& j) {
  io::Table t{"Generalised coordinates q (lengths in mm, angles in rad)", {"q", "value", "q'", "q''", "unit"}, {}};
  for (std::size_t k = 0; k < in.coordinates.size(); ++k) {
    const auto& c = in.coordinates[k];
    const Eigen::Index i = static_cast<Eigen::Index>(k);
    t.add_row({c.name, io::fixed(s.q[i], 6), io::fixed(s.qd[i], 6), io::fixed(s.qdd[i], 6), unit_of(c, 0)});
    j["coordinates"].push_back({{"name", c.name}, {"kind", c.is_angle ? "angle" : "displacement"},
                                {c.is_angle ? "value_rad" : "value_mm", s.q[i]},
                                {c.is_angle ? "rate_rad_s" : "rate_mm_s", s.qd[i]},
                                {c.is_angle ? "acceleration_rad_s2" : "acceleration_mm_s2", s.qdd[i]}});
    if (c.is_angle) j["coordinates"].back()["value_deg"] = s.q[i] * 180 / std::numbers::pi;
  }
  r.tables.push_back(t);
}

void symbol_table(io::Report& r, const sym::EquationsInput& in, const sym::Equations& eq, nlohmann::json& j) {
  if (eq.symbol_values.empty()) return;
  io::Table t{"Dimensions written as symbols", {"symbol", "value", "unit"}, {}};
  for (std::size_t k = 0; k < eq.symbol_values.size(); ++k) {
    const bool angle = in.symbols[k].kind == sym::Symbol::Kind::angle;
    const auto& [name, v] = eq.symbol_values[k];
    t.add_row({name, io::fixed(v, 6), angle ? "rad" : "mm"});
    j["symbols"][name] = {{angle ? "value_rad" : "value_mm", v}};
  }
  r.tables.push_back(t);
}

void equation_tables(io::Report& r, const sym::EquationsInput& in, const sym::Equations& eq, const sym::Evaluated& v,
                     io::Format f, nlohmann::json& j) {
  io::Table phi{"Constraint equations Phi(q) = 0", {"row", "Phi", "value"}, {}};
  std::vector<std::string> header = {"row"};
  for (const auto& c : in.coordinates) header.push_back("d/d" + c.name);
  io::Table jac{"Jacobian Phi_q", header, {}}, jac_v{"Jacobian Phi_q at this position", header, {}};
  io::Table vel{"Velocity equations Phi_q q' = 0", {"row", "Phi_q q'"}, {}};
  io::Table acc{"Acceleration equations Phi_q q'' = gamma", {"row", "gamma", "value"}, {}};
  for (std::size_t i = 0; i < eq.phi.size(); ++i) {
    const Eigen::Index ii = static_cast<Eigen::Index>(i);
    const std::string row = std::to_string(i + 1);
    phi.add_row({row, cell(eq.phi[i], f), value(v.phi[ii])});
    std::vector<std::string> sr = {row}, nr = {row};
    nlohmann::json jr = nlohmann::json::array();
    for (std::size_t k = 0; k < eq.phi_q[i].size(); ++k) {
      sr.push_back(cell(eq.phi_q[i][k], f));
      nr.push_back(value(v.phi_q(ii, static_cast<Eigen::Index>(k))));
      jr.push_back(expr_json(eq.phi_q[i][k], v.phi_q(ii, static_cast<Eigen::Index>(k))));
    }
    jac.add_row(sr);
    jac_v.add_row(nr);
    vel.add_row({row, cell(eq.velocity[i], f) + (f == io::Format::md ? "$= 0$" : " = 0")});
    acc.add_row({row, cell(eq.gamma[i], f), value(v.gamma[ii])});
    j["phi"].push_back(expr_json(eq.phi[i], v.phi[ii]));
    j["phi_q"].push_back(jr);
    j["velocity"].push_back({{"text", eq.velocity[i].text}, {"latex", eq.velocity[i].latex}});
    j["gamma"].push_back(expr_json(eq.gamma[i], v.gamma[ii]));
  }
  for (auto* t : {&phi, &jac, &jac_v, &vel, &acc}) r.tables.push_back(*t);
}

void ratio_table(io::Report& r, const sym::EquationsInput& in, const sym::Equations& eq, const sym::Evaluated& v,
                 io::Format f, nlohmann::json& j) {
  if (eq.ratios.empty()) return;
  io::Table t{"Velocity ratios", {"ratio", "formula", "value"}, {}};
  for (std::size_t k = 0; k < eq.ratios.size(); ++k) {
    const auto& ratio = eq.ratios[k];
    const std::string name = in.coordinates[static_cast<std::size_t>(ratio.dependent)].name + "'/" +
                             in.coordinates[static_cast<std::size_t>(ratio.independent)].name + "'";
    t.add_row({name, cell(ratio.formula, f), value(v.ratios[static_cast<Eigen::Index>(k)])});
    nlohmann::json jr = expr_json(ratio.formula, v.ratios[static_cast<Eigen::Index>(k)]);
    jr["ratio"] = name;
    j["ratios"].push_back(jr);
  }
  r.tables.push_back(t);
}

}  // namespace

void add_equations_section(io::Report& report, const mechanism::Mechanism& mech, const KinAnalysis& analysis, io::Format format) {
  if (analysis.positions.empty()) {
    report.warnings.push_back("--equations: no assembled position to write the equations at");
    return;
  }
  const io::YamlDocument doc = io::load_yaml_file(mech.file);
  const YAML::Node section = doc.root["equations"];
  const sym::EquationsInput in =
      section ? sym::read_equations_input(section, doc.file, mech.model) : default_coordinates(mech.model);
  const KinPosition& p = analysis.positions.front();
  sym::Equations eq;
  try {
    eq = sym::loop_equations(mech.model, in, p.q, analysis.dof.dof);
  } catch (const std::invalid_argument& e) {
    io::fail_at(section ? io::mark_of(section, doc.file) : io::SourceMark{doc.file, 0, 0}, e.what());
  }
  const sym::CoordinateState s = sym::coordinate_state(mech.model, in, p.q, p.qd, p.qdd);
  const sym::Evaluated v = sym::evaluate(eq, s);
  nlohmann::json j = nlohmann::json::object();
  j["loops"] = eq.loops;
  coordinate_table(report, in, s, j);
  symbol_table(report, in, eq, j);
  equation_tables(report, in, eq, v, format, j);
  ratio_table(report, in, eq, v, format, j);
  const int rows = static_cast<int>(eq.phi.size()), n = static_cast<int>(in.coordinates.size());
  report.notes.push_back(fmt::format("Equations: {} coordinates, {} independent constraint equations from the loops {}; "
                                     "n - m = {} against {} degree(s) of freedom.", n, rows, fmt::join(eq.loops, "; "),
                                     n - rows, analysis.dof.dof));
  if (n - rows != analysis.dof.dof)
    report.warnings.push_back(fmt::format("--equations: the coordinates give {} equation(s) for {} coordinates but the "
                                          "mechanism has {} degree(s) of freedom: a loop passes a link whose angle is "
                                          "not a coordinate", rows, n, analysis.dof.dof));
  report.json["equations"] = j;
}

}  // namespace gearkit::cli

extern "C" void gearkit_add_equations_section(gearkit::io::Report& report, const gearkit::mechanism::Mechanism& mech,
                                              const gearkit::cli::KinAnalysis& analysis, gearkit::io::Format format) {
  gearkit::cli::add_equations_section(report, mech, analysis, format);
}
