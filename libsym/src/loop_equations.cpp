#include <gearkit/sym/loop_equations.hpp>

#include "loop_writer.hpp"
#include "symbolic_system.hpp"
#include "trig.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

namespace gearkit::sym {

using GiNaC::ex;

namespace {

constexpr double kMm = 1000.0;
constexpr int kMaxLinks = 60, kMaxJoints = 80;
constexpr std::size_t kMaxLoops = 2000;

double wrap(double a) { return std::remainder(a, 2 * 3.14159265358979323846); }

double to_double(const ex& e, const GiNaC::exmap& values) {
  const ex v = e.subs(values).evalf();
  return GiNaC::is_a<GiNaC::numeric>(v) ? GiNaC::ex_to<GiNaC::numeric>(v).to_double()
                                         : std::numeric_limits<double>::quiet_NaN();
}

Eigen::Vector2d world(const Eigen::VectorXd& q, const kin::BodyPoint& p) { return kin::Model::point_position(q, p); }
double angle_of(const Eigen::VectorXd& q, int body) { return body == kin::kGround ? 0.0 : q[3 * body + 2]; }

void check_name(const std::string& name, std::set<std::string>& seen) {
  static const std::set<std::string> reserved = {"sin", "cos", "tan", "exp", "log", "sqrt", "Pi", "I", "Euler", "Catalan"};
  bool ok = !name.empty() && std::isalpha(static_cast<unsigned char>(name[0]));
  for (char ch : name) ok = ok && std::isalnum(static_cast<unsigned char>(ch));
  if (!ok || reserved.count(name))
    throw std::invalid_argument(fmt::format("expected a symbol name of letters and digits (phi1, l3, s), found '{}'", name));
  if (!seen.insert(name).second) throw std::invalid_argument(fmt::format("the name '{}' is used twice", name));
}

void validate(const kin::Model& model, const EquationsInput& input) {
  if (static_cast<int>(model.bodies().size()) > kMaxLinks || static_cast<int>(model.constraints().size()) > kMaxJoints)
    throw std::invalid_argument(fmt::format("--equations handles at most {} links and {} joints", kMaxLinks, kMaxJoints));
  std::set<std::string> seen;
  for (const Coordinate& c : input.coordinates) {
    check_name(c.name, seen);
    if (c.is_angle && (c.angle.from.body != c.angle.to.body || (c.angle.from.local - c.angle.to.local).norm() < 1e-12))
      throw std::invalid_argument(fmt::format("coordinate '{}': expected two distinct points of one link", c.name));
    if (c.is_angle && c.angle.from.body == kin::kGround)
      throw std::invalid_argument(fmt::format("coordinate '{}': the ground does not turn", c.name));
    if (!c.is_angle && !dynamic_cast<const kin::Prismatic*>(
                           model.constraints().at(static_cast<std::size_t>(c.displacement.joint)).constraint.get()))
      throw std::invalid_argument(fmt::format("coordinate '{}': expected a prismatic joint", c.name));
  }
  for (const Symbol& s : input.symbols) {
    check_name(s.name, seen);
    if (s.a.body != s.b.body || (s.kind == Symbol::Kind::angle && (s.c.body != s.a.body || s.d.body != s.a.body)))
      throw std::invalid_argument(fmt::format("symbol '{}': expected points of one link", s.name));
  }
}

double symbol_value(const Symbol& s, const Eigen::VectorXd& pose) {
  const Eigen::Vector2d v = s.b.local - s.a.local;
  switch (s.kind) {
    case Symbol::Kind::length: return v.norm() * kMm;
    case Symbol::Kind::dx: return (Eigen::Rotation2Dd(angle_of(pose, s.a.body)) * v).x() * kMm;
    case Symbol::Kind::dy: return (Eigen::Rotation2Dd(angle_of(pose, s.a.body)) * v).y() * kMm;
    case Symbol::Kind::angle: {
      const Eigen::Vector2d w = s.d.local - s.c.local;
      return wrap(std::atan2(w.y(), w.x()) - std::atan2(v.y(), v.x()));
    }
  }
  return 0.0;
}

void make_symbols(const EquationsInput& input, const Eigen::VectorXd& pose, SymbolicSystem& sys) {
  for (const Coordinate& c : input.coordinates) {
    const std::string tex = c.tex.empty() ? detail::tex_name(c.name) : c.tex;
    sys.q.emplace_back(c.name, tex);
    sys.qd.emplace_back("d" + c.name, "\\dot{" + tex + "}");
    sys.qdd.emplace_back("dd" + c.name, "\\ddot{" + tex + "}");
  }
  for (const Symbol& s : input.symbols) {
    sys.params.emplace_back(s.name, s.tex.empty() ? detail::tex_name(s.name) : s.tex);
    sys.param_values.push_back(symbol_value(s, pose));
  }
}

// Rows of the loops, kept while they raise the rank of Phi_q at the pose, up to n - dof.
void select_rows(const detail::LoopWriter& writer, const std::vector<detail::Loop>& loops, const CoordinateState& at,
                 int wanted, SymbolicSystem& sys, std::vector<std::string>& described) {
  const GiNaC::exmap values = sys.values(at);
  const Eigen::Index n = static_cast<Eigen::Index>(sys.q.size());
  Eigen::MatrixXd kept(0, n);
  for (const detail::Loop& loop : loops) {
    if (static_cast<int>(sys.phi.size()) >= wanted) break;
    bool used = false;
    for (const ex& row : writer.rows(loop)) {
      Eigen::MatrixXd trial(kept.rows() + 1, n);
      trial.topRows(kept.rows()) = kept;
      for (Eigen::Index j = 0; j < n; ++j) trial(kept.rows(), j) = to_double(row.diff(sys.q[static_cast<std::size_t>(j)]), values);
      Eigen::FullPivLU<Eigen::MatrixXd> lu(trial);
      lu.setThreshold(1e-9);
      if (lu.rank() <= kept.rows() || static_cast<int>(sys.phi.size()) >= wanted) continue;
      if (std::abs(to_double(row, values)) > 1e-6 * std::max(1.0, trial.row(kept.rows()).norm()))
        throw std::logic_error("loop equation not satisfied at the assembled pose");
      kept = trial;
      sys.phi.push_back(row);
      used = true;
    }
    if (used) described.push_back(writer.describe(loop));
  }
}

void differentiate(SymbolicSystem& sys) {
  const std::size_t n = sys.q.size();
  for (const ex& row : sys.phi) {
    std::vector<ex> grad;
    ex velocity = 0;
    for (std::size_t j = 0; j < n; ++j) {
      grad.push_back(row.diff(sys.q[j]));
      velocity += grad.back() * sys.qd[j];
    }
    ex gamma = 0;
    for (std::size_t j = 0; j < n; ++j) gamma -= velocity.diff(sys.q[j]) * sys.qd[j];
    sys.phi_q.push_back(grad);
    sys.gamma.push_back(gamma.expand());
  }
}

}  // namespace

CoordinateState coordinate_state(const kin::Model& model, const EquationsInput& input, const Eigen::VectorXd& q,
                                 const Eigen::VectorXd& qd, const Eigen::VectorXd& qdd) {
  const Eigen::Index n = static_cast<Eigen::Index>(input.coordinates.size());
  CoordinateState s{Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n)};
  auto rate = [](const Eigen::VectorXd& v, int body) { return body == kin::kGround || v.size() == 0 ? 0.0 : v[3 * body + 2]; };
  auto point_rate = [&](const Eigen::VectorXd& v, const kin::BodyPoint& p, int order) -> Eigen::Vector2d {
    if (p.body == kin::kGround || v.size() == 0) return Eigen::Vector2d::Zero();
    const Eigen::Vector2d r = Eigen::Rotation2Dd(angle_of(q, p.body)) * p.local;
    const Eigen::Vector2d perp(-r.y(), r.x());
    const double w = rate(qd, p.body);
    const Eigen::Vector2d base(v[3 * p.body], v[3 * p.body + 1]);
    return order == 1 ? Eigen::Vector2d(base + w * perp) : Eigen::Vector2d(base + rate(qdd, p.body) * perp - w * w * r);
  };
  for (Eigen::Index k = 0; k < n; ++k) {
    const Coordinate& c = input.coordinates[static_cast<std::size_t>(k)];
    if (c.is_angle) {
      const Eigen::Vector2d d = c.angle.to.local - c.angle.from.local;
      const double psi = angle_of(q, c.angle.from.body) + std::atan2(d.y(), d.x());
      s.q[k] = wrap(c.angle.sense * (psi - c.angle.zero));
      s.qd[k] = c.angle.sense * rate(qd, c.angle.from.body);
      s.qdd[k] = c.angle.sense * rate(qdd, c.angle.from.body);
      continue;
    }
    const auto* p = dynamic_cast<const kin::Prismatic*>(model.constraints()[static_cast<std::size_t>(c.displacement.joint)].constraint.get());
    const int g = p->guide().body;
    const kin::BodyPoint origin{g, c.displacement.origin};
    const Eigen::Vector2d u = Eigen::Rotation2Dd(angle_of(q, g)) * p->axis_local();
    const Eigen::Vector2d du(-u.y(), u.x());  // d u / d theta_g
    const Eigen::Vector2d rel = world(q, p->slider()) - world(q, origin);
    const Eigen::Vector2d vrel = point_rate(qd, p->slider(), 1) - point_rate(qd, origin, 1);
    const Eigen::Vector2d arel = point_rate(qdd, p->slider(), 2) - point_rate(qdd, origin, 2);
    const double w = rate(qd, g), a = rate(qdd, g);
    const double sign = c.displacement.sign * kMm;
    s.q[k] = sign * u.dot(rel);
    s.qd[k] = sign * (u.dot(vrel) + w * du.dot(rel));
    s.qdd[k] = sign * (u.dot(arel) + 2 * w * du.dot(vrel) + (a * du - w * w * u).dot(rel));
  }
  return s;
}

