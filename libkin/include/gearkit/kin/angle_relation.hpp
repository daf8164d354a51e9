#pragma once
// A linear relation between body angles, sum_k c_k theta_k = constant: one equation. It is
// what gear meshes (omega_2/c = -z1/z2 omega_1/c) and epicyclic trains (Willis' equation)
// impose on the rotations of their members, so the plugins build their elements from it.
#include <gearkit/kin/constraint.hpp>
#include <string>
#include <utility>
#include <vector>

namespace gearkit::kin {

class AngleRelation final : public Constraint {
 public:
  /// @param terms (body, coefficient) pairs; kGround terms are allowed and contribute nothing.
  /// @param constant [rad] the value of the sum (the phase of the drawn configuration).
  /// @param kind what the relation is ("gear_mesh", "epicyclic_train").
  /// Bodies are checked when the relation is added to a Model (Model::add_constraint).
  /// @throws std::bad_alloc only.
  AngleRelation(std::vector<std::pair<int, double>> terms, double constant, std::string kind)
      : terms_(std::move(terms)), constant_(constant), kind_(std::move(kind)) {}
  std::string kind() const override { return kind_; }
  int equations() const override { return 1; }
  std::vector<int> bodies() const override;
  void evaluate(const ConstraintInput& in, ConstraintOutput& out) const override;
  const std::vector<std::pair<int, double>>& terms() const { return terms_; }

 private:
  std::vector<std::pair<int, double>> terms_;
  double constant_;
  std::string kind_;
};

}  // namespace gearkit::kin
