#include "checks.hpp"

#include <fmt/format.h>

namespace gearkit::elements {

void check_body(const kin::Model& model, int body, const std::string& field, bool ground_allowed) {
  const int bodies = static_cast<int>(model.bodies().size());
  if (body == kin::kGround && ground_allowed) return;
  if (body < 0 || body >= bodies)
    throw kin::ElementError(field, fmt::format("'{}': expected a {}body of the model (0 to {}), found {}", field,
                                               ground_allowed ? "moving body or the ground, " : "moving ",
                                               bodies - 1, body == kin::kGround ? std::string("the ground")
                                                                                : std::to_string(body)));
}

double drawn_angle(const kin::Model& model, int body) {
  return body == kin::kGround ? 0.0 : model.bodies()[static_cast<std::size_t>(body)].angle_guess;
}

int add_element(kin::Model& model, std::string name, std::unique_ptr<kin::Constraint> constraint) {
  return model.add_constraint(std::move(name), std::shared_ptr<const kin::Constraint>(std::move(constraint)));
}

}  // namespace gearkit::elements
