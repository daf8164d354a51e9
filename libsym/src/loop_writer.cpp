#include "loop_writer.hpp"

#include <cmath>
#include <numbers>
#include <numeric>

namespace gearkit::sym::detail {

using GiNaC::ex;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double kMm = 1000.0;  // the equations are written in mm, as the course's figures

double wrap(double a) { return std::remainder(a, 2 * pi); }
bool near(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return (a - b).norm() < 1e-12; }
bool same_point(const kin::BodyPoint& p, int body, const Eigen::Vector2d& local) {
  return p.body == body && near(p.local, local);
}
double direction_of(const Eigen::Vector2d& v) { return std::atan2(v.y(), v.x()); }

int find(std::vector<int>& parent, int x) {
  while (parent[static_cast<std::size_t>(x)] != x) x = parent[static_cast<std::size_t>(x)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
  return x;
}

}  // namespace

LoopWriter::LoopWriter(const kin::Model& model, const EquationsInput& input, const Eigen::VectorXd& pose, SymbolicSystem& sys)
    : model_(model), input_(input), pose_(pose), sys_(sys), edges_(joint_edges(model)) {
  // Links joined by a prismatic joint keep their relative angle: one angle group.
  const int nodes = static_cast<int>(model.bodies().size()) + 1;
  std::vector<int> parent(static_cast<std::size_t>(nodes));
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& e : edges_)
    if (e.kind == JointEdge::Kind::prismatic) parent[static_cast<std::size_t>(find(parent, e.a.body + 1))] = find(parent, e.b.body + 1);
  group_.resize(static_cast<std::size_t>(nodes));
  for (int n = 0; n < nodes; ++n) group_[static_cast<std::size_t>(n)] = find(parent, n);
  group_coord_.assign(static_cast<std::size_t>(nodes), -1);
  group_fixed_.assign(static_cast<std::size_t>(nodes), false);
  group_fixed_[static_cast<std::size_t>(group_[0])] = true;
  for (std::size_t k = 0; k < input.coordinates.size(); ++k) {
    const Coordinate& c = input.coordinates[k];
    if (!c.is_angle) continue;
    int& slot = group_coord_[static_cast<std::size_t>(group_of(c.angle.from.body))];
    if (slot < 0) slot = static_cast<int>(k);
  }
}

double LoopWriter::body_angle(int body) const {
  return body == kin::kGround ? 0.0 : pose_[3 * body + 2];
}

LoopWriter::Vec LoopWriter::direction(int k, double off) const {
  const Coordinate& c = input_.coordinates[static_cast<std::size_t>(k)];
  const double total = wrap(c.angle.zero + off);
  ex extra = 0;
  int quadrant = 0;
  bool found = false;
  auto try_match = [&](double rest, const ex& what) {
    for (int m : {0, 1, -1, 2})
      if (!found && std::abs(wrap(total - rest - m * pi / 2)) < 1e-9) {
        quadrant = m;
        extra = what;
        found = true;
      }
  };
  try_match(0.0, 0);
  for (std::size_t s = 0; s < input_.symbols.size() && !found; ++s)
    if (input_.symbols[s].kind == Symbol::Kind::angle) {
      try_match(sys_.param_values[s], sys_.params[s]);
      try_match(-sys_.param_values[s], -sys_.params[s]);
    }
  if (!found) extra = number(total);
  // cos(sense phi + extra) = cos(phi + sense extra), sin(...) = sense sin(phi + sense extra).
  const int sense = c.angle.sense;
  const ex x = sys_.q[static_cast<std::size_t>(k)] + sense * extra;
  const ex C = GiNaC::cos(x), S = sense * GiNaC::sin(x);
  switch (quadrant) {
    case 1: return {-S, C};
    case -1: return {S, -C};
    case 2: return {-C, -S};
    default: return {C, S};
  }
}

std::optional<LoopWriter::Vec> LoopWriter::local_direction(int body, double beta) const {
  const std::size_t g = static_cast<std::size_t>(group_of(body));
  if (group_fixed_[g]) {
    const double a = body_angle(body) + beta;
    return Vec{number(std::cos(a)), number(std::sin(a))};
  }
  const int k = group_coord_[g];
  if (k < 0) return std::nullopt;
  const Coordinate& c = input_.coordinates[static_cast<std::size_t>(k)];
  const double beta_c = direction_of(c.angle.to.local - c.angle.from.local);
  return direction(k, body_angle(body) - body_angle(c.angle.from.body) - beta_c + beta);
}

ex LoopWriter::length(int body, const Eigen::Vector2d& p, const Eigen::Vector2d& r) const {
  const double L = (r - p).norm() * kMm;
  for (std::size_t s = 0; s < input_.symbols.size(); ++s) {
    const Symbol& y = input_.symbols[s];
    if (y.kind != Symbol::Kind::length) continue;
    if ((same_point(y.a, body, p) && same_point(y.b, body, r)) || (same_point(y.a, body, r) && same_point(y.b, body, p)))
      return sys_.params[s];
  }
  for (std::size_t s = 0; s < input_.symbols.size(); ++s) {
    const Symbol& y = input_.symbols[s];
    if (y.kind == Symbol::Kind::length && y.a.body == body && std::abs(sys_.param_values[s] - L) < 1e-9 * std::max(1.0, L))
      return sys_.params[s];
  }
  return number(L);
}

LoopWriter::Vec LoopWriter::fixed_vector(int body, const Eigen::Vector2d& p, const Eigen::Vector2d& r) const {
  const Eigen::Vector2d w = Eigen::Rotation2Dd(body_angle(body)) * (r - p) * kMm;
  Vec out{number(w.x()), number(w.y())};
  for (std::size_t s = 0; s < input_.symbols.size(); ++s) {
    const Symbol& y = input_.symbols[s];
    const int axis = y.kind == Symbol::Kind::dx ? 0 : y.kind == Symbol::Kind::dy ? 1 : -1;
    if (axis < 0) continue;
    if (same_point(y.a, body, p) && same_point(y.b, body, r)) out[static_cast<std::size_t>(axis)] = sys_.params[s];
    if (same_point(y.a, body, r) && same_point(y.b, body, p)) out[static_cast<std::size_t>(axis)] = -sys_.params[s];
  }
  // A length symbol along an axis serves as that component.
  const ex L = length(body, p, r);
  if (!GiNaC::is_a<GiNaC::numeric>(L)) {
    if (std::abs(w.y()) < 1e-9 && GiNaC::is_a<GiNaC::numeric>(out[0])) out[0] = w.x() > 0 ? L : -L;
    if (std::abs(w.x()) < 1e-9 && GiNaC::is_a<GiNaC::numeric>(out[1])) out[1] = w.y() > 0 ? L : -L;
  }
  return out;
}

std::optional<LoopWriter::Vec> LoopWriter::body_vector(int body, const Eigen::Vector2d& p, const Eigen::Vector2d& r) const {
  if (near(p, r)) return Vec{0, 0};
  if (group_fixed_[static_cast<std::size_t>(group_of(body))]) return fixed_vector(body, p, r);
  const auto d = local_direction(body, direction_of(r - p));
  if (!d) return std::nullopt;
  const ex L = length(body, p, r);
  return Vec{L * (*d)[0], L * (*d)[1]};
}

}  // namespace gearkit::sym::detail
