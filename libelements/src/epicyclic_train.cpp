#include <gearkit/elements/epicyclic_train.hpp>

#include "checks.hpp"

#include <gearkit/kin/angle_relation.hpp>

#include <fmt/format.h>

namespace gearkit::elements {

namespace {

class EpicyclicTrain final : public kin::Constraint {
 public:
  EpicyclicTrain(const EpicyclicTrainParameters& p, double tau0, double phase)
      : tau0_(tau0), relation_({{p.output, 1.0}, {p.input, -tau0}, {p.arm, tau0 - 1.0}}, phase, "epicyclic_train") {
    // The chain starts at the input's gear and ends at the output's.
    drawing_.central = {{p.input, p.driving.front()}, {p.output, p.driven.back()}};
    drawing_.arm = p.arm;
  }
  std::string kind() const override { return "epicyclic_train"; }
  int equations() const override { return 1; }
  std::vector<int> bodies() const override { return relation_.bodies(); }
  kin::ConstraintDrawing drawing() const override { return drawing_; }
  void evaluate(const kin::ConstraintInput& in, kin::ConstraintOutput& out) const override {
    relation_.evaluate(in, out);
  }
  kin::Reaction reaction(const kin::ConstraintInput&, std::span<const double> lambda) const override {
    const double l = lambda[0];
    kin::Reaction r;
    r.moment = -l;  // the first body is the output
    r.values.push_back({"T_out", "N m", -l, "torque on the output member from the train"});
    r.values.push_back({"T_in", "N m", tau0_ * l, "torque on the input member from the train"});
    r.values.push_back({"T_arm", "N m", (1.0 - tau0_) * l, "torque on the arm from the train"});
    return r;
  }

 private:
  double tau0_;
  kin::AngleRelation relation_;
  kin::ConstraintDrawing drawing_;
};

double tooth_product(const std::vector<int>& teeth, const std::string& field) {
  if (teeth.empty()) throw kin::ElementError(field, fmt::format("'{}': expected a list of tooth numbers, found none", field));
  double product = 1.0;
  for (int z : teeth) {
    if (z < 1) throw kin::ElementError(field, fmt::format("'{}': expected numbers of teeth >= 1, found {}", field, z));
    product *= z;
  }
  return product;
}

void check_parameters(const kin::Model& model, const EpicyclicTrainParameters& p) {
  check_body(model, p.input, "input", true);
  check_body(model, p.output, "output", true);
  check_body(model, p.arm, "arm", true);
  if (p.input == p.output || p.input == p.arm || p.output == p.arm)
    throw kin::ElementError("arm", "expected input, output and arm to be three different links");
  if (p.externals < 0)
    throw kin::ElementError("externals", fmt::format("'externals': expected the number of external meshes >= 0, "
                                                     "found {}", p.externals));
}

}  // namespace

double basic_ratio(const EpicyclicTrainParameters& p) {
  return (p.externals % 2 ? -1.0 : 1.0) * tooth_product(p.driving, "driving") / tooth_product(p.driven, "driven");
}

std::unique_ptr<kin::Constraint> make_epicyclic_train(const kin::Model& model, const EpicyclicTrainParameters& p) {
  check_parameters(model, p);
  const double tau0 = basic_ratio(p);
  const auto drawn = [&](int body) { return drawn_angle(model, body) - drawn_angle(model, p.arm); };
  const double phase = p.phase.value_or(drawn(p.output) - tau0 * drawn(p.input));
  return std::make_unique<EpicyclicTrain>(p, tau0, phase);
}

int add_epicyclic_train(kin::Model& model, std::string name, const EpicyclicTrainParameters& p) {
  return add_element(model, std::move(name), make_epicyclic_train(model, p));
}

}  // namespace gearkit::elements
