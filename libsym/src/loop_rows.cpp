// LoopWriter::rows and describe: walking one loop link by link.
#include "loop_writer.hpp"
#include "trig.hpp"

#include <cmath>

namespace gearkit::sym::detail {

using GiNaC::ex;

namespace {

constexpr double kMm = 1000.0;

const Eigen::Vector2d& point_on(const JointEdge& e, int body) { return e.a.body == body ? e.a.local : e.b.local; }

int displacement_coordinate(const EquationsInput& input, int constraint) {
  for (std::size_t k = 0; k < input.coordinates.size(); ++k)
    if (!input.coordinates[k].is_angle && input.coordinates[k].displacement.joint == constraint) return static_cast<int>(k);
  return -1;
}

}  // namespace

std::vector<ex> LoopWriter::rows(const Loop& loop) const {
  ex sx = 0, sy = 0;
  std::optional<Vec> unknown_axis;
  int unknowns = 0;
  const std::size_t n = loop.size();
  for (std::size_t i = 0; i < n; ++i) {
    const LoopStep& in = loop[i];
    const LoopStep& out = loop[(i + 1) % n];
    const int body = in.to;  // == out.from
    const auto v = body_vector(body, point_on(edges_[static_cast<std::size_t>(in.edge)], body),
                               point_on(edges_[static_cast<std::size_t>(out.edge)], body));
    if (!v) return {};
    sx += (*v)[0];
    sy += (*v)[1];
    const JointEdge& e = edges_[static_cast<std::size_t>(out.edge)];
    if (e.kind == JointEdge::Kind::revolute) continue;
    // The slide from the guide's point to the slider's point is t u, u the axis in the world.
    const auto u = local_direction(e.b.body, std::atan2(e.axis.y(), e.axis.x()));
    if (!u) return {};
    const double walk = out.from == e.b.body ? +1.0 : -1.0;
    const int k = e.kind == JointEdge::Kind::prismatic ? displacement_coordinate(input_, e.constraint) : -1;
    if (k < 0) {
      ++unknowns;
      unknown_axis = *u;
      continue;
    }
    const DisplacementCoordinate& c = input_.coordinates[static_cast<std::size_t>(k)].displacement;
    const ex t = c.sign * sys_.q[static_cast<std::size_t>(k)] - number(e.axis.dot(e.b.local - c.origin) * kMm);
    sx += walk * t * (*u)[0];
    sy += walk * t * (*u)[1];
  }
  if (unknowns == 0) return {sx.expand(), sy.expand()};
  if (unknowns > 1) return {};
  // Project on the normal of the unknown slide: its displacement drops out.
  const Vec& u = *unknown_axis;
  return {combine_trig(-u[1] * sx + u[0] * sy)};
}

std::string LoopWriter::describe(const Loop& loop) const {
  std::string s;
  for (const LoopStep& step : loop) s += edges_[static_cast<std::size_t>(step.edge)].name + " - ";
  return s + edges_[static_cast<std::size_t>(loop.front().edge)].name;
}

}  // namespace gearkit::sym::detail
