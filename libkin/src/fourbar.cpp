#include <gearkit/kin/fourbar.hpp>

#include <gearkit/kin/solve.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>

namespace gearkit::kin {

GrashofResult grashof(double ground, double crank, double coupler, double rocker) {
  const std::array<double, 4> links{ground, crank, coupler, rocker};
  const auto shortest = static_cast<int>(std::min_element(links.begin(), links.end()) - links.begin());
  const double s = links[static_cast<std::size_t>(shortest)];
  const double l = *std::max_element(links.begin(), links.end());
  const double pq = ground + crank + coupler + rocker - s - l;
  GrashofResult r{GrashofClass::triple_rocker, s, l, pq, {}};
  const double tolerance = 1e-9 * (s + l + pq);
  if (std::abs(s + l - pq) <= tolerance) {
    r.kind = GrashofClass::change_point;
    r.text = fmt::format("change point (s + l = p + q = {:.6g} mm): the linkage can flatten and switch branch", pq * 1000);
    return r;
  }
  if (s + l > pq) {
    r.kind = GrashofClass::triple_rocker;
    r.text = fmt::format("non-Grashof triple rocker (s + l = {:.6g} mm > p + q = {:.6g} mm): no link turns fully",
                         (s + l) * 1000, pq * 1000);
    return r;
  }
  if (shortest == 0) {
    r.kind = GrashofClass::double_crank;
    r.text = "Grashof double crank (shortest link is the ground)";
  } else if (shortest == 2) {
    r.kind = GrashofClass::double_rocker;
    r.text = "Grashof double rocker (shortest link is the coupler)";
  } else {
    r.kind = GrashofClass::crank_rocker;
    r.text = shortest == 1 ? "Grashof crank-rocker (the input crank turns fully)"
                           : "Grashof rocker-crank (the output link turns fully)";
  }
  r.text += fmt::format(" (s + l = {:.6g} mm < p + q = {:.6g} mm)", (s + l) * 1000, pq * 1000);
  return r;
}

double transmission_angle(const Eigen::Vector2d& coupler, const Eigen::Vector2d& rocker) {
  const double c = std::abs(coupler.dot(rocker)) / (coupler.norm() * rocker.norm());
  return std::acos(std::clamp(c, 0.0, 1.0));
}

std::optional<FourBar> find_four_bar(const Model& model) {
  if (model.bodies().size() != 3 || model.drivers().size() != 1) return std::nullopt;
  std::vector<const Revolute*> joints;
  const AngleDriver* driver = nullptr;
  int driven = -1;
  for (const ModelConstraint& mc : model.constraints()) {
    if (auto r = dynamic_cast<const Revolute*>(mc.constraint.get())) {
      joints.push_back(r);
    } else if (auto d = dynamic_cast<const AngleDriver*>(mc.constraint.get())) {
      driver = d;
      const auto b = d->bodies();
      if (b[1] != kGround) return std::nullopt;
      driven = b[0];
    } else {
      return std::nullopt;
    }
  }
  if (joints.size() != 4 || !driver) return std::nullopt;
  // Orient each joint as (body, other) pairs.
  auto joint_between = [&](int x, int y, BodyPoint& on_x, BodyPoint& on_y) {
    for (const Revolute* r : joints) {
      if (r->a().body == x && r->b().body == y) {
        on_x = r->a();
        on_y = r->b();
        return true;
      }
      if (r->b().body == x && r->a().body == y) {
        on_x = r->b();
        on_y = r->a();
        return true;
      }
    }
    return false;
  };
  FourBar f;
  f.crank = driven;
  BodyPoint ground_o2;
  if (!joint_between(f.crank, kGround, f.a_crank, ground_o2)) return std::nullopt;
  f.o2 = ground_o2;
  // The crank's other joint.
  std::swap(f.a_crank, ground_o2);  // ground_o2 now holds the crank's ground-side point
  const BodyPoint crank_ground_point = ground_o2;
  for (int c = 0; c < 3; ++c) {
    if (c == f.crank) continue;
    BodyPoint on_crank, on_coupler;
    if (!joint_between(f.crank, c, on_crank, on_coupler)) continue;
    const int r = 3 - f.crank - c;
    BodyPoint on_c2, on_r, on_r_ground, ground_pt;
    if (!joint_between(c, r, on_c2, on_r) || !joint_between(r, kGround, on_r_ground, ground_pt)) return std::nullopt;
    f.coupler = c;
    f.rocker = r;
    f.a_crank = on_crank;
    f.a_coupler = on_coupler;
    f.b_coupler = on_c2;
    f.b_rocker = on_r;
    f.o4 = ground_pt;
    f.ground = (f.o4.local - f.o2.local).norm();
    f.crank_length = (on_crank.local - crank_ground_point.local).norm();
    f.coupler_length = (on_c2.local - on_coupler.local).norm();
    f.rocker_length = (on_r.local - on_r_ground.local).norm();
    return f;
  }
  return std::nullopt;
}

double transmission_angle(const FourBar& f, const Data& data) {
  const Eigen::Vector2d a = point_position(data, f.a_coupler);
  const Eigen::Vector2d b = point_position(data, f.b_coupler);
  const Eigen::Vector2d o4 = point_position(data, f.o4);
  return transmission_angle(b - a, b - o4);
}

}  // namespace gearkit::kin
