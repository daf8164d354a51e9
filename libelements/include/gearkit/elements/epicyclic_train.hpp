#pragma once
// The epicyclic train element: Willis' equation between the two central members of a simple
// epicyclic train and its arm (carrier),
//     (theta_out - theta_arm) - tau0 (theta_in - theta_arm) = phase,
// where tau0 is the basic ratio omega_out/omega_in with the arm held, from the tooth numbers of
// the driving and driven gears along the chain and the number of external meshes:
//     tau0 = (-1)^externals prod(z_driving) / prod(z_driven).
// One equation; its multiplier lambda is the torque on the output member: T_out = -lambda,
// T_in = tau0 lambda, T_arm = (1 - tau0) lambda [N m] (they sum to zero).
#include <gearkit/kin/element.hpp>
#include <gearkit/kin/model.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace gearkit::elements {

struct EpicyclicTrainParameters {
  int input = kin::kGround;   ///< body of the input central member
  int output = kin::kGround;  ///< body of the output central member
  int arm = kin::kGround;     ///< body of the arm (carrier)
  std::vector<int> driving;   ///< teeth of the driving gears along the chain, each >= 1
  std::vector<int> driven;    ///< teeth of the driven gears, each >= 1
  int externals = 0;          ///< external meshes along the chain, >= 0
  /// [rad] the constant of the equation; nullopt: from the model's drawn angles.
  std::optional<double> phase;
};

/// The basic ratio tau0 = (-1)^externals prod(driving) / prod(driven).
double basic_ratio(const EpicyclicTrainParameters& p);

/// Builds Willis' equation between bodies of `model`.
/// @throws kin::ElementError (field "input", "output", "arm", "driving", "driven",
///         "externals") for a body index not in the model, the three bodies not all different,
///         an empty tooth list or a tooth number below 1, externals < 0.
/// Reaction values: T_in, T_out, T_arm [N m], the torques on the three members from the train.
/// drawing(): the central members, input with driving.front() teeth and output with
/// driven.back(), and the arm.
std::unique_ptr<kin::Constraint> make_epicyclic_train(const kin::Model& model, const EpicyclicTrainParameters& p);

/// make_epicyclic_train added to `model` as constraint `name`. @returns its index.
int add_epicyclic_train(kin::Model& model, std::string name, const EpicyclicTrainParameters& p);

}  // namespace gearkit::elements
