#include <gearkit/kin/kinetostatics.hpp>

#include <gearkit/kin/solve.hpp>

#include <map>
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

// Constraint k's reaction at the state in `data` for the multipliers `lambda`.
ConstraintReaction reaction_of(const Model& model, const Data& data, int k, const Eigen::VectorXd& lambda) {
  const ModelConstraint& mc = model.constraints()[static_cast<std::size_t>(k)];
  const std::vector<int> bodies = mc.constraint->bodies();
  std::vector<BodyState> states(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i] == kGround) continue;
    const int c = 3 * bodies[i];
    states[i].r = data.q.segment<2>(c);
    states[i].set_theta(data.q(c + 2));
    states[i].r_dot = data.qd.segment<2>(c);
    states[i].omega = data.qd(c + 2);
  }
  ConstraintReaction r;
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
  return r;
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
  for (const PointForce& f : model.forces()) add_point_force(Q, data, f.at, f.force);
  for (const BodyTorque& t : model.torques())
    if (t.body != kGround) Q(3 * t.body + 2) += t.torque;
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

ForceAnalysis solve_forces(const Model& model, Data& data) {
  check_data(model, data);
  if (!data.factored) factorize(model, data);
  if (data.singular)
    throw std::runtime_error("kinetostatics at a singular configuration (dead point): the driving effort is unbounded");
  ForceAnalysis f;
  f.applied = applied_forces(model, data);
  const bool square = model.equations() == model.coordinates();
  f.determinate = square;
  if (square) {
    f.lambda = solve_with_jacobian_transpose(data, f.applied);
  } else {
    // Redundant constraints: the reactions are statically indeterminate; report the
    // minimum-norm multipliers that balance the forces.
    const Eigen::MatrixXd jt = data.jacobian().transpose();
    f.lambda = Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(jt).solve(f.applied);
  }
  data.lambda = f.lambda;

  for (std::size_t k = 0; k < model.drivers().size(); ++k) {
    const Driver& d = model.drivers()[k];
    f.effort_lagrange.push_back(-f.lambda(model.constraints()[static_cast<std::size_t>(d.constraint)].first_row));
    const Eigen::VectorXd dq = input_sensitivity(model, data, static_cast<int>(k));
    f.effort_virtual_power.push_back(-f.applied.dot(dq));
  }

  // Reactions, and the pins and other constraints on each body (for two-force members).
  std::map<int, std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>> pin_ends;  // body -> (point, force on it)
  std::map<int, int> other_constraints;
  for (std::size_t k = 0; k < model.constraints().size(); ++k) {
    const ModelConstraint& mc = model.constraints()[k];
    const std::vector<int> bodies = mc.constraint->bodies();
    if (mc.constraint->is_driver()) {
      for (int b : bodies) other_constraints[b] += 1;
      continue;
    }
    ConstraintReaction r = reaction_of(model, data, static_cast<int>(k), f.lambda);
    if (r.pin && r.at && bodies.size() == 2) {
      pin_ends[bodies[0]].push_back({*r.at, r.force});
      pin_ends[bodies[1]].push_back({*r.at, -r.force});
    } else {
      for (int b : bodies) other_constraints[b] += 1;
    }
    f.reactions.push_back(std::move(r));
  }

  // Loads per body, to know which bodies are unloaded.
  std::map<int, bool> loaded;
  for (std::size_t i = 0; i < model.bodies().size(); ++i)
    loaded[static_cast<int>(i)] = model.bodies()[i].mass > 0.0 || model.bodies()[i].inertia > 0.0;
  for (const PointForce& pf : model.forces()) loaded[pf.at.body] = true;
  for (const BodyTorque& t : model.torques()) loaded[t.body] = true;
  for (const Spring& s : model.springs()) loaded[s.a.body] = loaded[s.b.body] = true;
  for (const auto& [body, ends] : pin_ends) {
    if (body == kGround || ends.size() != 2 || loaded[body] || other_constraints[body] != 0) continue;
    const Eigen::Vector2d axis = ends[0].first - ends[1].first;
    if (axis.norm() == 0.0) continue;
    // Force on the member at end A, projected on (A - B): positive pulls the ends apart.
    f.two_force_members.push_back({body, model.body_name(body), ends[0].second.dot(axis.normalized())});
  }
  return f;
}

}  // namespace gearkit::kin
