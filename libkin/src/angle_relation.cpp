#include <gearkit/kin/angle_relation.hpp>

namespace gearkit::kin {

std::vector<int> AngleRelation::bodies() const {
  std::vector<int> b;
  for (const auto& [body, c] : terms_) b.push_back(body);
  return b;
}

void AngleRelation::evaluate(const ConstraintInput& in, ConstraintOutput& out) const {
  double sum = -constant_;
  out.phi_q.setZero();
  for (std::size_t k = 0; k < terms_.size(); ++k) {
    sum += terms_[k].second * in.bodies[k].theta;
    out.phi_q(0, 3 * static_cast<int>(k) + 2) = terms_[k].second;
  }
  out.phi(0) = sum;
  out.phi_t(0) = 0.0;
  out.gamma(0) = 0.0;  // linear in q: no velocity terms
}

}  // namespace gearkit::kin
