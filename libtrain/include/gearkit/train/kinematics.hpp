#pragma once
// Speeds of a train: all Willis equations in one exact linear system, plus the conditions a user
// imposes (members held fixed, members coupled together, input speeds). Speeds come out as exact
// rational multiples of the input speeds, so a ratio is a fraction (47/72), not a float.
#include <gearkit/train/model.hpp>
#include <gearkit/train/rational.hpp>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace gearkit::train {

/// What the train itself allows, before any condition.
struct Structure {
  std::size_t dof = 0;                    ///< members (without ground) minus the rank of the Willis equations
  std::vector<MemberId> independent;      ///< one choice of members whose speeds can be given freely
  std::vector<MemberId> locked;           ///< members that cannot turn (speed zero whatever happens)
  std::vector<MeshId> redundant_meshes;   ///< meshes whose equation follows from the others
};

/// Degrees of freedom and independent members. Planets are never chosen as independent when
/// another choice exists; among the others, the members declared first are preferred.
Structure analyse_structure(const TrainModel& model);

struct Condition {
  enum class Kind { fix, couple, input };
  Kind kind = Kind::fix;
  MemberId member = ground;
  MemberId other = ground;  ///< the second member of a coupling
  std::string label;        ///< how the user wrote it ("--fix ring"), for messages
};

/// A condition that contradicts the train and the conditions before it.
class ConditionError : public std::runtime_error {
 public:
  ConditionError(std::size_t index, const std::string& message);
  ~ConditionError() override;
  std::size_t index() const { return index_; }  ///< position in the condition list

 private:
  std::size_t index_;
};

/// A member's speed: w = sum_i per_input[i] * (speed of input i), exact. Undetermined when the
/// conditions leave it free.
struct MemberSpeed {
  bool determined = false;
  std::vector<Rational> per_input;
};

/// Speeds under conditions. The train's own freedom (before conditions) is analyse_structure()'s.
struct SpeedSolution {
  std::size_t remaining_dof = 0;           ///< freedom left after the conditions (0 = fully determined)
  std::vector<MemberId> free_members;      ///< members left free by the conditions
  std::vector<std::size_t> redundant_conditions;  ///< conditions already implied by the others
  std::vector<std::size_t> inputs;         ///< index (in the condition list) of each input, in order
  std::vector<MemberSpeed> speeds;         ///< per member
};

/// Solves the speeds for the given conditions (inputs are the parameters, in the order given).
/// @throws ConditionError if a condition contradicts the train and the conditions before it
///   (an input speed on a member the others already fix, a coupling that locks an input).
/// @throws std::invalid_argument for a condition naming a member outside the model.
SpeedSolution solve_speeds(const TrainModel& model, const std::vector<Condition>& conditions);

/// w_numerator / w_denominator, exact, when both are determined, there is exactly one input and
/// w_denominator is not identically zero; nullopt otherwise.
std::optional<Rational> speed_ratio(const SpeedSolution& solution, MemberId numerator, MemberId denominator);

/// A member's speed for input speeds `input_values` (any unit; the result is in the same unit).
/// @throws std::invalid_argument if the speed is undetermined or the value count is wrong.
double speed_value(const SpeedSolution& solution, MemberId member, const std::vector<double>& input_values);

/// One line of the --modes table: the input-output ratio with one more member held fixed, or two
/// more members coupled ("w_b = w_45"), on top of the base conditions.
struct TransmissionMode {
  std::string label;                  ///< "w_b = 0", "w_b = w_45"
  enum class Status { determined, underdetermined, contradictory } status = Status::determined;
  std::optional<Rational> ratio;      ///< w_output / w_input
  std::string message;                ///< why there is no ratio
};

/// Ratio w_output / w_input with each other non-planet member held fixed in turn, then with each
/// pair of them coupled (the seed's "w_b = 0, w_45 = 0, w_b = w_45"). Only the couplings of
/// `base` are kept (they are links of the machine, like "w_5 = w_1"); its fixes and inputs are
/// what the modes replace, so they are ignored. When the train with those couplings has more
/// than two degrees of freedom every mode leaves it free: a single entry then says so.
std::vector<TransmissionMode> transmission_modes(const TrainModel& model, const std::vector<Condition>& base,
                                                 MemberId input, MemberId output);

}  // namespace gearkit::train
