#pragma once
// Checks and helpers shared by the element builders.
#include <gearkit/kin/element.hpp>
#include <gearkit/kin/model.hpp>

#include <string>

namespace gearkit::elements {

/// Throws kin::ElementError(field) unless `body` is a body of `model` (or the ground, if allowed).
void check_body(const kin::Model& model, int body, const std::string& field, bool ground_allowed);

/// The drawn angle of a body (Body::angle_guess) [rad]; 0 for the ground.
double drawn_angle(const kin::Model& model, int body);

/// Adds `constraint` as `name`, the common tail of the add_* functions.
int add_element(kin::Model& model, std::string name, std::unique_ptr<kin::Constraint> constraint);

}  // namespace gearkit::elements
