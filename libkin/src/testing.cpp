#include <gearkit/kin/testing.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>

namespace gearkit::kin::testing {

namespace {

// The bodies of a constraint: its slots (bodies() in order) and the distinct moving bodies
// among them, whose coordinates are the ones that vary.
struct Slots {
  std::vector<int> body_of_slot;  // index into the distinct bodies, -1 for kGround
  int distinct = 0;
};

Slots slots_of(const Constraint& c) {
  Slots s;
  std::vector<int> seen;
  for (const int b : c.bodies()) {
    if (b == kGround) {
      s.body_of_slot.push_back(-1);
      continue;
    }
    const auto it = std::find(seen.begin(), seen.end(), b);
    s.body_of_slot.push_back(static_cast<int>(it - seen.begin()));
    if (it == seen.end()) seen.push_back(b);
  }
  s.distinct = static_cast<int>(seen.size());
  return s;
}

// One random configuration: per distinct body q, qd, qdd; the time and a driver's input f0.
struct Configuration {
  std::vector<Eigen::Vector3d> q, qd, qdd;
  double t = 0.0, input = 0.0;
};

Configuration draw(std::mt19937_64& rng, int bodies, const DerivativeCheckOptions& o) {
  std::uniform_real_distribution<double> position(-o.position_range, o.position_range),
      angle(-std::numbers::pi, std::numbers::pi), rate(-o.rate_range, o.rate_range), unit(0.0, 1.0);
  Configuration c;
  for (int i = 0; i < bodies; ++i) {
    c.q.emplace_back(position(rng), position(rng), angle(rng));
    c.qd.emplace_back(rate(rng), rate(rng), rate(rng));
    c.qdd.emplace_back(rate(rng), rate(rng), rate(rng));
  }
  c.t = unit(rng);
  c.input = 2.0 * unit(rng) - 1.0;
  return c;
}

// A coordinate nudged: distinct body `body` (or -1: none), coordinate 0 x, 1 y, 2 theta.
struct Nudge {
  int body = -1, coordinate = 0;
  double by = 0.0;
};

// The slots' states at time offset s along q(s) = q + qd s + qdd s^2 / 2 (ground: all zero).
std::vector<BodyState> states_at(const Slots& slots, const Configuration& c, double s, Nudge nudge = {}) {
  std::vector<BodyState> out(slots.body_of_slot.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    const int b = slots.body_of_slot[k];
    if (b < 0) continue;
    const auto i = static_cast<std::size_t>(b);
    Eigen::Vector3d q = c.q[i] + c.qd[i] * s + 0.5 * c.qdd[i] * s * s;
    const Eigen::Vector3d v = c.qd[i] + c.qdd[i] * s;
    if (b == nudge.body) q(nudge.coordinate) += nudge.by;
    out[k].r = q.head<2>();
    out[k].set_theta(q(2));
    out[k].r_dot = v.head<2>();
    out[k].omega = v(2);
  }
  return out;
}

struct Rows {
  Eigen::VectorXd phi, phi_t, gamma;
  Eigen::MatrixXd phi_q;
};

// Evaluates into outputs filled with NaN, so that an entry evaluate() does not write shows.
Rows evaluate(const Constraint& c, const std::vector<BodyState>& states, double t, double input) {
  const int m = c.equations(), columns = 3 * static_cast<int>(states.size());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Rows r{Eigen::VectorXd::Constant(m, nan), Eigen::VectorXd::Constant(m, nan), Eigen::VectorXd::Constant(m, nan),
         Eigen::MatrixXd::Constant(m, columns, nan)};
  ConstraintOutput out{r.phi, r.phi_q, r.phi_t, r.gamma};
  c.evaluate(ConstraintInput{states, t, input}, out);
  return r;
}

class Checker {
 public:
  Checker(const Constraint& c, const DerivativeCheckOptions& o, DerivativeReport& report)
      : c_(c), o_(o), report_(report), slots_(slots_of(c)) {}

  void check(const Configuration& cfg, int index) {
    index_ = index;
    const std::vector<BodyState> at = states_at(slots_, cfg, 0.0);
    const Rows r = evaluate(c_, at, cfg.t, cfg.input);
    if (!written(r)) return;  // NaN rows make every comparison below meaningless
    jacobian(cfg, r);
    const Rows tp = evaluate(c_, at, cfg.t + o_.h_t, cfg.input), tm = evaluate(c_, at, cfg.t - o_.h_t, cfg.input);
    const Eigen::VectorXd phi_t = (tp.phi - tm.phi) / (2.0 * o_.h_t);
    for (int k = 0; k < c_.equations(); ++k) compare("Phi_t", k, -1, r.phi_t(k), phi_t(k), o_.absolute, o_.relative);
    gamma(cfg, r);
  }

