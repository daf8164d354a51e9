// Bindings of libtrain: a train file (plugins/train's reader, docs/train.md) under conditions
// (the file's `analysis:` or the arguments, parsed as `gearkit train` parses them), solved
// exactly: speeds per input as fraction strings ("47/72", made fractions.Fraction by the
// package), the ratio, and with a torque the power flow with the meshes' efficiencies.
#include "common.hpp"

#include "train_conditions.hpp"
#include "train_file.hpp"

#include <gearkit/io/error.hpp>
#include <gearkit/train/kinematics.hpp>
#include <gearkit/train/rational.hpp>
#include <gearkit/train/torques.hpp>

#include <fmt/format.h>
#include <pybind11/stl.h>

namespace gearkit::python {

namespace gt = gearkit::train;
namespace pt = gearkit::plugins::train;

namespace {

struct Conditions {
  std::vector<gt::Condition> list;
  std::vector<pt::ConditionFail> fails;  // per condition: reports at its argument or file mark
  std::vector<std::optional<double>> input_speeds_rad_s;
};

struct Arguments {
  std::vector<std::string> fix, couple, input;
  std::optional<std::string> output, torque;
};

pt::ConditionFail argument_fail(std::string name) {
  return [name](std::string_view message) { fail_argument(name, message); };
}

pt::ConditionFail mark_fail(io::SourceMark mark) {
  return [mark](std::string_view message) { io::fail_at(mark, message); };
}

void add_condition(const gt::TrainModel& model, Conditions& c, const std::string& kind, const std::string& text,
                   const pt::ConditionFail& fail, bool typed) {
  if (kind == "fix") {
    c.list.push_back(pt::parse_fix(model, text, fail));
  } else if (kind == "couple") {
    c.list.push_back(pt::parse_couple(model, text, fail));
  } else {
    pt::ParsedInput in = pt::parse_input(model, text, fail, typed);
    c.list.push_back(in.condition);
    c.input_speeds_rad_s.push_back(in.speed_rad_s);
  }
  c.fails.push_back(fail);
}

// The arguments' conditions, or the file's when no argument gives one (as the CLI's options).
Conditions gather(const gt::TrainModel& model, const Arguments& a, const pt::FileAnalysis& file) {
  Conditions c;
  if (!a.fix.empty() || !a.couple.empty() || !a.input.empty()) {
    for (const auto& [kind, texts] : {std::pair{"fix", &a.fix}, std::pair{"couple", &a.couple}, std::pair{"input", &a.input}})
      for (const std::string& t : *texts) add_condition(model, c, kind, t, argument_fail(kind), true);
  } else {
    for (const auto& [kind, written] : {std::pair{"fix", &file.fix}, std::pair{"couple", &file.couple}, std::pair{"input", &file.input}})
      for (const pt::WrittenCondition& w : *written) add_condition(model, c, kind, w.text, mark_fail(w.mark), false);
  }
  std::size_t with_speed = 0;
  for (const auto& s : c.input_speeds_rad_s) with_speed += s.has_value();
  if (with_speed != 0 && with_speed != c.input_speeds_rad_s.size())
    for (std::size_t i = 0, k = 0; i < c.list.size(); ++i)
      if (c.list[i].kind == gt::Condition::Kind::input && !c.input_speeds_rad_s[k++])
        c.fails[i]("expected a speed for every input (MEMBER=SPEED) or for none");
  return c;
}

std::optional<gt::MemberId> output_member(const gt::TrainModel& model, const Arguments& a, const pt::FileAnalysis& file) {
  std::optional<gt::MemberId> output;
  if (a.output) output = pt::parse_member(model, *a.output, argument_fail("output"));
  else if (file.output) output = pt::parse_member(model, file.output->text, mark_fail(file.output->mark));
  if (output && *output == gt::ground) fail_argument("output", "expected a moving member, found 'ground'");
  return output;
}

py::dict speeds_dict(const gt::TrainModel& model, const gt::SpeedSolution& s, const std::optional<std::vector<double>>& values) {
  py::dict per_input, rad_s;
  for (gt::MemberId m = 1; m < model.member_count(); ++m) {
    const auto& w = s.speeds[m];
    const std::string& name = model.member(m).name;
    if (!w.determined) {
      per_input[py::str(name)] = py::none();
      rad_s[py::str(name)] = py::none();
      continue;
    }
    py::list f;
    for (const auto& r : w.per_input) f.append(gt::to_fraction_string(r));
    per_input[py::str(name)] = f;
    rad_s[py::str(name)] = values ? py::cast(gt::speed_value(s, m, *values)) : py::none();
  }
  py::dict d;
  d["per_input"] = per_input;
  d["rad_s"] = rad_s;
  return d;
}

py::object optional_list(const std::vector<std::optional<double>>& v, const gt::TrainModel& model) {
  py::dict d;
  for (gt::MemberId m = 0; m < v.size(); ++m) d[py::str(model.member(m).name)] = v[m] ? py::cast(*v[m]) : py::none();
  return d;
}

py::dict power_flow(const gt::TrainModel& model, const Conditions& c, const gt::SpeedSolution& s, const std::vector<double>& speeds,
                    gt::MemberId output, const std::string& torque) {
  const auto [member, T] = pt::parse_member_quantity(model, torque, io::Quantity::torque, argument_fail("torque"));
  const gt::PowerFlow f = gt::analyse_power_flow(model, c.list, s, speeds, output, member, T);
  py::dict d;
  d["torque_ideal_N_m"] = optional_list(f.torque_ideal_Nm, model);
  d["torque_with_losses_N_m"] = optional_list(f.torque_losses_Nm, model);
  d["power_ideal_W"] = optional_list(f.power_ideal_W, model);
  d["power_with_losses_W"] = optional_list(f.power_losses_W, model);
  d["efficiency"] = f.efficiency ? py::cast(*f.efficiency) : py::none();
  d["efficiency_exact"] = f.efficiency_exact ? py::cast(gt::to_fraction_string(*f.efficiency_exact)) : py::none();
  d["input_power_W"] = f.input_power_W;
  d["power_circulation"] = f.power_circulation;
  d["warnings"] = f.warnings;
  return d;
}

py::dict solve_train(const std::string& path, const Arguments& a, double mesh_efficiency) {
  const pt::TrainFile file = pt::load_train_file(path, mesh_efficiency);
  const gt::TrainModel& model = file.model;
  const Conditions c = gather(model, a, file.analysis);
  const std::optional<gt::MemberId> output = output_member(model, a, file.analysis);
  gt::SpeedSolution s;
  try {
    s = gt::solve_speeds(model, c.list);
  } catch (const gt::ConditionError& e) {
    c.fails.at(e.index())(e.what());
  }
  std::optional<std::vector<double>> values;
  if (!c.input_speeds_rad_s.empty() && c.input_speeds_rad_s.front()) {
    values.emplace();
    for (const auto& v : c.input_speeds_rad_s) values->push_back(*v);
  }
  py::dict d;
  d["train"] = model.name();
  py::list members;
  for (gt::MemberId m = 1; m < model.member_count(); ++m) members.append(model.member(m).name);
  d["members"] = members;
  d["dof"] = gt::analyse_structure(model).dof;
  d["remaining_dof"] = s.remaining_dof;
  py::list inputs;
  for (std::size_t i : s.inputs) inputs.append(model.member(c.list[i].member).name);
  d["inputs"] = inputs;
  d["output"] = output ? py::cast(model.member(*output).name) : py::none();
  d["speeds"] = speeds_dict(model, s, values);
  d["ratio"] = py::none();
  if (output && s.inputs.size() == 1)
    if (const auto r = gt::speed_ratio(s, *output, c.list[s.inputs[0]].member)) d["ratio"] = gt::to_fraction_string(*r);
  d["power_flow"] = py::none();
  if (a.torque) {
    if (!output) fail_argument("torque", "needs the output member (output=MEMBER or the file's analysis: output)");
    if (!values) fail_argument("torque", "needs the input speeds (input=['MEMBER=SPEED'])");
    d["power_flow"] = power_flow(model, c, s, *values, *output, *a.torque);
  }
  return d;
}

}  // namespace

void bind_train(py::module_& m) {
  m.def(
      "solve_train",
      [](const std::string& path, std::vector<std::string> fix, std::vector<std::string> couple, std::vector<std::string> input,
         std::optional<std::string> output, std::optional<std::string> torque, double mesh_efficiency) {
        return solve_train(path, Arguments{std::move(fix), std::move(couple), std::move(input), std::move(output), std::move(torque)},
                           mesh_efficiency);
      },
      py::arg("path"), py::kw_only(), py::arg("fix") = std::vector<std::string>{}, py::arg("couple") = std::vector<std::string>{},
      py::arg("input") = std::vector<std::string>{}, py::arg("output") = py::none(), py::arg("torque") = py::none(),
      py::arg("mesh_efficiency") = 1.0,
      "Loads a train file and solves its speeds exactly (libtrain solve_speeds) under the conditions given or the file's "
      "analysis; with a torque 'MEMBER=TORQUE' the power flow (analyse_power_flow).");
}

}  // namespace gearkit::python
