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

}  // namespace

Eigen::VectorXd applied_forces(const Model& model, const Data& data) {
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

  // Reactions and the joint count per body (for two-force members).
  std::map<int, std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>> revolute_ends;  // body -> (point, force on it)
  std::map<int, int> other_constraints;
  for (std::size_t k = 0; k < model.constraints().size(); ++k) {
    const ModelConstraint& mc = model.constraints()[k];
    if (mc.constraint->is_driver()) {
      for (int b : mc.constraint->bodies()) other_constraints[b] += 1;
      continue;
    }
    ConstraintReaction r;
    r.constraint = static_cast<int>(k);
    r.name = mc.name;
    r.kind = mc.constraint->kind();
    r.lambda = f.lambda.segment(mc.first_row, mc.constraint->equations());
    const std::vector<int> bodies = mc.constraint->bodies();
    r.body = bodies.empty() ? kGround : bodies[0];
    if (auto rev = dynamic_cast<const Revolute*>(mc.constraint.get())) {
      r.force = -r.lambda.head<2>();
      const Eigen::Vector2d at = point_position(data, rev->a());
      revolute_ends[rev->a().body].push_back({at, r.force});
      revolute_ends[rev->b().body].push_back({at, -r.force});
    } else {
      for (int b : bodies) other_constraints[b] += 1;
      if (auto pri = dynamic_cast<const Prismatic*>(mc.constraint.get())) {
        const int guide = pri->guide().body;
        const double theta_g = guide == kGround ? 0.0 : data.q(3 * guide + 2);
        const Eigen::Vector2d n = rotate(theta_g, perp(pri->axis_local()));
        r.force = -r.lambda(1) * n;
        r.moment = -r.lambda(0);
      }
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
  for (const auto& [body, ends] : revolute_ends) {
    if (body == kGround || ends.size() != 2 || loaded[body] || other_constraints[body] != 0) continue;
    const Eigen::Vector2d axis = ends[0].first - ends[1].first;
    if (axis.norm() == 0.0) continue;
    // Force on the member at end A, projected on (A - B): positive pulls the ends apart.
    f.two_force_members.push_back({body, model.body_name(body), ends[0].second.dot(axis.normalized())});
  }
  return f;
}

}  // namespace gearkit::kin
