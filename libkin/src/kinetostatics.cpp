#include <gearkit/kin/kinetostatics.hpp>

#include <array>
#include <span>

#include <gearkit/kin/solve.hpp>

#include <Eigen/LU>
#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>

namespace gearkit::kin {

namespace {

// Adds a force F [N] applied at body point p to the generalised forces.
void add_point_force(Eigen::VectorXd& Q, const Data& data, const BodyPoint& p, const Eigen::Vector2d& F) {
  if (p.body == kGround) return;
  const int k = 3 * p.body;
  Q.segment<2>(k) += F;
  Q(k + 2) += cross(rotate(data.q(k + 2), p.local), F);
}

double spring_tension(const Spring& s, double length) { return s.stiffness * (length - s.free_length) + s.preload; }

// Constraint k's reaction at the state in `data` for the multipliers `lambda`, into `r` (its
// storage reused: a sweep computes the reactions of every position).
void reaction_of(const Model& model, const Data& data, int k, const Eigen::VectorXd& lambda, ConstraintReaction& r) {
  const ModelConstraint& mc = model.constraints()[static_cast<std::size_t>(k)];
  const std::vector<int>& bodies = mc.bodies;
  std::array<BodyState, 4> few;  // joints and most elements join two bodies: no allocation
  std::vector<BodyState> many(bodies.size() > few.size() ? bodies.size() : 0);
  const std::span<BodyState> states = many.empty() ? std::span<BodyState>(few.data(), bodies.size()) : std::span<BodyState>(many);
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    states[i] = BodyState{};
    if (bodies[i] == kGround) continue;
    const int c = 3 * bodies[i];
    states[i].r = data.q.segment<2>(c);
    states[i].set_theta(data.q(c + 2));
    states[i].r_dot = data.qd.segment<2>(c);
    states[i].omega = data.qd(c + 2);
  }
  r.constraint = k;
  r.name = mc.name;
  r.kind = mc.constraint->kind();
  r.body = bodies.empty() ? kGround : bodies[0];
  r.lambda = lambda.segment(mc.first_row, mc.constraint->equations());
  const ConstraintInput in{states, data.t, 0.0};
  Reaction reaction = mc.constraint->reaction(in, std::span<const double>(r.lambda.data(), static_cast<std::size_t>(r.lambda.size())));
  r.force = reaction.force;
  r.moment = reaction.moment;
  r.at = reaction.at;
  r.pin = reaction.pin;
  r.values = std::move(reaction.values);
}

}  // namespace

Eigen::VectorXd applied_forces(const Model& model, const Data& data) {
  check_data(model, data);
  Eigen::VectorXd Q = Eigen::VectorXd::Zero(model.coordinates());
  for (std::size_t i = 0; i < model.bodies().size(); ++i) {
    const Body& b = model.bodies()[i];
    const int body = static_cast<int>(i);
    const BodyPoint com{body, b.centre_of_mass};
    // Gravity and d'Alembert's inertia force -m a_G at the centre of mass, -I_G alpha as a couple.
    const Eigen::Vector2d a_g = point_acceleration(data, com);
    add_point_force(Q, data, com, b.mass * model.gravity() - b.mass * a_g);
    Q(3 * body + 2) -= b.inertia * data.qdd(3 * body + 2);
  }
  for (const PointForce& f : model.forces())
    if (!f.unknown) add_point_force(Q, data, f.at, f.force);
  for (const BodyTorque& t : model.torques())
    if (t.body != kGround && !t.unknown) Q(3 * t.body + 2) += t.torque;
  for (const Spring& s : model.springs()) {
    const Eigen::Vector2d pa = point_position(data, s.a), pb = point_position(data, s.b);
    const double length = (pb - pa).norm();
    if (length == 0.0) continue;
    const Eigen::Vector2d e = (pb - pa) / length;
    const double tension = spring_tension(s, length);
    add_point_force(Q, data, s.a, tension * e);
    add_point_force(Q, data, s.b, -tension * e);
  }
  return Q;
}