namespace {

// The coordinates the model's drivers move (an angle relative to the ground, a slide).
std::vector<int> driven_coordinates(const kin::Model& model, const EquationsInput& input) {
  std::vector<int> found;
  for (const kin::Driver& d : model.drivers()) {
    const kin::Constraint* c = model.constraints()[static_cast<std::size_t>(d.constraint)].constraint.get();
    const std::vector<int> bodies = c->bodies();
    for (std::size_t k = 0; k < input.coordinates.size(); ++k) {
      const Coordinate& x = input.coordinates[k];
      bool match = false;
      if (x.is_angle && dynamic_cast<const kin::AngleDriver*>(c))
        match = bodies[0] == x.angle.from.body && bodies[1] == kin::kGround;
      if (!x.is_angle && dynamic_cast<const kin::DisplacementDriver*>(c)) {
        const auto* p = dynamic_cast<const kin::Prismatic*>(model.constraints()[static_cast<std::size_t>(x.displacement.joint)].constraint.get());
        match = p && bodies[0] == p->slider().body && bodies[1] == p->guide().body;
      }
      if (match) {
        found.push_back(static_cast<int>(k));
        break;
      }
    }
  }
  return found;
}

GiNaC::matrix columns(const SymbolicSystem& sys, const std::vector<int>& cols) {
  GiNaC::matrix m(static_cast<unsigned>(sys.phi.size()), static_cast<unsigned>(cols.size()));
  for (std::size_t i = 0; i < sys.phi.size(); ++i)
    for (std::size_t j = 0; j < cols.size(); ++j)
      m(static_cast<unsigned>(i), static_cast<unsigned>(j)) = sys.phi_q[i][static_cast<std::size_t>(cols[j])];
  return m;
}

std::vector<int> dependent_of(std::size_t n, const std::vector<int>& independent) {
  std::vector<int> d;
  for (std::size_t k = 0; k < n; ++k)
    if (std::find(independent.begin(), independent.end(), static_cast<int>(k)) == independent.end()) d.push_back(static_cast<int>(k));
  return d;
}

bool regular_at(const SymbolicSystem& sys, const std::vector<int>& independent, const CoordinateState& at) {
  const std::vector<int> dep = dependent_of(sys.q.size(), independent);
  Eigen::MatrixXd a(static_cast<Eigen::Index>(sys.phi.size()), static_cast<Eigen::Index>(dep.size()));
  const GiNaC::exmap values = sys.values(at);
  for (Eigen::Index i = 0; i < a.rows(); ++i)
    for (Eigen::Index j = 0; j < a.cols(); ++j)
      a(i, j) = to_double(sys.phi_q[static_cast<std::size_t>(i)][static_cast<std::size_t>(dep[static_cast<std::size_t>(j)])], values);
  Eigen::FullPivLU<Eigen::MatrixXd> lu(a);
  lu.setThreshold(1e-9);
  return a.rows() == a.cols() && lu.isInvertible();
}

std::vector<int> choose_independent(const kin::Model& model, const EquationsInput& input, const SymbolicSystem& sys,
                                    const CoordinateState& at) {
  const std::size_t free = sys.q.size() - sys.phi.size();
  if (!input.independent.empty()) return input.independent;
  std::vector<int> driven = driven_coordinates(model, input);
  if (driven.size() == free) return driven;
  if (free != 1) return {};
  for (std::size_t k = 0; k < sys.q.size(); ++k)
    if (regular_at(sys, {static_cast<int>(k)}, at)) return {static_cast<int>(k)};
  return {0};
}

// q_d' / q_i' = -(Phi_q^d)^-1 Phi_q^i by Cramer's rule, then shortened.
void velocity_ratios(SymbolicSystem& sys, const std::vector<int>& independent, Equations& out) {
  if (independent.size() != 1 || sys.phi.empty()) return;
  const std::vector<int> dep = dependent_of(sys.q.size(), independent);
  const GiNaC::matrix a = columns(sys, dep);
  const ex det = a.determinant();
  if (det.is_zero()) return;
  const GiNaC::matrix b = columns(sys, independent);
  for (std::size_t j = 0; j < dep.size(); ++j) {
    GiNaC::matrix aj = a;
    for (unsigned i = 0; i < aj.rows(); ++i) aj(i, static_cast<unsigned>(j)) = -b(i, 0);
    const detail::Fraction ratio = detail::simplify_ratio(aj.determinant() / det);
    sys.ratios.push_back(ratio.num / ratio.den);
    out.ratios.push_back({dep[j], independent[0], detail::print_fraction(ratio.num, ratio.den)});
  }
}

void print_all(const SymbolicSystem& sys, Equations& out) {
  for (std::size_t i = 0; i < sys.phi.size(); ++i) {
    out.phi.push_back(detail::print(sys.phi[i]));
    std::vector<Expression> row;
    ex velocity = 0;
    for (std::size_t j = 0; j < sys.q.size(); ++j) {
      row.push_back(detail::print(sys.phi_q[i][j]));
      velocity += sys.phi_q[i][j] * sys.qd[j];
    }
    out.phi_q.push_back(row);
    out.velocity.push_back(detail::print(velocity));
    out.gamma.push_back(detail::print(sys.gamma[i]));
  }
  for (std::size_t k = 0; k < sys.params.size(); ++k) out.symbol_values.emplace_back(sys.params[k].get_name(), sys.param_values[k]);
}

}  // namespace

