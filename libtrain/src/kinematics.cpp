#include <gearkit/train/kinematics.hpp>
#include <gearkit/train/linear_system.hpp>
#include <gearkit/train/willis.hpp>

#include <fmt/format.h>

namespace gearkit::train {

ConditionError::ConditionError(std::size_t index, const std::string& message)
    : std::runtime_error(message), index_(index) {}
ConditionError::~ConditionError() = default;

namespace {

// Planets are eliminated first (never left as the free ones); then later-declared members before
// earlier ones, so that the members declared first (usually the input shafts) stay independent.
std::vector<long long> speed_preference(const TrainModel& model) {
  const auto n = static_cast<long long>(model.member_count());
  std::vector<long long> preference(model.member_count());
  for (MemberId m = 0; m < model.member_count(); ++m)
    preference[m] = (model.is_planet(m) ? n : 0) + static_cast<long long>(m);
  return preference;
}

SparseRow to_sparse(const std::vector<std::pair<MemberId, long long>>& row) {
  SparseRow sparse;
  for (const auto& [member, coefficient] : row) sparse.emplace_back(member, Rational(coefficient));
  return sparse;
}

// The structural system: w_ground = 0 and one Willis row per mesh. Meshes go in from the last:
// in a chain of stages declared input-first, each new row then pivots on a member no earlier row
// depends on, so elimination adds no fill-in (a 100-stage train stays as cheap as a 2-stage one).
EchelonSystem structural_system(const TrainModel& model, std::size_t parameters, std::vector<MeshId>* redundant) {
  EchelonSystem system(model.member_count(), parameters, speed_preference(model));
  system.add_row(SparseRow{{ground, Rational(1)}});
  for (MeshId k = model.meshes().size(); k-- > 0;) {
    const auto result = system.add_row(to_sparse(willis_row(model, k)));
    if (result.status != EchelonSystem::RowStatus::independent && redundant) redundant->insert(redundant->begin(), k);
  }
  return system;
}

Structure structure_of(const TrainModel& model, const EchelonSystem& system,
                       const std::vector<SparseRow>& expressions, std::vector<MeshId> redundant) {
  Structure s;
  s.independent = system.free_unknowns();
  s.dof = s.independent.size();
  for (MemberId m = 1; m < model.member_count(); ++m)
    if (expressions[m].empty()) s.locked.push_back(m);
  s.redundant_meshes = std::move(redundant);
  return s;
}

void check_member(const TrainModel& model, MemberId m) {
  if (m >= model.member_count()) throw std::invalid_argument("condition names a member outside the model");
}

}  // namespace

Structure analyse_structure(const TrainModel& model) {
  std::vector<MeshId> redundant;
  const EchelonSystem system = structural_system(model, 0, &redundant);
  return structure_of(model, system, system.solve(), std::move(redundant));
}

namespace {

SparseRow condition_row(const TrainModel& model, const Condition& c, std::size_t& input_index) {
  check_member(model, c.member);
  SparseRow row{{c.member, Rational(1)}};
  if (c.kind == Condition::Kind::couple) {
    check_member(model, c.other);
    row.emplace_back(c.other, Rational(-1));
  } else if (c.kind == Condition::Kind::input) {
    row.emplace_back(model.member_count() + input_index++, Rational(-1));
  }
  return row;
}

// Conditions first, then the meshes from the last: in a chain of stages each mesh row then meets
// only its neighbours' pivots, so the work grows linearly with the number of stages. Returns
// nullopt when some row is not independent; the caller then redoes the elimination in the order
// that tells which condition is redundant or contradictory.
std::optional<EchelonSystem> conditions_first(const TrainModel& model, const std::vector<Condition>& conditions,
                                              std::size_t inputs) {
  EchelonSystem system(model.member_count(), inputs, speed_preference(model));
  const auto independent = [](const EchelonSystem::AddResult& r) {
    return r.status == EchelonSystem::RowStatus::independent;
  };
  if (!independent(system.add_row(SparseRow{{ground, Rational(1)}}))) return std::nullopt;
  std::size_t input_index = 0;
  for (const Condition& c : conditions)
    if (!independent(system.add_row(condition_row(model, c, input_index)))) return std::nullopt;
  for (MeshId k = model.meshes().size(); k-- > 0;)
    if (!independent(system.add_row(to_sparse(willis_row(model, k))))) return std::nullopt;
  return system;
}

// Structure first, then each condition in turn, so each is classified against the train and the
// conditions before it.
EchelonSystem conditions_last(const TrainModel& model, const std::vector<Condition>& conditions, std::size_t inputs,
                              SpeedSolution& solution) {
  EchelonSystem system = structural_system(model, inputs, nullptr);
  std::size_t input_index = 0;
  for (std::size_t i = 0; i < conditions.size(); ++i) {
    const Condition& c = conditions[i];
    const auto result = system.add_row(condition_row(model, c, input_index));
    if (result.status == EchelonSystem::RowStatus::redundant) {
      solution.redundant_conditions.push_back(i);
    } else if (result.status == EchelonSystem::RowStatus::inconsistent) {
      throw ConditionError(
          i, fmt::format("'{}' over-determines the train: with the Willis equations and the conditions before it, the "
                         "speed of '{}' is already fixed",
                         c.label, model.member(c.member).name));
    }
  }
  return system;
}

}  // namespace

SpeedSolution solve_speeds(const TrainModel& model, const std::vector<Condition>& conditions) {
  SpeedSolution solution;
  for (std::size_t i = 0; i < conditions.size(); ++i)
    if (conditions[i].kind == Condition::Kind::input) solution.inputs.push_back(i);
  const std::size_t n = model.member_count();

  std::optional<EchelonSystem> fast = conditions_first(model, conditions, solution.inputs.size());
  const EchelonSystem system =
      fast ? std::move(*fast) : conditions_last(model, conditions, solution.inputs.size(), solution);

  solution.free_members = system.free_unknowns();
  solution.remaining_dof = solution.free_members.size();
  std::vector<SparseRow> expressions = system.solve();
  solution.speeds.resize(n);
  for (MemberId m = 0; m < n; ++m) {
    MemberSpeed& speed = solution.speeds[m];
    speed.determined = true;
    speed.per_input.assign(solution.inputs.size(), Rational(0));
    for (auto& [column, value] : expressions[m]) {
      if (column < n) {
        speed.determined = false;
      } else {
        speed.per_input[column - n] = std::move(value);
      }
    }
    if (!speed.determined) speed.per_input.clear();
  }
  return solution;
}

std::optional<Rational> speed_ratio(const SpeedSolution& solution, MemberId numerator, MemberId denominator) {
  if (solution.inputs.size() != 1) return std::nullopt;
  const MemberSpeed& a = solution.speeds.at(numerator);
  const MemberSpeed& b = solution.speeds.at(denominator);
  if (!a.determined || !b.determined || b.per_input[0] == 0) return std::nullopt;
  return Rational(a.per_input[0] / b.per_input[0]);
}

double speed_value(const SpeedSolution& solution, MemberId member, const std::vector<double>& input_values) {
  const MemberSpeed& s = solution.speeds.at(member);
  if (!s.determined) throw std::invalid_argument("speed_value: the speed is not determined by the conditions");
  if (input_values.size() != s.per_input.size()) throw std::invalid_argument("speed_value: one value per input");
  double value = 0;
  for (std::size_t i = 0; i < input_values.size(); ++i) value += to_double(s.per_input[i]) * input_values[i];
  return value;
}

std::vector<TransmissionMode> transmission_modes(const TrainModel& model, const std::vector<Condition>& base,
                                                 MemberId input, MemberId output) {
  std::vector<Condition> kept;
  for (const Condition& c : base)
    if (c.kind == Condition::Kind::couple) kept.push_back(c);
  // With more than two degrees of freedom (with its couplings) one more condition and the input
  // leave the train free in every mode: say so once instead of for each of the n(n+1)/2 modes.
  std::size_t dof = 0;
  try {
    dof = solve_speeds(model, kept).remaining_dof;
  } catch (const ConditionError&) {
    dof = 0;
  }
  if (dof > 2) {
    TransmissionMode all;
    all.label = "any member held or pair coupled";
    all.status = TransmissionMode::Status::underdetermined;
    all.message = fmt::format("{} degree(s) of freedom left in every mode: the train (with its couplings) has {}, a "
                              "mode needs 2",
                              dof - 2, dof);
    return {all};
  }
  std::vector<MemberId> candidates;
  for (MemberId m = 1; m < model.member_count(); ++m)
    if (!model.is_planet(m) && m != input && m != output) candidates.push_back(m);

  const auto name = [&](MemberId m) { return "w_" + model.member(m).name; };
  std::vector<std::pair<std::string, Condition>> extra;
  for (MemberId m : candidates) extra.push_back({name(m) + " = 0", Condition{Condition::Kind::fix, m, ground, ""}});
  for (std::size_t i = 0; i < candidates.size(); ++i)
    for (std::size_t j = i + 1; j < candidates.size(); ++j)
      extra.push_back({name(candidates[i]) + " = " + name(candidates[j]),
                       Condition{Condition::Kind::couple, candidates[i], candidates[j], ""}});

  std::vector<TransmissionMode> modes;
  for (auto& [label, condition] : extra) {
    TransmissionMode mode;
    mode.label = label;
    std::vector<Condition> conditions = kept;
    condition.label = label;
    conditions.push_back(condition);
    conditions.push_back(Condition{Condition::Kind::input, input, ground, "input " + name(input)});
    try {
      const SpeedSolution s = solve_speeds(model, conditions);
      mode.ratio = speed_ratio(s, output, input);
      if (!mode.ratio) {
        mode.status = TransmissionMode::Status::underdetermined;
        mode.message = fmt::format("{} degree(s) of freedom left", s.remaining_dof);
      }
    } catch (const ConditionError&) {
      mode.status = TransmissionMode::Status::contradictory;
      mode.message = "locks the input";
    }
    modes.push_back(std::move(mode));
  }
  return modes;
}

}  // namespace gearkit::train
