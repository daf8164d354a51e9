#include <gearkit/kin/model.hpp>

#include <stdexcept>

namespace gearkit::kin {

std::optional<Eigen::Vector2d> Body::point(const std::string& point_name) const {
  for (const auto& [name, local] : points)
    if (name == point_name) return local;
  return std::nullopt;
}

int Model::add_body(Body body) {
  if (body.name == ground_.name || body_index(body.name))
    throw std::invalid_argument("duplicate body name '" + body.name + "'");
  body_by_name_.emplace(body.name, static_cast<int>(bodies_.size()));
  bodies_.push_back(std::move(body));
  ++revision_;
  return static_cast<int>(bodies_.size()) - 1;
}

int Model::add_constraint(std::string name, std::shared_ptr<const Constraint> constraint) {
  if (!constraint) throw std::invalid_argument("constraint '" + name + "' is empty");
  if (constraint_index(name)) throw std::invalid_argument("duplicate constraint name '" + name + "'");
  for (int b : constraint->bodies())
    if (b != kGround && (b < 0 || b >= static_cast<int>(bodies_.size())))
      throw std::invalid_argument("constraint '" + name + "' names body index " + std::to_string(b) +
                                  " of a model with " + std::to_string(bodies_.size()) + " bodies");
  const int rows = constraint->equations();
  const bool driver = constraint->is_driver();
  constraint_by_name_.emplace(name, static_cast<int>(constraints_.size()));
  std::vector<int> bodies = constraint->bodies();
  constraints_.push_back({std::move(name), std::move(constraint), equations_, std::move(bodies)});
  equations_ += rows;
  const int index = static_cast<int>(constraints_.size()) - 1;
  if (driver) drivers_.push_back({index, DriverQuantity::angle, 0.0, std::nullopt});
  ++revision_;
  return index;
}

void Model::set_driver(int constraint, DriverQuantity quantity, double value) {
  for (Driver& d : drivers_)
    if (d.constraint == constraint) {
      d.quantity = quantity;
      d.value = value;
      ++revision_;
      return;
    }
  throw std::invalid_argument("constraint " + std::to_string(constraint) + " is not a driver");
}

void Model::add_friction(JointFriction friction) {
  if (friction.constraint < 0 || friction.constraint >= static_cast<int>(constraints_.size()))
    throw std::invalid_argument("friction names constraint " + std::to_string(friction.constraint) + " of " +
                                std::to_string(constraints_.size()));
  const ModelConstraint& c = constraints_[static_cast<std::size_t>(friction.constraint)];
  const std::string kind = c.constraint->kind();
  if (kind != "revolute" && kind != "prismatic" && kind != "pin_in_slot" && kind != "contact")
    throw std::invalid_argument("friction on '" + c.name + "' (" + kind +
                                "): only revolute, prismatic, pin_in_slot and contact joints take friction");
  for (const JointFriction& f : frictions_)
    if (f.constraint == friction.constraint) throw std::invalid_argument("joint '" + c.name + "' already has friction");
  if (!(friction.mu >= 0.0)) throw std::invalid_argument("friction coefficient of '" + c.name + "' must be >= 0");
  if (kind == "revolute" && !(friction.radius > 0.0))
    throw std::invalid_argument("friction in revolute '" + c.name + "' needs a journal radius > 0");
  if (!(friction.length >= 0.0)) throw std::invalid_argument("bearing length of '" + c.name + "' must be >= 0");
  frictions_.push_back(friction);
}

void Model::set_driver_effort(int driver, double effort) {
  if (driver < 0 || driver >= static_cast<int>(drivers_.size()))
    throw std::invalid_argument("driver " + std::to_string(driver) + " out of range");
  drivers_[static_cast<std::size_t>(driver)].effort = effort;
}

std::optional<int> Model::body_index(const std::string& name) const {
  if (name == ground_.name) return kGround;
  const auto found = body_by_name_.find(name);
  if (found == body_by_name_.end()) return std::nullopt;
  return found->second;
}

const std::string& Model::body_name(int index) const {
  return index == kGround ? ground_.name : bodies_.at(static_cast<std::size_t>(index)).name;
}

std::optional<int> Model::constraint_index(const std::string& name) const {
  const auto found = constraint_by_name_.find(name);
  if (found == constraint_by_name_.end()) return std::nullopt;
  return found->second;
}

Eigen::Vector2d Model::point_position(const Eigen::VectorXd& q, const BodyPoint& p) {
  if (p.body == kGround) return p.local;
  const int k = 3 * p.body;
  return Eigen::Vector2d(q(k), q(k + 1)) + rotate(q(k + 2), p.local);
}

bool Model::has_loads() const {
  if (!forces_.empty() || !torques_.empty() || !springs_.empty() || !frictions_.empty()) return true;
  for (const Body& b : bodies_)
    if (b.mass > 0.0 || b.inertia > 0.0) return true;
  return false;
}

}  // namespace gearkit::kin