double potential_energy(const Model& model, const Data& data) {
  check_data(model, data);
  double v = 0.0;
  for (std::size_t i = 0; i < model.bodies().size(); ++i) {
    const Body& b = model.bodies()[i];
    v -= b.mass * model.gravity().dot(point_position(data, {static_cast<int>(i), b.centre_of_mass}));
  }
  for (const Spring& s : model.springs()) {
    const double stretch = (point_position(data, s.b) - point_position(data, s.a)).norm() - s.free_length;
    v += 0.5 * s.stiffness * stretch * stretch + s.preload * stretch;
  }
  return v;
}

double kinetic_energy(const Model& model, const Data& data) {
  check_data(model, data);
  double t = 0.0;
  for (std::size_t i = 0; i < model.bodies().size(); ++i) {
    const Body& b = model.bodies()[i];
    const Eigen::Vector2d v = point_velocity(data, {static_cast<int>(i), b.centre_of_mass});
    const double w = data.qd(3 * static_cast<int>(i) + 2);
    t += 0.5 * b.mass * v.squaredNorm() + 0.5 * b.inertia * w * w;
  }
  return t;
}

namespace {

// The generalised force of a unit unknown load.
Eigen::VectorXd unit_load(const Model& model, const Data& data, const UnknownLoad& u) {
  Eigen::VectorXd Q = Eigen::VectorXd::Zero(model.coordinates());
  if (u.torque) {
    const BodyTorque& t = model.torques()[static_cast<std::size_t>(u.index)];
    if (t.body != kGround) Q(3 * t.body + 2) = 1.0;
  } else {
    const PointForce& f = model.forces()[static_cast<std::size_t>(u.index)];
    add_point_force(Q, data, f.at, f.force.normalized());
  }
  return Q;
}

// Multipliers without friction for the forces Q*.
Eigen::VectorXd frictionless_multipliers(const Model& model, Data& data, const Eigen::VectorXd& applied) {
  if (model.equations() == model.coordinates()) return solve_with_jacobian_transpose(data, applied);
  // Redundant constraints: the reactions are statically indeterminate; the minimum-norm
  // multipliers that balance the forces.
  const Eigen::MatrixXd jt = data.jacobian().transpose();
  return Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(jt).solve(applied);
}

// The efforts of the drivers that have a given one, for the applied forces Q* (forward sense,
// with friction when the model has it; NaN when that sense is self-locking).
Eigen::VectorXd given_driver_efforts(const Model& model, Data& data, int driver, const Eigen::VectorXd& applied,
                                     const std::vector<int>& given) {
  Eigen::VectorXd e(static_cast<int>(given.size()));
  if (model.frictions().empty()) {
    for (std::size_t i = 0; i < given.size(); ++i) e(static_cast<int>(i)) = -applied.dot(input_sensitivity(model, data, given[i]));
    return e;
  }
  Eigen::VectorXd lambda, qf;
  const FrictionAnalysis fa = analyse_friction(model, data, driver, applied, frictionless_multipliers(model, data, applied), lambda, qf);
  for (std::size_t i = 0; i < given.size(); ++i)
    e(static_cast<int>(i)) = fa.forward.effort[static_cast<std::size_t>(given[i])];
  return e;
}

// Inverse kinetostatics: the magnitudes of the unknown loads for the drivers' given efforts;
// adds them to f.applied and fills f.unknown_loads.
void solve_unknown_loads(const Model& model, Data& data, int driver, ForceAnalysis& f) {
  std::vector<int> given;
  for (std::size_t k = 0; k < model.drivers().size(); ++k)
    if (model.drivers()[k].effort) given.push_back(static_cast<int>(k));
  std::vector<UnknownLoad> unknown;
  for (std::size_t i = 0; i < model.forces().size(); ++i)
    if (model.forces()[i].unknown) unknown.push_back({model.forces()[i].name, false, static_cast<int>(i), 0.0, Eigen::Vector2d::Zero()});
  for (std::size_t i = 0; i < model.torques().size(); ++i)
    if (model.torques()[i].unknown) unknown.push_back({model.torques()[i].name, true, static_cast<int>(i), 0.0, Eigen::Vector2d::Zero()});
  if (unknown.empty() && given.empty()) return;
  if (unknown.size() != given.size())
    throw std::invalid_argument(fmt::format("{} unknown load(s) need as many drivers with a given effort, found {}",
                                            unknown.size(), given.size()));
  const int u = static_cast<int>(unknown.size());
  Eigen::MatrixXd U(model.coordinates(), u);
  Eigen::VectorXd target(u);
  for (int i = 0; i < u; ++i) {
    U.col(i) = unit_load(model, data, unknown[static_cast<std::size_t>(i)]);
    target(i) = *model.drivers()[static_cast<std::size_t>(given[static_cast<std::size_t>(i)])].effort;
  }
  // E(F) = E(0) + D F exactly without friction (virtual power is linear in the loads); with
  // friction E is piecewise linear and Newton's method on the same D, refreshed by finite
  // differences, converges in a few steps.
  const auto efforts = [&](const Eigen::VectorXd& F) { return given_driver_efforts(model, data, driver, f.applied + U * F, given); };
  Eigen::MatrixXd D(u, u);
  for (int i = 0; i < u; ++i)
    for (int k = 0; k < u; ++k) D(k, i) = -U.col(i).dot(input_sensitivity(model, data, given[static_cast<std::size_t>(k)]));
  Eigen::FullPivLU<Eigen::MatrixXd> lu(D);
  Eigen::VectorXd F = Eigen::VectorXd::Constant(u, std::numeric_limits<double>::quiet_NaN());
  if (lu.isInvertible()) F = lu.solve(target - efforts(Eigen::VectorXd::Zero(u)));
  else f.warnings.push_back("the given driving effort cannot determine the unknown load: the load does no work in this motion");
  for (int it = 0; F.allFinite() && !model.frictions().empty() && it < 40; ++it) {
    const Eigen::VectorXd r = efforts(F) - target;
    if (!r.allFinite()) {
      f.warnings.push_back("the unknown load cannot be found: the mechanism locks by friction at the load it would need");
      F.setConstant(std::numeric_limits<double>::quiet_NaN());
      break;
    }
    if (r.lpNorm<Eigen::Infinity>() <= 1e-12 * std::max(1.0, target.lpNorm<Eigen::Infinity>())) break;
    for (int i = 0; i < u; ++i) {
      const double h = 1e-7 * std::max(1.0, std::abs(F(i)));
      Eigen::VectorXd Fh = F;
      Fh(i) += h;
      D.col(i) = (efforts(Fh) - target - r) / h;
    }
    F -= D.fullPivLu().solve(r);
  }
  if (F.allFinite()) f.applied += U * F;
  for (int i = 0; i < u; ++i) {
    UnknownLoad& x = unknown[static_cast<std::size_t>(i)];
    x.value = F(i);
    if (!x.torque) x.force = F(i) * model.forces()[static_cast<std::size_t>(x.index)].force.normalized();
  }
  f.unknown_loads = std::move(unknown);
}

// Adds each joint's friction to its reaction (force along the axis at the joint point, or the
// friction couple of a revolute) and names N and the friction force.
void add_friction_to_reactions(const FrictionAnalysis& fa, const Model& model, const Data& data, ForceAnalysis& f) {
  for (const JointFrictionForce& jf : fa.joints)
    for (ConstraintReaction& r : f.reactions) {
      if (r.constraint != jf.constraint) continue;
      const Constraint* c = model.constraints()[static_cast<std::size_t>(jf.constraint)].constraint.get();
      const auto axis = [&](const BodyPoint& on, const Eigen::Vector2d& local) {
        return on.body == kGround ? local : rotate(data.q(3 * on.body + 2), local);
      };
      if (jf.kind == "revolute") r.moment += jf.friction;
      if (const auto* p = dynamic_cast<const Prismatic*>(c)) r.force += jf.friction * axis(p->guide(), p->axis_local());
      if (const auto* s = dynamic_cast<const PinInSlot*>(c)) r.force += jf.friction * axis(s->slot(), s->axis_local());
      if (const auto* k = dynamic_cast<const Contact*>(c)) r.force += jf.friction * axis(k->line(), k->axis_local());
      const bool couple = jf.kind == "revolute";
      r.values.push_back({couple ? "F" : "N", "N", jf.normal, couple ? "pin force magnitude" : "normal force"});
      r.values.push_back({couple ? "M_f" : "F_f", couple ? "N m" : "N", jf.friction,
                          couple ? "friction couple (friction circle), ccw on the first link" : "friction force along the axis on the first link"});
      r.pin = r.pin && jf.friction == 0.0;
    }
}

// Massless, unloaded links with exactly two pins and nothing else: two-force members.
std::vector<TwoForceMember> two_force_members(const Model& model, const ForceAnalysis& f, const std::set<int>& with_friction) {
  std::map<int, std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>> pin_ends;  // body -> (point, force on it)
  std::map<int, int> other_constraints;
  for (std::size_t k = 0; k < model.constraints().size(); ++k) {
    const ModelConstraint& mc = model.constraints()[k];
    if (mc.constraint->is_driver()) {
      for (int b : mc.bodies) other_constraints[b] += 1;
    }
  }
  for (const ConstraintReaction& r : f.reactions) {
    const std::vector<int>& bodies = model.constraints()[static_cast<std::size_t>(r.constraint)].bodies;
    if (r.pin && r.at && bodies.size() == 2 && !with_friction.count(r.constraint)) {
      pin_ends[bodies[0]].push_back({*r.at, r.force});
      pin_ends[bodies[1]].push_back({*r.at, -r.force});
    } else {
      for (int b : bodies) other_constraints[b] += 1;
    }
  }
  // Loads per body (index body + 1: the ground is -1), to know which bodies are unloaded.
  std::vector<char> loaded(model.bodies().size() + 1, 0);
  const auto load = [&](int body) { loaded[static_cast<std::size_t>(body + 1)] = 1; };
  for (std::size_t i = 0; i < model.bodies().size(); ++i)
    if (model.bodies()[i].mass > 0.0 || model.bodies()[i].inertia > 0.0) load(static_cast<int>(i));
  for (const PointForce& pf : model.forces()) load(pf.at.body);
  for (const BodyTorque& t : model.torques()) load(t.body);
  for (const Spring& s : model.springs()) load(s.a.body), load(s.b.body);
  std::vector<TwoForceMember> members;
  for (const auto& [body, ends] : pin_ends) {
    if (body == kGround || ends.size() != 2 || loaded[static_cast<std::size_t>(body + 1)] || other_constraints[body] != 0) continue;
    const Eigen::Vector2d axis = ends[0].first - ends[1].first;
    if (axis.norm() == 0.0) continue;
    // Force on the member at end A, projected on (A - B): positive pulls the ends apart.
    members.push_back({body, model.body_name(body), ends[0].second.dot(axis.normalized())});
  }
  return members;
}

// Efforts by virtual power and by the multipliers, with the friction forces Q_f.
void driver_efforts(const Model& model, Data& data, const Eigen::VectorXd& friction_forces, bool locked, ForceAnalysis& f) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = 0; k < model.drivers().size(); ++k) {
    const Driver& d = model.drivers()[k];
    const Eigen::VectorXd dq = input_sensitivity(model, data, static_cast<int>(k));
    f.effort_lagrange.push_back(locked ? nan : -f.lambda(model.constraints()[static_cast<std::size_t>(d.constraint)].first_row));
    f.effort_virtual_power.push_back(locked ? nan : -(f.applied + friction_forces).dot(dq));
  }
}

}  // namespace