Equations loop_equations(const kin::Model& model, const EquationsInput& input, const Eigen::VectorXd& pose, int dof) {
  validate(model, input);
  auto sys = std::make_shared<SymbolicSystem>();
  make_symbols(input, pose, *sys);
  Equations out;
  const detail::LoopWriter writer(model, input, pose, *sys);
  const auto loops = detail::simple_loops(writer.edges(), static_cast<int>(model.bodies().size()), kMaxLoops);
  const Eigen::VectorXd none;
  const CoordinateState at = coordinate_state(model, input, pose, none, none);
  select_rows(writer, loops, at, static_cast<int>(input.coordinates.size()) - dof, *sys, out.loops);
  differentiate(*sys);
  out.independent = choose_independent(model, input, *sys, at);
  velocity_ratios(*sys, out.independent, out);
  print_all(*sys, out);
  out.system = sys;
  return out;
}

Evaluated evaluate(const Equations& equations, const CoordinateState& state) {
  const SymbolicSystem& sys = *equations.system;
  const GiNaC::exmap values = sys.values(state);
  const Eigen::Index m = static_cast<Eigen::Index>(sys.phi.size()), n = static_cast<Eigen::Index>(sys.q.size());
  Evaluated e{Eigen::VectorXd(m), Eigen::VectorXd(m), Eigen::VectorXd::Constant(static_cast<Eigen::Index>(equations.ratios.size()), std::numeric_limits<double>::quiet_NaN()), Eigen::MatrixXd(m, n)};
  for (Eigen::Index i = 0; i < m; ++i) {
    e.phi[i] = to_double(sys.phi[static_cast<std::size_t>(i)], values);
    e.gamma[i] = to_double(sys.gamma[static_cast<std::size_t>(i)], values);
    for (Eigen::Index j = 0; j < n; ++j) e.phi_q(i, j) = to_double(sys.phi_q[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)], values);
  }
  if (equations.ratios.empty()) return e;
  const std::vector<int> dep = dependent_of(sys.q.size(), equations.independent);
  Eigen::MatrixXd a(m, static_cast<Eigen::Index>(dep.size()));
  for (std::size_t j = 0; j < dep.size(); ++j) a.col(static_cast<Eigen::Index>(j)) = e.phi_q.col(dep[j]);
  Eigen::FullPivLU<Eigen::MatrixXd> lu(a);
  lu.setThreshold(1e-9);
  if (!lu.isInvertible()) return e;
  const Eigen::VectorXd x = lu.solve(-e.phi_q.col(equations.independent[0]));
  for (std::size_t r = 0; r < equations.ratios.size(); ++r) e.ratios[static_cast<Eigen::Index>(r)] = x[static_cast<Eigen::Index>(r)];
  return e;
}

}  // namespace gearkit::sym
