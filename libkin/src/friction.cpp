#include <gearkit/kin/friction.hpp>

#include <gearkit/kin/solve.hpp>

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace gearkit::kin {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// How a joint's friction magnitude follows from its multipliers.
enum class Law { circle, face, bearing };  // revolute couple, mu |N|, prismatic mu max(|N|, 2|M|/b)

struct Joint {
  int constraint = 0, first_row = 0, rows = 0, slot = 0;
  Law law = Law::face;
  double mu = 0.0, rho = 0.0, length = 0.0;
  int row_of_normal = 0;          // face and bearing: the multiplier of the normal force
  Eigen::VectorXd direction;      // generalised force of a unit friction against the forward motion
  double sliding = 0.0;           // forward relative velocity (along the axis, or rad/s)
  double actual = 0.0;            // the same at data.qd
  Eigen::VectorXd h;              // S Phi_q^-T direction
};

BodyState state_of(const Eigen::VectorXd& q, int body) {
  BodyState s;
  if (body == kGround) return s;
  s.r = q.segment<2>(3 * body);
  s.set_theta(q(3 * body + 2));
  return s;
}

// Velocity in the motion `w` of body `body`'s material point now at global `p`.
Eigen::Vector2d velocity_at(const Eigen::VectorXd& q, const Eigen::VectorXd& w, int body, const Eigen::Vector2d& p) {
  if (body == kGround) return Eigen::Vector2d::Zero();
  return w.segment<2>(3 * body) + w(3 * body + 2) * perp(p - q.segment<2>(3 * body));
}

double angular_rate(const Eigen::VectorXd& w, int body) { return body == kGround ? 0.0 : w(3 * body + 2); }

// Adds the generalised force of `force` applied at global point `p` of `body`.
void add_force(Eigen::VectorXd& Q, const Eigen::VectorXd& q, int body, const Eigen::Vector2d& p, const Eigen::Vector2d& force) {
  if (body == kGround) return;
  Q.segment<2>(3 * body) += force;
  Q(3 * body + 2) += cross(p - q.segment<2>(3 * body), force);
}

double sign_of(double v, double scale) { return std::abs(v) <= 1e-12 * scale ? 0.0 : (v > 0 ? 1.0 : -1.0); }

// A friction force along the unit `u` at `p` between `first` and `second`, against the relative
// velocity of the first: its direction vector, forward sliding and actual sliding.
void sliding_joint(const Data& data, const Eigen::VectorXd& w, double scale, int first, int second,
                   const Eigen::Vector2d& p, const Eigen::Vector2d& u, Joint& j) {
  j.sliding = u.dot(velocity_at(data.q, w, first, p) - velocity_at(data.q, w, second, p));
  j.actual = u.dot(velocity_at(data.q, data.qd, first, p) - velocity_at(data.q, data.qd, second, p));
  const double s = sign_of(j.sliding, scale);
  add_force(j.direction, data.q, first, p, -s * u);
  add_force(j.direction, data.q, second, p, s * u);
}

// The joint's law, rows and direction of friction for the motion w.
Joint make_joint(const Model& model, const Data& data, const JointFriction& f, const Eigen::VectorXd& w, double scale) {
  const ModelConstraint& mc = model.constraints()[static_cast<std::size_t>(f.constraint)];
  Joint j;
  j.constraint = f.constraint;
  j.first_row = mc.first_row;
  j.rows = mc.constraint->equations();
  j.mu = f.mu;
  j.length = f.length;
  j.direction = Eigen::VectorXd::Zero(model.coordinates());
  const Constraint* c = mc.constraint.get();
  if (const auto* r = dynamic_cast<const Revolute*>(c)) {
    j.law = Law::circle;
    j.rho = f.radius * f.mu / std::sqrt(1.0 + f.mu * f.mu);  // r sin(atan mu)
    j.sliding = angular_rate(w, r->a().body) - angular_rate(w, r->b().body);
    j.actual = angular_rate(data.qd, r->a().body) - angular_rate(data.qd, r->b().body);
    const double s = sign_of(j.sliding, scale);
    if (r->a().body != kGround) j.direction(3 * r->a().body + 2) -= s;
    if (r->b().body != kGround) j.direction(3 * r->b().body + 2) += s;
  } else if (const auto* p = dynamic_cast<const Prismatic*>(c)) {
    j.law = f.length > 0.0 ? Law::bearing : Law::face;
    j.row_of_normal = 1;
    const BodyState g = state_of(data.q, p->guide().body);
    const Eigen::Vector2d at = Model::point_position(data.q, p->slider());
    sliding_joint(data, w, scale, p->slider().body, p->guide().body, at, g.rotated(p->axis_local()), j);
  } else if (const auto* s = dynamic_cast<const PinInSlot*>(c)) {
    const BodyState g = state_of(data.q, s->slot().body);
    sliding_joint(data, w, scale, s->pin().body, s->slot().body, Model::point_position(data.q, s->pin()),
                  g.rotated(s->axis_local()), j);
  } else if (const auto* k = dynamic_cast<const Contact*>(c)) {
    const BodyState a = state_of(data.q, k->circle().body), b = state_of(data.q, k->line().body);
    sliding_joint(data, w, scale, k->circle().body, k->line().body, k->contact_point(a, b), b.rotated(k->axis_local()), j);
  }
  return j;
}

// Friction magnitude of joint j at the multipliers y (coefficient scale 1), and its gradient.
double magnitude(const Joint& j, const Eigen::VectorXd& y, Eigen::Vector2d* gradient = nullptr) {
  if (gradient) gradient->setZero();
  if (j.law == Law::circle) {
    const Eigen::Vector2d f = y.segment<2>(j.slot);
    const double norm = f.norm();
    if (gradient && norm > 0.0) *gradient = j.rho * f / norm;
    return j.rho * norm;
  }
  const double n = y(j.slot + j.row_of_normal);
  double value = j.mu * std::abs(n);
  int which = j.row_of_normal;
  double slope = j.mu * (n >= 0 ? 1.0 : -1.0) * (n == 0.0 ? 0.0 : 1.0);
  if (j.law == Law::bearing) {
    const double m = y(j.slot), couple = j.mu * 2.0 * std::abs(m) / j.length;
    if (couple > value) {
      value = couple;
      which = 0;
      slope = j.mu * 2.0 / j.length * (m >= 0 ? 1.0 : -1.0);
    }
  }
  if (gradient) (*gradient)(which) = slope;
  return value;
}

struct System {
  std::vector<Joint> joints;
  Eigen::VectorXd y0;
  int m = 0;
};

// dH/dy at y for the coefficients times k and the sense (+1 forward, -1 reverse).
Eigen::MatrixXd friction_jacobian(const System& sys, const Eigen::VectorXd& y, double k, double sense) {
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(sys.m, sys.m);
  for (const Joint& j : sys.joints) {
    Eigen::Vector2d g;
    magnitude(j, y, &g);
    for (int r = 0; r < j.rows; ++r) J.col(j.slot + r) += (k * sense * g(r)) * j.h;
  }
  return J;
}

struct Solution {
  bool converged = false;
  Eigen::VectorXd y;
  double determinant = 0.0;  // of I - k dH/dy at y
};

// Newton's method on y - y0 - k sense H(y) = 0 from `y`.
Solution newton(const System& sys, double k, double sense, Eigen::VectorXd y) {
  Solution s;
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(sys.m, sys.m);
  for (int it = 0; it < 60; ++it) {
    Eigen::VectorXd G = y - sys.y0;
    for (const Joint& j : sys.joints) G -= (k * sense * magnitude(j, y)) * j.h;
    const Eigen::MatrixXd A = I - friction_jacobian(sys, y, k, sense);
    const double scale = std::max({1e-300, sys.y0.lpNorm<Eigen::Infinity>(), y.lpNorm<Eigen::Infinity>()});
    if (G.lpNorm<Eigen::Infinity>() <= 1e-12 * scale) {
      s.converged = true;
      s.y = y;
      s.determinant = A.determinant();
      return s;
    }
    const Eigen::VectorXd dy = A.partialPivLu().solve(-G);
    if (!dy.allFinite()) return s;
    y += dy;
  }
  return s;
}

// 1 / (largest real positive eigenvalue of dH/dy at y), +inf if there is none.
double pole_estimate(const System& sys, const Eigen::VectorXd& y, double sense) {
  const Eigen::MatrixXd J = friction_jacobian(sys, y, 1.0, sense);
  if (J.isZero(0.0)) return kInf;
  const Eigen::EigenSolver<Eigen::MatrixXd> es(J, false);
  double largest = 0.0;
  for (int i = 0; i < es.eigenvalues().size(); ++i) {
    const std::complex<double> l = es.eigenvalues()(i);
    if (std::abs(l.imag()) <= 1e-12 * std::abs(l) && l.real() > largest) largest = l.real();
  }
  return largest > 0.0 ? 1.0 / largest : kInf;
}

// The wedging factor k*, by continuation from the solution y at factor k towards the pole.
double locate_pole(const System& sys, Eigen::VectorXd y, double k, double sense) {
  double previous = kNaN;
  for (int it = 0; it < 80; ++it) {
    const double estimate = pole_estimate(sys, y, sense);
    if (estimate <= k) return k;  // not reached from a solution on the branch; kept as a guard
    if (estimate == kInf || std::abs(estimate - previous) <= 1e-13 * estimate) return estimate;
    previous = estimate;
    const double next = k + 0.5 * (estimate - k);
    const Solution s = newton(sys, next, sense, y);
    if (!s.converged || !(s.determinant > 0.0)) return estimate;
    k = next;
    y = s.y;
  }
  return previous;
}

struct SenseSolution {
  bool locked = false;
  double factor = kInf;
  Eigen::VectorXd y;
};

// The forward (+1) or reverse (-1) solution at the given coefficients (k = 1) and k*.
SenseSolution solve_sense(const System& sys, double sense) {
  SenseSolution r;
  r.factor = locate_pole(sys, sys.y0, 0.0, sense);
  // At the limit itself (the coefficient the seeds give as "mu = tan(alpha)") the mechanism
  // locks: a margin of 1e-9 keeps a coefficient printed to ten digits from giving 1e10 N m.
  if (r.factor <= 1.0 + 1e-9) {
    r.locked = true;
    return r;
  }
  Solution s = newton(sys, 1.0, sense, sys.y0);
  for (int steps = 2; (!s.converged || !(s.determinant > 0.0)) && steps <= 64; steps *= 2) {
    Eigen::VectorXd y = sys.y0;  // continuation in k when the direct step fails
    for (int i = 1; i <= steps; ++i) {
      s = newton(sys, static_cast<double>(i) / steps, sense, y);
      if (!s.converged) break;
      y = s.y;
    }
  }
  if (!s.converged || !(s.determinant > 0.0)) {
    r.locked = true;
    r.factor = std::min(r.factor, 1.0);
    return r;
  }
  r.y = s.y;
  r.factor = locate_pole(sys, s.y, 1.0, sense);  // refined from the solution (friction circles)
  return r;
}

// Q_f at the solution y for the sense, with the coefficients times k.
Eigen::VectorXd friction_forces_at(const System& sys, const Eigen::VectorXd& y, double sense, int n, double k = 1.0) {
  Eigen::VectorXd Q = Eigen::VectorXd::Zero(n);
  for (const Joint& j : sys.joints) Q += (k * sense * magnitude(j, y)) * j.direction;
  return Q;
}

double efficiency(double ideal_power, double power) {
  if (!std::isfinite(power) || ideal_power == 0.0) return kNaN;
  return ideal_power > 0.0 ? ideal_power / power : power / ideal_power;
}

// What one sense of motion needs to know about the driver it reports.
struct DriverMotion {
  Eigen::VectorXd dq;     // its input sensitivity
  double rate = 0.0;      // its input rate in the forward motion
};

// Where the loads drive the mechanism (ideal driver power < 0), the factor k at which the
// driver's power with friction reaches zero: beyond it the driver must push (efficiency <= 0),
// the self-locking of a screw or an incline. Bracketed by doubling, then Illinois regula falsi.
double zero_power_factor(const System& sys, double sense, const Eigen::VectorXd& applied, const DriverMotion& d,
                         double k_max) {
  const int n = static_cast<int>(applied.size());
  Eigen::VectorXd y = sys.y0;
  const auto power = [&](double k, bool& ok) {
    const Solution s = newton(sys, k, sense, y);
    ok = s.converged && s.determinant > 0.0;
    if (ok) y = s.y;
    return ok ? -sense * d.rate * (applied + friction_forces_at(sys, s.y, sense, n, k)).dot(d.dq) : kNaN;
  };
  double lo = 0.0, p_lo = -sense * d.rate * applied.dot(d.dq), hi = std::min(1.0, 0.5 * k_max), p_hi = 0.0;
  bool ok = true;
  for (int i = 0; i < 80; ++i, hi = std::min(2.0 * hi, 0.5 * (hi + k_max))) {
    p_hi = power(hi, ok);
    if (!ok) return kInf;
    if (p_hi >= 0.0) break;
    lo = hi;
    p_lo = p_hi;
    if (hi >= 1e12) return kInf;
  }
  if (!(p_hi >= 0.0)) return kInf;
  int side = 0;
  for (int it = 0; it < 200 && hi - lo > 1e-14 * hi; ++it) {
    double k = (lo * p_hi - hi * p_lo) / (p_hi - p_lo);
    if (!(k > lo && k < hi)) k = 0.5 * (lo + hi);
    const double p = power(k, ok);
    if (!ok) return kInf;
    if (p == 0.0) return k;
    if (p < 0.0) {
      lo = k, p_lo = p;
      if (side == -1) p_hi *= 0.5;
      side = -1;
    } else {
      hi = k, p_hi = p;
      if (side == 1) p_lo *= 0.5;
      side = 1;
    }
  }
  return 0.5 * (lo + hi);
}

// Efforts, efficiencies and self-locking of one sense for every driver; `reported` is the
// driver whose self-locking the sense reports. Returns the solution at the given coefficients.
SenseSolution analyse_sense(const System& sys, double sense, const Eigen::VectorXd& applied,
                            const std::vector<DriverMotion>& drivers, int reported, double scale, FrictionSense& r) {
  const SenseSolution s = solve_sense(sys, sense);
  r.wedged = s.locked;
  r.wedging_factor = s.factor;
  const int n = static_cast<int>(applied.size());
  const Eigen::VectorXd Qf = s.locked ? Eigen::VectorXd() : friction_forces_at(sys, s.y, sense, n);
  for (const DriverMotion& d : drivers) {
    const double e = s.locked ? kNaN : -(applied + Qf).dot(d.dq);
    const double v = sense * d.rate;
    r.effort.push_back(e);
    r.efficiency.push_back(std::abs(v) <= 1e-12 * scale ? kNaN : efficiency(-applied.dot(d.dq) * v, e * v));
  }
  r.critical_factor = s.factor;
  const DriverMotion& d = drivers[static_cast<std::size_t>(reported)];
  if (-sense * d.rate * applied.dot(d.dq) < 0.0)  // the loads drive the mechanism in this sense
    r.critical_factor = std::min(r.critical_factor, zero_power_factor(sys, sense, applied, d, s.factor));
  r.self_locking = r.wedged || r.critical_factor <= 1.0 + 1e-9;
  return s;
}

// The system of the joints with friction at the current state.
System build_system(const Model& model, Data& data, const Eigen::VectorXd& w, double scale, const Eigen::VectorXd& lambda0,
                    std::vector<std::string>& warnings) {
  System sys;
  for (const JointFriction& f : model.frictions()) {
    Joint j = make_joint(model, data, f, w, scale);
    j.slot = sys.m;
    sys.m += j.rows;
    if (sign_of(j.sliding, scale) == 0.0)
      warnings.push_back(fmt::format("joint '{}' does not slide or turn in this motion: its static friction is not "
                                     "determined and is taken as zero", model.constraints()[static_cast<std::size_t>(f.constraint)].name));
    sys.joints.push_back(std::move(j));
  }
  sys.y0.resize(sys.m);
  for (Joint& j : sys.joints) {
    sys.y0.segment(j.slot, j.rows) = lambda0.segment(j.first_row, j.rows);
    const Eigen::VectorXd full = solve_with_jacobian_transpose(data, j.direction);
    j.h.resize(sys.m);
    for (const Joint& other : sys.joints) j.h.segment(other.slot, other.rows) = full.segment(other.first_row, other.rows);
  }
  return sys;
}

// The forward friction of each joint at the solution y.
void report_joints(const Model& model, const System& sys, const Eigen::VectorXd& y, double scale, FrictionAnalysis& out) {
  for (const Joint& j : sys.joints) {
    const ModelConstraint& mc = model.constraints()[static_cast<std::size_t>(j.constraint)];
    JointFrictionForce jf;
    jf.constraint = j.constraint;
    jf.name = mc.name;
    jf.kind = mc.constraint->kind();
    const double g = magnitude(j, y);
    jf.normal = j.law == Law::circle ? y.segment<2>(j.slot).norm() : -y(j.slot + j.row_of_normal);
    jf.friction = -sign_of(j.sliding, scale) * g;
    jf.sliding = j.sliding;
    jf.power = std::abs(g * j.actual);
    out.dissipated_power += jf.power;
    if (jf.kind == "contact" && jf.normal < 0.0 && g > 0.0)
      out.warnings.push_back(fmt::format("contact '{}' pulls (N = {:.6g} N): it would open; the model keeps it closed", jf.name, jf.normal));
    out.joints.push_back(jf);
  }
}

}  // namespace

