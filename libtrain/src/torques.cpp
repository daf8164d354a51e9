#include <gearkit/train/linear_system.hpp>
#include <gearkit/train/torques.hpp>
#include <gearkit/train/willis.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>

namespace gearkit::train {

namespace {

struct MeshTorqueCoefficients {
  Rational on_a, on_b, on_carrier;
};

MeshTorqueCoefficients mesh_coefficients(const TrainModel& model, MeshId k, MeshDriver driver) {
  const WillisCoefficients w = willis_coefficients(model, k);
  MeshTorqueCoefficients c{Rational(w.on_a), Rational(w.on_b), Rational(0)};
  if (driver != MeshDriver::none) {
    const Rational eta = rational_from_double(model.mesh(k).efficiency);
    if (driver == MeshDriver::gear_a) c.on_b *= eta;  // gear b receives the power
    else c.on_a *= eta;
  }
  c.on_carrier = -(c.on_a + c.on_b);
  return c;
}

// One unknown of the torque system: a mesh multiplier, a condition's reaction or the load.
struct Unknown {
  enum class Kind { mesh, condition, output } kind;
  std::size_t index;  // mesh or condition index
};

}  // namespace

std::pair<Rational, Rational> mesh_gear_torques(const TrainModel& model, MeshId mesh, const Rational& multiplier,
                                                MeshDriver driver) {
  const MeshTorqueCoefficients c = mesh_coefficients(model, mesh, driver);
  return {multiplier * c.on_a, multiplier * c.on_b};
}

namespace {

/// The condition whose unknown the given torque replaces: the given torque acts on the same
/// member as the load, an input's torque or a fixed member's reaction.
std::optional<std::size_t> replaced_condition(const std::vector<Condition>& conditions, MemberId output,
                                              MemberId given_member) {
  if (given_member == output) return std::nullopt;
  for (std::size_t j = 0; j < conditions.size(); ++j)
    if (conditions[j].kind == Condition::Kind::input && conditions[j].member == given_member) return j;
  for (std::size_t j = 0; j < conditions.size(); ++j)
    if (conditions[j].kind == Condition::Kind::fix && conditions[j].member == given_member) return j;
  return std::nullopt;
}

/// The columns of the torque system: mesh multipliers, then the conditions' reactions, then the
/// load, then the given torque (the one parameter).
struct TorqueColumns {
  std::vector<Unknown> unknowns;
  std::vector<long long> preference;
  std::vector<std::optional<std::size_t>> of_condition;
  std::optional<std::size_t> output;
  std::size_t given = 0;
};

TorqueColumns torque_columns(std::size_t meshes, const std::vector<Condition>& conditions, MemberId output,
                             MemberId given_member) {
  const std::optional<std::size_t> replaced = replaced_condition(conditions, output, given_member);
  TorqueColumns columns;
  for (MeshId k = 0; k < meshes; ++k) {
    columns.unknowns.push_back({Unknown::Kind::mesh, k});
    columns.preference.push_back(static_cast<long long>(k));
  }
  columns.of_condition.resize(conditions.size());
  for (std::size_t j = 0; j < conditions.size(); ++j) {
    if (replaced && *replaced == j) continue;
    columns.of_condition[j] = columns.unknowns.size();
    columns.unknowns.push_back({Unknown::Kind::condition, j});
    columns.preference.push_back(1000000 + static_cast<long long>(j));
  }
  if (given_member != output) {
    columns.output = columns.unknowns.size();
    columns.unknowns.push_back({Unknown::Kind::output, 0});
    columns.preference.push_back(2000000);
  }
  columns.given = columns.unknowns.size();
  return columns;
}

/// Member equilibrium rows: sum of mesh torques + external torques = 0, one per member.
std::vector<std::map<std::size_t, Rational>> equilibrium_rows(const TrainModel& model,
                                                              const std::vector<Condition>& conditions,
                                                              const TorqueColumns& columns, MemberId output,
                                                              MemberId given_member,
                                                              const std::vector<MeshDriver>& drivers) {
  std::vector<std::map<std::size_t, Rational>> rows(model.member_count());
  for (MeshId k = 0; k < model.meshes().size(); ++k) {
    const Mesh& mesh = model.mesh(k);
    const MeshTorqueCoefficients c = mesh_coefficients(model, k, drivers.empty() ? MeshDriver::none : drivers[k]);
    rows[model.gear(mesh.gear_a).member][k] += c.on_a;
    rows[model.gear(mesh.gear_b).member][k] += c.on_b;
    rows[mesh.carrier][k] += c.on_carrier;
  }
  for (std::size_t j = 0; j < conditions.size(); ++j) {
    const Condition& c = conditions[j];
    if (!columns.of_condition[j]) continue;
    rows.at(c.member)[*columns.of_condition[j]] += 1;
    if (c.kind == Condition::Kind::couple) rows.at(c.other)[*columns.of_condition[j]] -= 1;
  }
  if (columns.output) rows[output][*columns.output] += 1;
  rows[given_member][columns.given] += 1;
  return rows;
}

/// The external torques, couplings and the frame's reaction from the solved columns.
void fill_external_torques(TorqueSolution& solution, const std::vector<Condition>& conditions,
                           const TorqueColumns& columns, const std::map<std::size_t, Rational>& ground_row,
                           MemberId output, MemberId given_member,
                           const std::function<std::optional<Rational>(std::size_t)>& value_of) {
  solution.external[given_member] = Rational(1);
  const auto add = [&](MemberId m, const std::optional<Rational>& v, int sign) {
    auto& slot = solution.external[m];
    if (!slot) return;
    if (!v) slot.reset();
    else *slot += sign * *v;
  };
  solution.coupling.resize(conditions.size());
  for (std::size_t j = 0; j < conditions.size(); ++j) {
    if (!columns.of_condition[j]) continue;
    const auto v = value_of(*columns.of_condition[j]);
    if (conditions[j].kind == Condition::Kind::couple) solution.coupling[j] = v;  // internal to the machine
    else add(conditions[j].member, v, +1);
  }
  if (columns.output) add(output, value_of(*columns.output), +1);
  // The frame: the reaction of gears fixed to it (its equilibrium row was not imposed).
  std::optional<Rational> frame = Rational(0);
  for (const auto& [column, value] : ground_row) {
    const auto v = value_of(column);
    if (!v) {
      frame.reset();
      break;
    }
    *frame -= value * *v;
  }
  solution.external[ground] = frame;
}

}  // namespace

TorqueSolution solve_torques(const TrainModel& model, const std::vector<Condition>& conditions, MemberId output,
                             MemberId given_member, const std::vector<MeshDriver>& drivers) {
  const std::size_t n = model.member_count();
  const std::size_t meshes = model.meshes().size();
  if (output == ground || output >= n) throw std::invalid_argument("solve_torques: output must be a member other than ground");
  if (given_member == ground || given_member >= n)
    throw std::invalid_argument("solve_torques: the given torque must act on a member other than ground");
  if (!drivers.empty() && drivers.size() != meshes) throw std::invalid_argument("solve_torques: one driver per mesh");

  const TorqueColumns columns = torque_columns(meshes, conditions, output, given_member);
  const auto rows = equilibrium_rows(model, conditions, columns, output, given_member, drivers);
  TorqueSolution solution;
  EchelonSystem system(columns.unknowns.size(), 1, columns.preference);
  for (MemberId m = n; m-- > 1;) {  // last declared first: the stages of a chain stay local
    SparseRow row;
    for (const auto& [column, value] : rows[m])
      if (value != 0) row.emplace_back(column, value);
    if (system.add_row(row).status == EchelonSystem::RowStatus::inconsistent) {
      solution.balanced = false;
      solution.message = fmt::format(
          "member '{}' cannot be held in equilibrium: no fixed member, coupling or load path balances the given torque "
          "there", model.member(m).name);
      return solution;
    }
  }
  solution.balanced = true;
  const std::vector<SparseRow> expressions = system.solve();
  const auto value_of = [&](std::size_t column) -> std::optional<Rational> {
    Rational v(0);
    for (const auto& [c, coefficient] : expressions[column]) {
      if (c != columns.given) return std::nullopt;
      v = coefficient;
    }
    return v;
  };
  solution.mesh_multiplier.resize(meshes);
  for (MeshId k = 0; k < meshes; ++k) solution.mesh_multiplier[k] = value_of(k);
  solution.external.assign(n, Rational(0));
  fill_external_torques(solution, conditions, columns, rows[ground], output, given_member, value_of);
  return solution;
}

namespace {

std::vector<MeshDriver> drivers_from(const TrainModel& model, const TorqueSolution& torques,
                                     const std::vector<double>& w, double given, const std::vector<MeshDriver>& current) {
  std::vector<MeshDriver> drivers(model.meshes().size(), MeshDriver::none);
  double scale = 0;
  for (double v : w) scale = std::max(scale, std::fabs(v));
  for (MeshId k = 0; k < model.meshes().size(); ++k) {
    if (!torques.mesh_multiplier[k]) continue;
    const Mesh& mesh = model.mesh(k);
    const MeshDriver used = current.empty() ? MeshDriver::none : current[k];
    const auto [t_a, t_b] = mesh_gear_torques(model, k, *torques.mesh_multiplier[k], used);
    (void)t_b;
    const double relative = w[model.gear(mesh.gear_a).member] - w[mesh.carrier];
    const double power_into_a = to_double(t_a) * given * relative;
    const double tiny = 1e-12 * std::fabs(to_double(t_a) * given) * std::max(scale, 1e-300);
    if (power_into_a < -tiny) drivers[k] = MeshDriver::gear_a;
    else if (power_into_a > tiny) drivers[k] = MeshDriver::gear_b;
  }
  return drivers;
}

}  // namespace

namespace {

/// The torques with losses: the power direction of each mesh from the ideal torques, checked
/// again with the losses until it no longer changes (a change that persists is near self-locking).
TorqueSolution lossy_torques(const TrainModel& model, const std::vector<Condition>& conditions, MemberId output,
                             MemberId given_member, const TorqueSolution& ideal, const std::vector<double>& w,
                             double given_torque_Nm, PowerFlow& flow) {
  flow.drivers = drivers_from(model, ideal, w, given_torque_Nm, {});
  TorqueSolution lossy = solve_torques(model, conditions, output, given_member, flow.drivers);
  for (int iteration = 0; lossy.balanced; ++iteration) {
    const std::vector<MeshDriver> again = drivers_from(model, lossy, w, given_torque_Nm, flow.drivers);
    if (again == flow.drivers) break;
    if (iteration == 4) {
      flow.warnings.push_back("the power direction of some mesh changes once losses are counted (near self-locking); "
                              "torques with losses are uncertain");
      break;
    }
    flow.drivers = again;
    lossy = solve_torques(model, conditions, output, given_member, flow.drivers);
  }
  return lossy;
}

/// Torques and powers of every member and coupling, ideal and with losses, in SI.
void fill_torques_and_powers(PowerFlow& flow, const std::vector<Condition>& conditions, const TorqueSolution& ideal,
                             const TorqueSolution& lossy, const std::vector<double>& w, double given_torque_Nm) {
  const std::size_t n = w.size();
  const auto scaled = [&](const std::optional<Rational>& r) -> std::optional<double> {
    if (!r) return std::nullopt;
    return to_double(*r) * given_torque_Nm;
  };
  flow.coupling_ideal_Nm.resize(conditions.size());
  flow.coupling_losses_Nm.resize(conditions.size());
  for (std::size_t j = 0; j < conditions.size(); ++j) {
    flow.coupling_ideal_Nm[j] = scaled(ideal.coupling[j]);
    if (lossy.balanced) flow.coupling_losses_Nm[j] = scaled(lossy.coupling[j]);
  }
  flow.torque_ideal_Nm.resize(n);
  flow.torque_losses_Nm.resize(n);
  flow.power_ideal_W.resize(n);
  flow.power_losses_W.resize(n);
  for (MemberId m = 0; m < n; ++m) {
    flow.torque_ideal_Nm[m] = scaled(ideal.external[m]);
    if (lossy.balanced) flow.torque_losses_Nm[m] = scaled(lossy.external[m]);
    if (m == ground) continue;
    if (flow.torque_ideal_Nm[m]) flow.power_ideal_W[m] = *flow.torque_ideal_Nm[m] * w[m];
    if (flow.torque_losses_Nm[m]) flow.power_losses_W[m] = *flow.torque_losses_Nm[m] * w[m];
    if (flow.power_ideal_W[m] && *flow.power_ideal_W[m] > 0) flow.input_power_W += *flow.power_ideal_W[m];
  }
}

/// Efficiency between the first input and the output, with its warnings (self-locking, back-driven).
void add_efficiency(PowerFlow& flow, const TrainModel& model, const std::vector<Condition>& conditions,
                    const SpeedSolution& speeds, const TorqueSolution& lossy, MemberId output) {
  std::optional<MemberId> input;
  for (const Condition& c : conditions)
    if (c.kind == Condition::Kind::input) {
      input = c.member;
      break;
    }
  if (!input || !lossy.balanced || !flow.power_losses_W[*input] || !flow.power_losses_W[output]) return;
  const double p_in = *flow.power_losses_W[*input];
  if (p_in > 0) {
    flow.efficiency = -*flow.power_losses_W[output] / p_in;
    // With losses the output takes power in too: no torque at the input alone moves the train
    // this way (a back-driven Wolfrom train with a low eta_0 locks).
    if (*flow.efficiency <= 0)
      flow.warnings.push_back(fmt::format(
          "self-locking: with the mesh losses the input '{}' cannot drive the output '{}' (efficiency {:.4f} <= 0: "
          "the load would have to drive the train as well)",
          model.member(*input).name, model.member(output).name, *flow.efficiency));
  } else {
    flow.warnings.push_back(fmt::format("the input '{}' receives power instead of giving it (back-driven)",
                                        model.member(*input).name));
  }
  const auto exact_in = speed_ratio(speeds, *input, *input);
  const auto exact_out = speed_ratio(speeds, output, *input);
  if (flow.efficiency && exact_in && exact_out && lossy.external[*input] && lossy.external[output] &&
      *lossy.external[*input] != 0)
    flow.efficiency_exact = Rational(-(*lossy.external[output] * *exact_out) / (*lossy.external[*input] * *exact_in));
}

/// Power circulation: a member (through its meshes) or a coupling carrying more power than
/// enters the train.
void find_power_circulation(PowerFlow& flow, const TrainModel& model, const std::vector<Condition>& conditions,
                            const TorqueSolution& ideal, const std::vector<double>& w, double given_torque_Nm) {
  const std::size_t n = model.member_count();
  std::vector<double> through(n, 0.0);
  for (MeshId k = 0; k < model.meshes().size(); ++k) {
    if (!ideal.mesh_multiplier[k]) continue;
    const Mesh& mesh = model.mesh(k);
    const MeshTorqueCoefficients c = mesh_coefficients(model, k, MeshDriver::none);
    std::map<MemberId, Rational> on;
    on[model.gear(mesh.gear_a).member] += c.on_a;
    on[model.gear(mesh.gear_b).member] += c.on_b;
    on[mesh.carrier] += c.on_carrier;
    for (const auto& [m, coefficient] : on) {
      if (m == ground) continue;
      const double p = to_double(coefficient * *ideal.mesh_multiplier[k]) * given_torque_Nm * w[m];
      if (p > 0) through[m] += p;
    }
  }
  for (MemberId m = 1; m < n; ++m)
    if (through[m] > flow.max_through_power_W) {
      flow.max_through_power_W = through[m];
      flow.max_through_power_at = "member '" + model.member(m).name + "'";
    }
  for (std::size_t j = 0; j < conditions.size(); ++j) {
    if (!ideal.coupling[j]) continue;
    const double p = std::fabs(to_double(*ideal.coupling[j]) * given_torque_Nm * w[conditions[j].member]);
    if (p > flow.max_through_power_W) {
      flow.max_through_power_W = p;
      flow.max_through_power_at = "coupling '" + conditions[j].label + "'";
    }
  }
  if (flow.input_power_W > 0 && flow.max_through_power_W > flow.input_power_W * (1 + 1e-9)) {
    flow.power_circulation = true;
    flow.warnings.push_back(fmt::format("power circulation: {} carries {:.4g} times the input power",
                                        flow.max_through_power_at, flow.max_through_power_W / flow.input_power_W));
  }
}

}  // namespace

PowerFlow analyse_power_flow(const TrainModel& model, const std::vector<Condition>& conditions,
                             const SpeedSolution& speeds, const std::vector<double>& input_speeds_rad_s,
                             MemberId output, MemberId given_member, double given_torque_Nm) {
  const std::size_t n = model.member_count();
  std::vector<double> w(n);
  for (MemberId m = 0; m < n; ++m) w[m] = speed_value(speeds, m, input_speeds_rad_s);

  PowerFlow flow;
  const TorqueSolution ideal = solve_torques(model, conditions, output, given_member);
  if (!ideal.balanced) {
    flow.warnings.push_back(ideal.message);
    return flow;
  }
  const TorqueSolution lossy = lossy_torques(model, conditions, output, given_member, ideal, w, given_torque_Nm, flow);
  fill_torques_and_powers(flow, conditions, ideal, lossy, w, given_torque_Nm);
  add_efficiency(flow, model, conditions, speeds, lossy, output);
  find_power_circulation(flow, model, conditions, ideal, w, given_torque_Nm);
  return flow;
}

}  // namespace gearkit::train