ForceAnalysis solve_forces(const Model& model, Data& data, int driver) {
  ForceAnalysis f;
  solve_forces(model, data, driver, f);
  return f;
}

void solve_forces(const Model& model, Data& data, int driver, ForceAnalysis& f) {
  check_data(model, data);
  if (!data.factored) factorize(model, data);
  if (data.singular)
    throw std::runtime_error("kinetostatics at a singular configuration (dead point): the driving effort is unbounded");
  f.effort_lagrange.clear();
  f.effort_virtual_power.clear();
  f.two_force_members.clear();
  f.unknown_loads.clear();
  f.friction.reset();
  f.warnings.clear();
  f.applied = applied_forces(model, data);
  const bool square = model.equations() == model.coordinates();
  f.determinate = square;
  if (!model.drivers().empty()) solve_unknown_loads(model, data, driver, f);
  const Eigen::VectorXd lambda0 = frictionless_multipliers(model, data, f.applied);
  Eigen::VectorXd friction_forces = Eigen::VectorXd::Zero(model.coordinates());
  f.lambda = lambda0;
  std::set<int> with_friction;
  for (const JointFriction& jf : model.frictions()) with_friction.insert(jf.constraint);
  bool locked = false;
  if (!model.frictions().empty() && !model.drivers().empty()) {
    if (!square) {
      f.warnings.push_back("redundant constraints: the reactions are indeterminate, friction is not computed");
    } else {
      f.friction = analyse_friction(model, data, driver, f.applied, lambda0, f.lambda, friction_forces);
      locked = f.friction->forward.wedged;
      f.warnings.insert(f.warnings.end(), f.friction->warnings.begin(), f.friction->warnings.end());
      if (locked)
        f.warnings.push_back(fmt::format("wedged (self-locking): no finite driving effort moves the mechanism in the analysed "
                                         "sense (it wedges from {:.6g} times the friction coefficients); the reactions shown "
                                         "are without friction", f.friction->forward.wedging_factor));
    }
  }
  data.lambda = f.lambda;
  driver_efforts(model, data, friction_forces, locked, f);
  std::size_t used = 0;
  for (std::size_t k = 0; k < model.constraints().size(); ++k) {
    if (model.constraints()[k].constraint->is_driver()) continue;
    if (used == f.reactions.size()) f.reactions.emplace_back();
    reaction_of(model, data, static_cast<int>(k), f.lambda, f.reactions[used++]);
  }
  f.reactions.resize(used);
  if (f.friction && !locked) add_friction_to_reactions(*f.friction, model, data, f);
  f.two_force_members = two_force_members(model, f, with_friction);
}