FrictionAnalysis analyse_friction(const Model& model, Data& data, int driver, const Eigen::VectorXd& applied,
                                  const Eigen::VectorXd& lambda0, Eigen::VectorXd& lambda,
                                  Eigen::VectorXd& friction_forces) {
  if (driver < 0 || driver >= static_cast<int>(model.drivers().size()))
    throw std::invalid_argument("analyse_friction: driver out of range");
  const int n = model.coordinates();
  // The motion: the velocities, or the quasi-static motion of increasing input.
  Eigen::VectorXd w = data.qd;
  if (w.isZero(0.0)) w = input_sensitivity(model, data, driver);
  const double scale = std::max(1.0, w.lpNorm<Eigen::Infinity>());
  FrictionAnalysis out;
  const System sys = build_system(model, data, w, scale, lambda0, out.warnings);
  std::vector<DriverMotion> drivers;
  const Eigen::VectorXd rates = data.phi_q * w;  // each driver's row of Phi_q w is its input rate
  for (std::size_t k = 0; k < model.drivers().size(); ++k) {
    drivers.push_back({input_sensitivity(model, data, static_cast<int>(k)),
                       rates(model.constraints()[static_cast<std::size_t>(model.drivers()[k].constraint)].first_row)});
    out.effort_ideal.push_back(-applied.dot(drivers.back().dq));
  }
  const SenseSolution forward = analyse_sense(sys, 1.0, applied, drivers, driver, scale, out.forward);
  analyse_sense(sys, -1.0, applied, drivers, driver, scale, out.reverse);
  lambda = lambda0;
  friction_forces = Eigen::VectorXd::Zero(n);
  if (forward.locked) return out;
  friction_forces = friction_forces_at(sys, forward.y, 1.0, n);
  lambda = solve_with_jacobian_transpose(data, applied + friction_forces);
  report_joints(model, sys, forward.y, scale, out);
  return out;
}

}  // namespace gearkit::kin