 private:
  // Every entry of the rows written (a NaN left means an entry evaluate() never wrote; the
  // columns of a kGround slot are ignored by the assembler and may be left).
  bool written(const Rows& r) {
    const std::size_t before = report_.mismatches.size();
    const auto unwritten = [&](int row, int column, double value) {
      if (!std::isfinite(value)) report_.mismatches.push_back({"not finite", index_, row, column, value, 0.0});
    };
    for (int k = 0; k < c_.equations(); ++k) {
      unwritten(k, -1, r.phi(k));
      unwritten(k, -1, r.phi_t(k));
      unwritten(k, -1, r.gamma(k));
      for (std::size_t slot = 0; slot < slots_.body_of_slot.size(); ++slot)
        for (int j = 0; j < 3 && slots_.body_of_slot[slot] >= 0; ++j)
          unwritten(k, 3 * static_cast<int>(slot) + j, r.phi_q(k, 3 * static_cast<int>(slot) + j));
    }
    return report_.mismatches.size() == before;
  }

  void jacobian(const Configuration& cfg, const Rows& r) {
    for (int b = 0; b < slots_.distinct; ++b)
      for (int j = 0; j < 3; ++j) {
        const Rows plus = evaluate(c_, states_at(slots_, cfg, 0.0, {b, j, o_.h_q}), cfg.t, cfg.input);
        const Rows minus = evaluate(c_, states_at(slots_, cfg, 0.0, {b, j, -o_.h_q}), cfg.t, cfg.input);
        const Eigen::VectorXd numeric = (plus.phi - minus.phi) / (2.0 * o_.h_q);
        int first_column = -1;
        Eigen::VectorXd analytic = Eigen::VectorXd::Zero(c_.equations());
        for (std::size_t slot = 0; slot < slots_.body_of_slot.size(); ++slot)
          if (slots_.body_of_slot[slot] == b) {
            const int column = 3 * static_cast<int>(slot) + j;
            if (first_column < 0) first_column = column;
            analytic += r.phi_q.col(column);
          }
        for (int k = 0; k < c_.equations(); ++k)
          compare("Phi_q", k, first_column, analytic(k), numeric(k), o_.absolute, o_.relative);
      }
  }

  // d2/ds2 Phi(q(s), t + s) = Phi_q qdd - gamma, so gamma = Phi_q qdd - (second difference).
  void gamma(const Configuration& cfg, const Rows& r) {
    const double h = o_.h_t;
    const Rows plus = evaluate(c_, states_at(slots_, cfg, h), cfg.t + h, cfg.input);
    const Rows minus = evaluate(c_, states_at(slots_, cfg, -h), cfg.t - h, cfg.input);
    const Eigen::VectorXd second = (plus.phi - 2.0 * r.phi + minus.phi) / (h * h);
    Eigen::VectorXd phi_q_qdd = Eigen::VectorXd::Zero(c_.equations());
    for (std::size_t slot = 0; slot < slots_.body_of_slot.size(); ++slot) {
      const int b = slots_.body_of_slot[slot];
      if (b >= 0) phi_q_qdd += r.phi_q.middleCols<3>(3 * static_cast<int>(slot)) * cfg.qdd[static_cast<std::size_t>(b)];
    }
    const Eigen::VectorXd numeric = phi_q_qdd - second;
    for (int k = 0; k < c_.equations(); ++k)
      compare("gamma", k, -1, r.gamma(k), numeric(k), o_.absolute_gamma, o_.relative_gamma);
  }

  void compare(const char* quantity, int row, int column, double analytic, double numeric, double absolute,
               double relative) {
    ++report_.entries_checked;
    const double allowed = absolute + relative * std::max(std::abs(analytic), std::abs(numeric));
    if (!(std::abs(analytic - numeric) <= allowed))
      report_.mismatches.push_back({quantity, index_, row, column, analytic, numeric});
  }

  const Constraint& c_;
  const DerivativeCheckOptions& o_;
  DerivativeReport& report_;
  Slots slots_;
  int index_ = 0;
};

}  // namespace

std::string DerivativeReport::describe(const std::string& kind) const {
  std::string out;
  const std::size_t shown = std::min<std::size_t>(mismatches.size(), 8);
  for (std::size_t i = 0; i < shown; ++i) {
    const DerivativeMismatch& m = mismatches[i];
    out += fmt::format("{}: {} row {}{} configuration {}: analytic {:.12g}, finite difference {:.12g}\n", kind,
                       m.quantity, m.row, m.column >= 0 ? fmt::format(" column {}", m.column) : std::string(),
                       m.configuration, m.analytic, m.numeric);
  }
  if (mismatches.size() > shown) out += fmt::format("{}: ... {} more\n", kind, mismatches.size() - shown);
  return out;
}

DerivativeReport check_derivatives(const Constraint& constraint, const DerivativeCheckOptions& options) {
  if (options.configurations < 1) throw std::invalid_argument("check_derivatives: configurations must be >= 1");
  if (!(options.h_q > 0.0) || !(options.h_t > 0.0))
    throw std::invalid_argument("check_derivatives: the steps h_q and h_t must be > 0");
  DerivativeReport report;
  std::mt19937_64 rng(options.seed);
  Checker checker(constraint, options, report);
  const int bodies = slots_of(constraint).distinct;
  for (int i = 0; i < options.configurations; ++i) checker.check(draw(rng, bodies, options), i);
  return report;
}

}  // namespace gearkit::kin::testing
