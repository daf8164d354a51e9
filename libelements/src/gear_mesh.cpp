#include <gearkit/elements/gear_mesh.hpp>

#include "checks.hpp"

#include <gearkit/kin/angle_relation.hpp>

#include <fmt/format.h>

#include <cmath>

namespace gearkit::elements {

namespace {

constexpr double kDeg = 0.017453292519943295;

// k in (theta_2 - theta_c) + k (theta_1 - theta_c) = phase.
double mesh_factor(const GearMeshParameters& p) {
  const double ratio = static_cast<double>(p.z1) / static_cast<double>(p.z2);
  return p.internal ? -ratio : ratio;
}

// Tooth forces on the reference circle of gear 2 for the torque T_2 it receives (ISO 6336-1
// nominal tangential load F_t = 2 T / d; ISO 21771 transverse pressure angle).
void add_tooth_forces(const GearMeshParameters& p, double T2, std::vector<kin::ReactionValue>& values) {
  const double beta = p.helix_angle, alpha_n = p.pressure_angle;
  const double r2 = *p.module * p.z2 / (2.0 * std::cos(beta));
  const double F_t = std::abs(T2) / r2;
  const double alpha_t = std::atan(std::tan(alpha_n) / std::cos(beta));
  values.push_back({"F_t", "N", F_t, "nominal tangential force on the reference circle (ISO 6336-1)"});
  values.push_back({"F_r", "N", F_t * std::tan(alpha_t), "radial force"});
  values.push_back({"F_n", "N", F_t / (std::cos(alpha_n) * std::cos(beta)), "normal tooth force"});
  if (beta != 0.0) values.push_back({"F_a", "N", F_t * std::tan(std::abs(beta)), "axial force"});
}

class GearMesh final : public kin::Constraint {
 public:
  GearMesh(const GearMeshParameters& p, double phase)
      : p_(p), k_(mesh_factor(p)),
        relation_({{p.gear2, 1.0}, {p.gear1, k_}, {p.carrier, -1.0 - k_}}, phase, "gear_mesh") {}
  std::string kind() const override { return "gear_mesh"; }
  int equations() const override { return 1; }
  std::vector<int> bodies() const override { return relation_.bodies(); }
  void evaluate(const kin::ConstraintInput& in, kin::ConstraintOutput& out) const override {
    relation_.evaluate(in, out);
  }
  kin::Reaction reaction(const kin::ConstraintInput&, std::span<const double> lambda) const override {
    const double T2 = -lambda[0], T1 = -k_ * lambda[0];
    kin::Reaction r;
    r.moment = T2;  // the first body is gear 2
    r.values.push_back({"T_1", "N m", T1, "torque on gear 1 from gear 2"});
    r.values.push_back({"T_2", "N m", T2, "torque on gear 2 from gear 1"});
    if (p_.module) add_tooth_forces(p_, T2, r.values);
    return r;
  }

 private:
  GearMeshParameters p_;
  double k_;
  kin::AngleRelation relation_;
};

void check_parameters(const kin::Model& model, const GearMeshParameters& p) {
  check_body(model, p.gear1, "gear1", false);
  check_body(model, p.gear2, "gear2", false);
  check_body(model, p.carrier, "carrier", true);
  if (p.gear1 == p.gear2 || p.gear1 == p.carrier || p.gear2 == p.carrier)
    throw kin::ElementError("gear2", "expected gear1, gear2 and carrier to be three different links");
  for (const auto& [field, z] : {std::pair{"z1", p.z1}, std::pair{"z2", p.z2}})
    if (z < 1) throw kin::ElementError(field, fmt::format("'{}': expected a number of teeth >= 1, found {}", field, z));
  if (p.internal && p.z2 <= p.z1)
    throw kin::ElementError("z2", fmt::format("'z2': expected the internal gear 2 to have more teeth than gear 1 "
                                              "({}), found {}", p.z1, p.z2));
  if (p.module && !(*p.module > 0.0))
    throw kin::ElementError("module", fmt::format("'module': expected a module > 0, found {} mm", *p.module * 1e3));
  if (!(p.pressure_angle > 0.0 && p.pressure_angle < 45.0 * kDeg))
    throw kin::ElementError("pressure_angle", fmt::format("'pressure_angle': expected an angle in (0, 45) deg, found "
                                                          "{:g} deg", p.pressure_angle / kDeg));
  if (!(std::abs(p.helix_angle) < 45.0 * kDeg))
    throw kin::ElementError("helix_angle", fmt::format("'helix_angle': expected an angle in (-45, 45) deg, found "
                                                       "{:g} deg", p.helix_angle / kDeg));
}

}  // namespace

std::unique_ptr<kin::Constraint> make_gear_mesh(const kin::Model& model, const GearMeshParameters& p) {
  check_parameters(model, p);
  const double k = mesh_factor(p);
  const auto drawn = [&](int body) { return drawn_angle(model, body) - drawn_angle(model, p.carrier); };
  const double phase = p.phase.value_or(drawn(p.gear2) + k * drawn(p.gear1));
  return std::make_unique<GearMesh>(p, phase);
}

int add_gear_mesh(kin::Model& model, std::string name, const GearMeshParameters& p) {
  return add_element(model, std::move(name), make_gear_mesh(model, p));
}

}  // namespace gearkit::elements