namespace {

// The generalised force -Phi_q^T lambda of constraint k on each of its bodies, about each body's
// frame origin: (Fx, Fy, M).
std::vector<Eigen::Vector3d> constraint_forces(const Model& model, const Data& data, int k, const Eigen::VectorXd& lambda) {
  const ModelConstraint& mc = model.constraints()[static_cast<std::size_t>(k)];
  const std::vector<int>& bodies = mc.bodies;
  std::vector<BodyState> states(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i] != kGround) {
      states[i].r = data.q.segment<2>(3 * bodies[i]);
      states[i].set_theta(data.q(3 * bodies[i] + 2));
      states[i].r_dot = data.qd.segment<2>(3 * bodies[i]);
      states[i].omega = data.qd(3 * bodies[i] + 2);
    }
  const int m = mc.constraint->equations(), columns = 3 * static_cast<int>(bodies.size());
  Eigen::VectorXd phi(m), phi_t(m), gamma(m);
  Eigen::MatrixXd phi_q(m, columns);
  ConstraintOutput out{phi, phi_q, phi_t, gamma};
  mc.constraint->evaluate(ConstraintInput{states, data.t, 0.0}, out);
  const Eigen::VectorXd generalised = -phi_q.transpose() * lambda.segment(mc.first_row, m);
  std::vector<Eigen::Vector3d> per_body;
  for (std::size_t i = 0; i < bodies.size(); ++i) per_body.push_back(generalised.segment<3>(3 * static_cast<int>(i)));
  return per_body;
}

