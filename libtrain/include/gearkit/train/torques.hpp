#pragma once
// Torques on the members of a train in steady motion, by the Willis method.
//
// Each mesh k carries a multiplier mu_k: the torques it puts on gear a, gear b and the carrier are
// mu_k times (c_a, c_b, c_c), the coefficients of its Willis equation (willis.hpp). In the ideal
// case the mesh's power then vanishes for every motion the equation allows. With losses, the
// coefficient of the gear that RECEIVES power in the carrier's frame is multiplied by the basic
// efficiency eta_0 (and the carrier takes -(c_a' + c_b')), so the relative power leaving the
// mesh is eta_0 times the relative power entering it.
//
// External torques act where the user acts: on members held fixed (reactions), on coupled
// members (the coupling's internal torque), on the inputs and on the output (the load). Member
// equilibrium  T_ext(m) + sum_k mu_k c_k(m) = 0  for every member but ground gives an exact linear
// system; one torque is given (on `given_member`), all results are per unit of it.
// Sign convention: a torque is positive in the sense of positive speed; power = T w > 0 enters
// the train.
#include <gearkit/train/kinematics.hpp>
#include <gearkit/train/model.hpp>
#include <gearkit/train/rational.hpp>

#include <optional>
#include <string>
#include <vector>

namespace gearkit::train {

/// Which gear of a mesh gives power in the carrier's frame.
enum class MeshDriver { none, gear_a, gear_b };

struct TorqueSolution {
  bool balanced = false;  ///< false: no torques can hold the train in equilibrium (see `message`)
  std::string message;
  /// Torque applied to each member from outside the train (the given torque, the load, the
  /// reactions of held members, the torques that drive the inputs) per unit of the given torque;
  /// couplings are not included (see `coupling`). nullopt when statically indeterminate. The
  /// entry for ground is the couple the frame takes (bearings of fixed axes, gears on the frame).
  std::vector<std::optional<Rational>> external;
  std::vector<std::optional<Rational>> mesh_multiplier;  ///< mu_k per unit of the given torque
  /// The internal torque of each coupling condition (same index as the condition list): the
  /// torque it puts on `member` (and minus that on `other`). nullopt for other conditions.
  std::vector<std::optional<Rational>> coupling;
};

/// Solves the torques. `drivers` is empty for the ideal case, else one entry per mesh.
/// @throws std::invalid_argument if output or given_member is ground or outside the model, or
///   drivers has the wrong size.
TorqueSolution solve_torques(const TrainModel& model, const std::vector<Condition>& conditions, MemberId output,
                             MemberId given_member, const std::vector<MeshDriver>& drivers = {});

/// The torque mu * c on each gear of mesh k (for gear a and gear b), per unit of the given torque.
std::pair<Rational, Rational> mesh_gear_torques(const TrainModel& model, MeshId mesh, const Rational& multiplier,
                                                MeshDriver driver);

/// Result of the power-flow analysis, in SI units.
struct PowerFlow {
  std::vector<std::optional<double>> torque_ideal_Nm;   ///< per member, as TorqueSolution::external
  std::vector<std::optional<double>> torque_losses_Nm;  ///< with mesh efficiencies
  std::vector<std::optional<double>> coupling_ideal_Nm; ///< per condition: torque of each coupling on its first member
  std::vector<std::optional<double>> coupling_losses_Nm;
  std::vector<std::optional<double>> power_ideal_W;     ///< T w per member
  std::vector<std::optional<double>> power_losses_W;
  std::vector<MeshDriver> drivers;                      ///< power direction per mesh (carrier frame)
  std::optional<double> efficiency;                     ///< -P_out / P_in with losses
  std::optional<Rational> efficiency_exact;             ///< the same, exact, with a single input
  double input_power_W = 0;                             ///< power entering (ideal), sum of T w > 0
  double max_through_power_W = 0;                       ///< largest power carried by a member or coupling
  std::string max_through_power_at;                     ///< where
  bool power_circulation = false;                       ///< some member or coupling carries more than the input
  std::vector<std::string> warnings;
};

/// Torques for a given torque `given_torque_Nm` on `given_member`, speeds from `speeds` with
/// input speeds `input_speeds_rad_s` (one per input). The power direction of each mesh comes
/// from the ideal solution and is re-checked with losses (a mesh whose direction flips is
/// reported, e.g. near self-locking).
/// @throws std::invalid_argument as solve_torques, or if a speed is undetermined.
PowerFlow analyse_power_flow(const TrainModel& model, const std::vector<Condition>& conditions,
                             const SpeedSolution& speeds, const std::vector<double>& input_speeds_rad_s,
                             MemberId output, MemberId given_member, double given_torque_Nm);

}  // namespace gearkit::train