Eigen::Vector2d origin_of(const Data& data, int body) { return data.q.segment<2>(3 * body); }

// The forces of every constraint on the free bodies: the joint's reaction at its point (its
// opposite on the second body), or the generalised force about the frame origin.
void add_constraint_forces(const Model& model, const Data& data, const ForceAnalysis& f, std::vector<FreeBody>& fb) {
  std::map<int, const JointFrictionForce*> friction;
  if (f.friction)
    for (const JointFrictionForce& j : f.friction->joints) friction[j.constraint] = &j;
  std::map<int, const ConstraintReaction*> reactions;
  for (const ConstraintReaction& r : f.reactions) reactions[r.constraint] = &r;
  for (std::size_t k = 0; k < model.constraints().size(); ++k) {
    const ModelConstraint& mc = model.constraints()[k];
    const std::vector<int>& bodies = mc.bodies;
    const auto r = reactions.find(static_cast<int>(k));
    const std::string kind = mc.constraint->is_driver() ? "driver" : mc.constraint->kind();
    if (r != reactions.end() && r->second->at && bodies.size() == 2) {
      const auto fr = friction.find(static_cast<int>(k));
      for (int side = 0; side < 2; ++side) {
        if (bodies[static_cast<std::size_t>(side)] == kGround) continue;
        const double s = side == 0 ? 1.0 : -1.0;
        BodyForce bf{mc.name, kind, *r->second->at, s * r->second->force, s * r->second->moment};
        if (fr != friction.end()) {
          bf.normal = fr->second->normal;
          bf.friction = s * fr->second->friction;
        }
        fb[static_cast<std::size_t>(bodies[static_cast<std::size_t>(side)])].forces.push_back(bf);
      }
      continue;
    }
    const std::vector<Eigen::Vector3d> g = constraint_forces(model, data, static_cast<int>(k), f.lambda);
    for (std::size_t i = 0; i < bodies.size(); ++i)
      if (bodies[i] != kGround)
        fb[static_cast<std::size_t>(bodies[i])].forces.push_back({mc.name, kind, origin_of(data, bodies[i]), g[i].head<2>(), g[i](2)});
  }
}

// Weights, inertia forces and the loads (with the solved magnitudes of unknown ones).
void add_load_forces(const Model& model, const Data& data, const ForceAnalysis& f, std::vector<FreeBody>& fb) {
  for (std::size_t i = 0; i < model.bodies().size(); ++i) {
    const Body& b = model.bodies()[i];
    const BodyPoint com{static_cast<int>(i), b.centre_of_mass};
    const Eigen::Vector2d at = point_position(data, com);
    if (b.mass > 0.0 && model.gravity().squaredNorm() > 0.0) fb[i].forces.push_back({"weight", "weight", at, b.mass * model.gravity(), 0.0});
    const Eigen::Vector2d inertia = -b.mass * point_acceleration(data, com);
    const double couple = -b.inertia * data.qdd(3 * static_cast<int>(i) + 2);
    if (inertia.squaredNorm() > 0.0 || couple != 0.0) fb[i].forces.push_back({"inertia", "inertia", at, inertia, couple});
  }
  std::map<std::pair<bool, int>, double> solved;
  for (const UnknownLoad& u : f.unknown_loads) solved[{u.torque, u.index}] = u.value;
  for (std::size_t i = 0; i < model.forces().size(); ++i) {
    const PointForce& pf = model.forces()[i];
    if (pf.at.body == kGround) continue;
    const auto u = solved.find({false, static_cast<int>(i)});
    const Eigen::Vector2d force = pf.unknown ? (u == solved.end() ? 0.0 : u->second) * pf.force.normalized() : pf.force;
    fb[static_cast<std::size_t>(pf.at.body)].forces.push_back({pf.name, "force", point_position(data, pf.at), force, 0.0});
  }
  for (std::size_t i = 0; i < model.torques().size(); ++i) {
    const BodyTorque& t = model.torques()[i];
    if (t.body == kGround) continue;
    const auto u = solved.find({true, static_cast<int>(i)});
    const double torque = t.unknown ? (u == solved.end() ? 0.0 : u->second) : t.torque;
    fb[static_cast<std::size_t>(t.body)].forces.push_back({t.name, "torque", origin_of(data, t.body), Eigen::Vector2d::Zero(), torque});
  }
  for (const Spring& s : model.springs()) {
    const Eigen::Vector2d pa = point_position(data, s.a), pb = point_position(data, s.b);
    const double length = (pb - pa).norm();
    if (length == 0.0) continue;
    const Eigen::Vector2d e = (pb - pa) / length;
    const double tension = spring_tension(s, length);
    if (s.a.body != kGround) fb[static_cast<std::size_t>(s.a.body)].forces.push_back({s.name, "spring", pa, tension * e, 0.0});
    if (s.b.body != kGround) fb[static_cast<std::size_t>(s.b.body)].forces.push_back({s.name, "spring", pb, -tension * e, 0.0});
  }
}

}  // namespace

std::vector<FreeBody> free_bodies(const Model& model, const Data& data, const ForceAnalysis& forces) {
  check_data(model, data);
  std::vector<FreeBody> fb(model.bodies().size());
  for (std::size_t i = 0; i < fb.size(); ++i) {
    fb[i].body = static_cast<int>(i);
    fb[i].name = model.bodies()[i].name;
  }
  add_constraint_forces(model, data, forces, fb);
  add_load_forces(model, data, forces, fb);
  return fb;
}

}  // namespace gearkit::kin
