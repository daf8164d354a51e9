// `gearkit train FILE ...`: speeds, ratios, modes, torques and assembly checks of a gear train;
// `gearkit train synth ...`: tooth counts for a target ratio (train_synth_command.cpp).
#include "train_command.hpp"
#include "train_willis.hpp"

#include "train_centre_distance.hpp"
#include "train_conditions.hpp"
#include "train_diagram.hpp"
#include "train_file.hpp"
#include "train_rating.hpp"
#include "train_synth_command.hpp"

#include <gearkit/io/command_line.hpp>
#include <gearkit/io/error.hpp>
#include <gearkit/io/limits.hpp>
#include <gearkit/io/output.hpp>
#include <gearkit/io/quantity.hpp>
#include <gearkit/io/report.hpp>
#include <gearkit/train/assembly.hpp>
#include <gearkit/train/kinematics.hpp>
#include <gearkit/train/torques.hpp>
#include <gearkit/train/willis.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <ostream>

namespace gearkit::plugins::train {

namespace gt = gearkit::train;
namespace po = boost::program_options;

namespace {

constexpr std::string_view usage =
    "gearkit train FILE [--fix MEMBER]... [--couple A=B]... [--input MEMBER[=SPEED]]... [--output-member MEMBER] "
    "[--torque MEMBER=TORQUE | --power MEMBER=POWER] [--mesh-efficiency ETA] [--modes] [--svg FILE] [--dxf FILE] "
    "[options]\n"
    "       gearkit train synth reducer|planetary ... (see gearkit train synth --help)";

constexpr double rpm_per_rad_s = 60.0 / (2.0 * std::numbers::pi);

// Where a condition came from, to place an error about it.
struct Origin {
  std::string option;                 // "fix", "couple", "input" (command line)
  std::optional<io::SourceMark> mark; // set when written in the file
};

[[noreturn]] void fail_from(const Origin& origin, std::string_view message) {
  if (origin.mark) io::fail_at(*origin.mark, message);
  io::fail_option("--" + origin.option, message);
}

ConditionFail fail_with(const Origin& origin) {
  return [origin](std::string_view message) { fail_from(origin, message); };
}

std::vector<std::string> strings(const po::variables_map& vm, const char* key) {
  return vm.count(key) ? vm[key].as<std::vector<std::string>>() : std::vector<std::string>{};
}

struct Conditions {
  std::vector<gt::Condition> list;
  std::vector<Origin> origins;
  std::vector<std::optional<double>> input_speeds_rad_s;  // per input, in order
};

// External torques act only where the user acts on the train (torques.hpp): a torque given on any
// other member has nothing to balance it, and every torque would come out indeterminate.
void check_torque_member(const gt::TrainModel& model, const Conditions& c, gt::MemberId member, gt::MemberId output,
                         const std::string& option) {
  std::vector<std::string> allowed{model.member(output).name};
  for (const gt::Condition& k : c.list) {
    allowed.push_back(model.member(k.member).name);
    if (k.kind == gt::Condition::Kind::couple) allowed.push_back(model.member(k.other).name);
    if (k.member == member || (k.kind == gt::Condition::Kind::couple && k.other == member)) return;
  }
  if (member == output) return;
  std::sort(allowed.begin(), allowed.end());
  allowed.erase(std::unique(allowed.begin(), allowed.end()), allowed.end());
  io::fail_option("--" + option,
                  fmt::format("expected a member the train is driven, loaded, held or coupled at ({}), found {}",
                              fmt::join(allowed, ", "), io::quote(model.member(member).name)));
}

Conditions gather_conditions(const gt::TrainModel& model, const po::variables_map& vm, const FileAnalysis& file) {
  Conditions c;
  const bool from_command_line = vm.count("fix") || vm.count("couple") || vm.count("input");
  const auto add = [&](const std::string& option, const std::string& text, std::optional<io::SourceMark> mark) {
    const Origin origin{option, std::move(mark)};
    const ConditionFail fail = fail_with(origin);
    if (option == "fix") {
      c.list.push_back(parse_fix(model, text, fail));
    } else if (option == "couple") {
      c.list.push_back(parse_couple(model, text, fail));
    } else {
      ParsedInput input = parse_input(model, text, fail, !origin.mark.has_value());
      c.list.push_back(input.condition);
      c.input_speeds_rad_s.push_back(input.speed_rad_s);
    }
    c.origins.push_back(origin);
  };
  if (from_command_line) {
    for (const auto& t : strings(vm, "fix")) add("fix", t, std::nullopt);
    for (const auto& t : strings(vm, "couple")) add("couple", t, std::nullopt);
    for (const auto& t : strings(vm, "input")) add("input", t, std::nullopt);
  } else {
    for (const auto& w : file.fix) add("fix", w.text, w.mark);
    for (const auto& w : file.couple) add("couple", w.text, w.mark);
    for (const auto& w : file.input) add("input", w.text, w.mark);
  }
  std::size_t with_speed = 0;
  for (const auto& s : c.input_speeds_rad_s) with_speed += s.has_value();
  if (with_speed != 0 && with_speed != c.input_speeds_rad_s.size()) {
    for (std::size_t i = 0, k = 0; i < c.list.size(); ++i)
      if (c.list[i].kind == gt::Condition::Kind::input && !c.input_speeds_rad_s[k++])
        fail_from(c.origins[i], "expected a speed for every input (MEMBER=SPEED) or for none");
  }
  return c;
}

std::string names(const gt::TrainModel& model, const std::vector<gt::MemberId>& ids) {
  std::vector<std::string> n;
  for (auto id : ids) n.push_back("'" + model.member(id).name + "'");
  return n.empty() ? std::string("none") : fmt::format("{}", fmt::join(n, ", "));
}

nlohmann::json name_list(const gt::TrainModel& model, const std::vector<gt::MemberId>& ids) {
  nlohmann::json j = nlohmann::json::array();
  for (auto id : ids) j.push_back(model.member(id).name);
  return j;
}

void add_equations(io::Report& report, const gt::TrainModel& model) {
  io::Table table{"Willis equations (one per mesh)", {"mesh", "carrier", "equation", "linear form"}, {}};
  nlohmann::json equations = nlohmann::json::array();
  for (gt::MeshId k = 0; k < model.meshes().size(); ++k) {
    const std::string eq = gt::willis_equation_text(model, k);
    const std::string linear = gt::willis_linear_text(model, k);
    table.add_row({model.mesh(k).name, model.member(model.mesh(k).carrier).name, eq, linear});
    equations.push_back({{"mesh", model.mesh(k).name},
                         {"carrier", model.member(model.mesh(k).carrier).name},
                         {"equation", eq},
                         {"linear", linear},
                         {"basic_ratio", gt::to_fraction_string(gt::basic_ratio(model, k))}});
  }
  report.tables.push_back(std::move(table));
  report.json["equations"] = equations;
}

void add_structure(io::Report& report, const gt::TrainModel& model, const gt::Structure& s) {
  report.notes.push_back(fmt::format("Degrees of freedom of the train: {} (independent members: {})", s.dof,
                                     names(model, s.independent)));
  report.json["dof"] = s.dof;
  report.json["independent_members"] = name_list(model, s.independent);
  report.json["locked_members"] = name_list(model, s.locked);
  if (s.dof == 0)
    report.warnings.push_back("the train is locked: its meshes leave no degree of freedom, nothing can turn");
  else if (!s.locked.empty())
    report.warnings.push_back(fmt::format("members {} are locked: the meshes form a closed loop that forces their "
                                          "speed to zero", names(model, s.locked)));
  for (gt::MeshId k : s.redundant_meshes)
    report.notes.push_back(fmt::format("mesh '{}' repeats a constraint of the others (statically indeterminate, e.g. "
                                       "an extra planet drawn explicitly)", model.mesh(k).name));
}

std::string role(const gt::TrainModel& model, gt::MemberId m, const Conditions& c, std::optional<gt::MemberId> output) {
  std::vector<std::string> roles;
  for (const auto& cond : c.list) {
    if (cond.member != m && cond.other != m) continue;
    if (cond.kind == gt::Condition::Kind::fix && cond.member == m) roles.push_back("fixed");
    if (cond.kind == gt::Condition::Kind::input && cond.member == m) roles.push_back("input");
    if (cond.kind == gt::Condition::Kind::couple)
      roles.push_back("= " + model.member(cond.member == m ? cond.other : cond.member).name);
  }
  if (output && *output == m) roles.push_back("output");
  if (model.is_planet(m)) roles.push_back("planet of " + model.member(model.member(m).carried_by).name);
  if (m == gt::ground) roles.push_back("frame");
  return fmt::format("{}", fmt::join(roles, ", "));
}

void add_speeds(io::Report& report, const gt::TrainModel& model, const gt::SpeedSolution& s, const Conditions& c,
                std::optional<gt::MemberId> output, const std::optional<std::vector<double>>& speeds_rad_s) {
  const bool single_input = s.inputs.size() == 1;
  std::vector<std::string> header{"member", "role"};
  if (speeds_rad_s) header.push_back("n [rpm]");
  if (single_input) header.push_back("w / w_" + model.member(c.list[s.inputs[0]].member).name);
  if (speeds_rad_s) header.push_back("n relative to carrier [rpm]");
  io::Table table{"Speeds", header, {}};
  nlohmann::json rpm = nlohmann::json::object(), exact = nlohmann::json::object(),
                 relative = nlohmann::json::object();
  for (gt::MemberId m = 0; m < model.member_count(); ++m) {
    std::vector<std::string> row{model.member(m).name, role(model, m, c, output)};
    const gt::MemberSpeed& speed = s.speeds[m];
    if (speeds_rad_s) {
      if (speed.determined) {
        const double n = gt::speed_value(s, m, *speeds_rad_s) * rpm_per_rad_s;
        row.push_back(io::fixed(n, 4));
        rpm[model.member(m).name] = n;
      } else {
        row.push_back("free");
      }
    }
    if (single_input) {
      row.push_back(speed.determined ? gt::to_fraction_and_decimal(speed.per_input[0]) : "free");
      if (speed.determined) exact[model.member(m).name] = gt::to_fraction_string(speed.per_input[0]);
    }
    if (speeds_rad_s) {
      const gt::MemberId carrier = model.member(m).carried_by;
      if (model.is_planet(m) && speed.determined && s.speeds[carrier].determined) {
        const double n = (gt::speed_value(s, m, *speeds_rad_s) - gt::speed_value(s, carrier, *speeds_rad_s)) *
                         rpm_per_rad_s;
        row.push_back(io::fixed(n, 4));
        relative[model.member(m).name] = n;
      } else {
        row.push_back("");
      }
    }
    table.add_row(std::move(row));
  }
  report.tables.push_back(std::move(table));
  if (speeds_rad_s) {
    report.json["speeds_rpm"] = rpm;
    report.json["planet_speeds_relative_to_carrier_rpm"] = relative;
  }
  if (single_input) report.json["speeds_per_input"] = exact;
  report.json["remaining_dof"] = s.remaining_dof;
  report.json["free_members"] = name_list(model, s.free_members);
  if (s.remaining_dof > 0)
    report.warnings.push_back(fmt::format(
        "under-determined: the conditions leave {} degree(s) of freedom; free member(s): {}. Add --fix, --couple or "
        "--input", s.remaining_dof, names(model, s.free_members)));
  for (std::size_t i : s.redundant_conditions)
    report.warnings.push_back(fmt::format("condition '{}' is already implied by the train and the conditions before "
                                          "it (redundant)", c.list[i].label));
}

void add_ratio(io::Report& report, const gt::TrainModel& model, const gt::SpeedSolution& s, const Conditions& c,
               gt::MemberId output) {
  if (s.inputs.size() != 1) {
    report.warnings.push_back("no ratio: it needs exactly one input (--input MEMBER)");
    return;
  }
  const gt::MemberId input = c.list[s.inputs[0]].member;
  const auto ratio = gt::speed_ratio(s, output, input);
  const std::string label = fmt::format("w_{} / w_{}", model.member(output).name, model.member(input).name);
  if (!ratio) {
    report.warnings.push_back(fmt::format("no ratio {}: the output speed is not determined by the conditions", label));
    return;
  }
  report.notes.push_back(fmt::format("Ratio {} = {}", label, gt::to_fraction_and_decimal(*ratio)));
  report.json["ratio"] = {{"input", model.member(input).name},
                          {"output", model.member(output).name},
                          {"exact", gt::to_fraction_string(*ratio)},
                          {"value", gt::to_double(*ratio)}};
}

void add_modes(io::Report& report, const gt::TrainModel& model, const Conditions& c, gt::MemberId input,
               gt::MemberId output) {
  std::size_t candidates = 0;  // members a mode may hold or couple: n holds and n(n-1)/2 pairs
  for (gt::MemberId m = 1; m < model.member_count(); ++m) candidates += !model.is_planet(m) && m != input && m != output;
  if (candidates > io::limits::kModesMembers)
    io::fail_option("--modes", fmt::format("expected at most {} members besides planets, input and output (modes hold "
                                           "or couple each of them), found {}",
                                           io::limits::kModesMembers, candidates));
  const auto modes = gt::transmission_modes(model, c.list, input, output);
  io::Table table{fmt::format("Modes: w_{} / w_{} with one more condition", model.member(output).name,
                              model.member(input).name),
                  {"condition", "ratio"}, {}};
  nlohmann::json j = nlohmann::json::array();
  for (const auto& mode : modes) {
    if (mode.ratio) {
      table.add_row({mode.label, gt::to_fraction_and_decimal(*mode.ratio)});
      j.push_back({{"condition", mode.label}, {"exact", gt::to_fraction_string(*mode.ratio)},
                   {"value", gt::to_double(*mode.ratio)}});
    } else {
      table.add_row({mode.label, mode.message});
      j.push_back({{"condition", mode.label}, {"exact", nullptr}, {"value", nullptr}, {"message", mode.message}});
    }
  }
  report.tables.push_back(std::move(table));
  report.json["modes"] = j;
}

std::string optional_fixed(const std::optional<double>& v, int digits) {
  return v ? io::fixed(*v, digits) : std::string("indeterminate");
}

void add_torques(io::Report& report, const gt::TrainModel& model, const gt::SpeedSolution& s, const Conditions& c,
                 const std::vector<double>& speeds_rad_s, gt::MemberId output, gt::MemberId given_member,
                 double given_torque_Nm) {
  const gt::PowerFlow flow =
      gt::analyse_power_flow(model, c.list, s, speeds_rad_s, output, given_member, given_torque_Nm);
  for (const auto& w : flow.warnings) report.warnings.push_back(w);
  if (flow.torque_ideal_Nm.empty()) return;
  io::Table table{"Torques from outside the train, and coupling torques (positive in the sense of positive speed; "
                  "power T·w > 0 enters the train)",
                  {"member", "T ideal [N*m]", "P ideal [W]", "T with losses [N*m]", "P with losses [W]"}, {}};
  nlohmann::json ideal = nlohmann::json::object(), lossy = nlohmann::json::object(),
                 p_ideal = nlohmann::json::object(), p_lossy = nlohmann::json::object();
  for (gt::MemberId m = 0; m < model.member_count(); ++m) {
    const auto& ti = flow.torque_ideal_Nm[m];
    const auto& tl = flow.torque_losses_Nm[m];
    const bool zero = ti && tl && *ti == 0 && *tl == 0;
    if (zero) continue;
    const bool frame = m == gt::ground;
    table.add_row({frame ? "ground (couple on the frame)" : model.member(m).name, optional_fixed(ti, 4),
                   frame ? "" : optional_fixed(flow.power_ideal_W[m], 3), optional_fixed(tl, 4),
                   frame ? "" : optional_fixed(flow.power_losses_W[m], 3)});
    const std::string& key = model.member(m).name;
    ideal[key] = ti ? nlohmann::json(*ti) : nlohmann::json(nullptr);
    lossy[key] = tl ? nlohmann::json(*tl) : nlohmann::json(nullptr);
    if (m != gt::ground) {
      p_ideal[key] = flow.power_ideal_W[m] ? nlohmann::json(*flow.power_ideal_W[m]) : nlohmann::json(nullptr);
      p_lossy[key] = flow.power_losses_W[m] ? nlohmann::json(*flow.power_losses_W[m]) : nlohmann::json(nullptr);
    }
  }
  nlohmann::json couplings = nlohmann::json::object();
  for (std::size_t j = 0; j < c.list.size(); ++j) {
    if (c.list[j].kind != gt::Condition::Kind::couple) continue;
    const auto& ci = flow.coupling_ideal_Nm[j];
    const auto& cl = flow.coupling_losses_Nm[j];
    const double w = gt::speed_value(s, c.list[j].member, speeds_rad_s);
    table.add_row({"coupling " + c.list[j].label.substr(7) + " (on " + model.member(c.list[j].member).name + ")",
                   optional_fixed(ci, 4), ci ? io::fixed(*ci * w, 3) : "indeterminate", optional_fixed(cl, 4),
                   cl ? io::fixed(*cl * w, 3) : "indeterminate"});
    couplings[c.list[j].label] = {{"member", model.member(c.list[j].member).name},
                                  {"ideal_Nm", ci ? nlohmann::json(*ci) : nlohmann::json(nullptr)},
                                  {"with_losses_Nm", cl ? nlohmann::json(*cl) : nlohmann::json(nullptr)}};
  }
  report.tables.push_back(std::move(table));

  io::Table meshes{"Power flow in each mesh (seen from its carrier)", {"mesh", "eta_0", "power flows"}, {}};
  nlohmann::json drivers = nlohmann::json::object();
  for (gt::MeshId k = 0; k < model.meshes().size(); ++k) {
    const gt::Mesh& mesh = model.mesh(k);
    const std::string a = model.gear(mesh.gear_a).name, b = model.gear(mesh.gear_b).name;
    const std::string direction = flow.drivers[k] == gt::MeshDriver::gear_a   ? a + " -> " + b
                                  : flow.drivers[k] == gt::MeshDriver::gear_b ? b + " -> " + a
                                                                              : "none (no relative motion)";
    meshes.add_row({mesh.name, io::fixed(mesh.efficiency, 4), direction});
    drivers[mesh.name] = direction;
  }
  report.tables.push_back(std::move(meshes));

  nlohmann::json j{{"given", {{"member", model.member(given_member).name}, {"torque_Nm", given_torque_Nm}}},
                   {"ideal_Nm", ideal},
                   {"with_losses_Nm", lossy},
                   {"power_ideal_W", p_ideal},
                   {"power_with_losses_W", p_lossy},
                   {"mesh_power_flow", drivers},
                   {"couplings", couplings},
                   {"input_power_W", flow.input_power_W},
                   {"max_through_power_W", flow.max_through_power_W},
                   {"max_through_power_at", flow.max_through_power_at},
                   {"power_circulation", flow.power_circulation}};
  if (flow.efficiency) {
    j["efficiency"] = *flow.efficiency;
    report.notes.push_back(
        flow.efficiency_exact
            ? fmt::format("Overall efficiency (with mesh losses) = {}", gt::to_fraction_and_decimal(*flow.efficiency_exact))
            : fmt::format("Overall efficiency (with mesh losses) = {:.6f}", *flow.efficiency));
  }
  if (flow.efficiency_exact) j["efficiency_exact"] = gt::to_fraction_string(*flow.efficiency_exact);
  report.json["torques"] = j;
}

void add_assembly(io::Report& report, const gt::TrainModel& model, double tolerance_mm) {
  const auto checks = gt::check_assembly(model, working_centre_distance, tolerance_mm);
  if (checks.empty()) return;
  io::Table table{"Assembly conditions", {"subject", "condition", "result", "detail"}, {}};
  nlohmann::json j = nlohmann::json::array();
  for (const auto& check : checks) {
    const std::string result = !check.checked ? "not checked" : check.satisfied ? "ok" : "FAILS";
    table.add_row({check.subject, check.condition, result, check.detail});
    j.push_back({{"subject", check.subject}, {"condition", check.condition}, {"checked", check.checked},
                 {"satisfied", check.satisfied}, {"detail", check.detail}});
    if (check.checked && !check.satisfied)
      report.warnings.push_back(fmt::format("cannot be assembled: {}, {}: {}", check.subject, check.condition,
                                            check.detail));
    if (!check.checked && check.suspect)
      report.warnings.push_back(fmt::format("assembly of {} ({}) {}", check.subject, check.condition, check.detail));
  }
  report.tables.push_back(std::move(table));
  report.json["assembly"] = j;
}

// The stick and speed diagrams (--svg, --dxf): speeds in rpm when the inputs have speeds, else as
// multiples of the one input's speed.
void add_pictures(const po::variables_map& vm, const gt::TrainModel& model, const Conditions& c,
                  const gt::SpeedSolution& s, std::optional<gt::MemberId> output,
                  const std::optional<std::vector<double>>& speeds_rad_s, const std::string& title,
                  io::OutputSet& outputs) {
  if (!vm.count("svg") && !vm.count("dxf")) return;
  TrainDiagramInput in;
  in.title = title;
  in.output = output;
  for (const gt::Condition& k : c.list) {
    if (k.kind == gt::Condition::Kind::fix) in.fixed.push_back(k.member);
    if (k.kind == gt::Condition::Kind::input) in.inputs.push_back(k.member);
    if (k.kind == gt::Condition::Kind::couple) in.couplings.emplace_back(k.member, k.other);
  }
  if (!c.list.empty() && (speeds_rad_s || s.inputs.size() == 1)) {
    in.speed_unit = speeds_rad_s ? "rpm" : "x w_" + model.member(c.list[s.inputs[0]].member).name;
    for (gt::MemberId m = 0; m < model.member_count(); ++m) {
      if (!s.speeds[m].determined) {
        in.speeds.emplace_back();
      } else if (speeds_rad_s) {
        in.speeds.emplace_back(gt::speed_value(s, m, *speeds_rad_s) * rpm_per_rad_s);
      } else {
        in.speeds.emplace_back(gt::to_double(s.speeds[m].per_input[0]));
      }
    }
  }
  const io::Drawing drawing = train_diagram(model, in);
  if (vm.count("svg")) outputs.add("--svg", vm["svg"].as<std::string>(), io::to_svg(drawing, {5, 0.3, title}));
  if (vm.count("dxf")) outputs.add("--dxf", vm["dxf"].as<std::string>(), io::to_dxf(drawing));
}

void add_train_options(po::options_description& desc) {
  desc.add_options()
      ("fix", po::value<std::vector<std::string>>()->value_name("MEMBER"), "hold MEMBER still (repeatable)")
      ("couple", po::value<std::vector<std::string>>()->value_name("A=B"), "members A and B turn together (repeatable)")
      ("input", po::value<std::vector<std::string>>()->value_name("MEMBER[=SPEED]"),
       "a driven member and its speed (repeatable); without SPEED only ratios are shown (unit required, e.g. sun=1500rpm)")
      ("output-member", po::value<std::string>()->value_name("MEMBER"),
       "the output member: ratio w_out/w_in, --modes and the load of --torque")
      ("torque", po::value<std::string>()->value_name("MEMBER=TORQUE"),
       "a torque applied to MEMBER; the others follow from equilibrium (unit required, e.g. sun=40N*m)")
      ("power", po::value<std::string>()->value_name("MEMBER=POWER"), "power fed to MEMBER (unit required, e.g. sun=7.5kW)")
      ("rate", po::bool_switch(), "load capacity of every mesh (docs/rating.md; face widths and materials in the file)")
      ("mesh-efficiency", io::number_in({0, 1, true, false, "a basic efficiency in (0, 1]"})->value_name("ETA"),
       "basic efficiency eta_0 of the meshes without their own 'efficiency' (default 1)")
      ("modes", "ratio w_out/w_in with each other member held fixed in turn, and with pairs coupled")
      ("willis", po::value<std::string>()->value_name("M1,M2,..."),
       "Willis' equation of each stage in the velocity vector u = {w_M1, w_M2, ...}, planets eliminated")
      ("centre-tolerance", po::value<std::string>()->value_name("LEN"),
       "coaxiality: largest accepted difference of planet centre distances (default 0.001 mm) (bare number: mm)")
      ("svg", po::value<std::string>()->value_name("FILE"),
       "write the stick diagram of the train and the speed diagram of its planetary stages as SVG")
      ("dxf", po::value<std::string>()->value_name("FILE"), "write the same drawing as DXF R2000");
  io::add_common_options(desc);
}

/// The output member from --output-member or the file's analysis, if any.
std::optional<gt::MemberId> output_member(const gt::TrainModel& model, const po::variables_map& vm,
                                          const TrainFile& file) {
  std::optional<gt::MemberId> output;
  if (vm.count("output-member")) {
    output = parse_member(model, vm["output-member"].as<std::string>(), fail_with(Origin{"output-member", {}}));
  } else if (file.analysis.output) {
    output = parse_member(model, file.analysis.output->text, fail_with(Origin{"", file.analysis.output->mark}));
  }
  if (output && *output == gt::ground) io::fail_option("--output-member", "expected a moving member, found 'ground'");
  return output;
}

/// What the speed part of the report needs from the conditions and their solution.
struct Kinematics {
  const gt::TrainModel& model;
  const Conditions& conditions;
  const gt::SpeedSolution& solution;
  std::optional<gt::MemberId> output;
  std::optional<std::vector<double>> speeds_rad_s;  ///< the input speeds, when every input has one
};

/// Torques (--torque or --power at a member) and, with --rate, the load capacity of the meshes.
void add_load(io::Report& report, const po::variables_map& vm, const Kinematics& k) {
  const bool is_torque = vm.count("torque") > 0;
  const std::string option = is_torque ? "torque" : "power";
  const auto fail = fail_with(Origin{option, {}});
  if (!k.output) io::fail_option("--" + option, "needs --output-member MEMBER (where the load acts)");
  auto [member, value] = parse_member_quantity(k.model, vm[option].as<std::string>(),
                                               is_torque ? io::Quantity::torque : io::Quantity::power, fail);
  if (k.solution.inputs.empty()) io::fail_option("--" + option, "needs at least one --input MEMBER");
  check_torque_member(k.model, k.conditions, member, *k.output, option);
  bool all_determined = true;
  for (const auto& sp : k.solution.speeds) all_determined = all_determined && sp.determined;
  if (!all_determined) {
    report.warnings.push_back("no torques: the conditions leave the speeds under-determined");
    return;
  }
  const std::vector<double> w = k.speeds_rad_s ? *k.speeds_rad_s : std::vector<double>(k.solution.inputs.size(), 1.0);
  if (!k.speeds_rad_s)
    report.notes.push_back("No input speed given: powers are shown for 1 rad/s at each input (torques do not "
                           "depend on it)");
  if (!is_torque) {
    if (!k.speeds_rad_s) io::fail_option("--power", "needs input speeds (--input MEMBER=SPEED) to turn power into torque");
    const double omega = gt::speed_value(k.solution, member, w);
    if (omega == 0) io::fail_option("--power", fmt::format("member '{}' does not turn; give a torque instead",
                                                         k.model.member(member).name));
    value /= omega;
  }
  add_torques(report, k.model, k.solution, k.conditions, w, *k.output, member, value);
  if (vm["rate"].as<bool>()) {
    if (!k.speeds_rad_s) io::fail_option("--rate", "needs the input speeds (--input MEMBER=SPEED)");
    add_mesh_ratings(report, vm["file"].as<std::string>(), k.model, k.solution, k.conditions.list, w, *k.output,
                     member, value);
  }
}

/// Speeds, the ratio and the modes for the conditions.
void add_kinematics(io::Report& report, const po::variables_map& vm, const Kinematics& k) {
  nlohmann::json labels = nlohmann::json::array();
  for (const auto& c : k.conditions.list) labels.push_back(c.label);
  report.json["conditions"] = labels;
  if (!k.conditions.list.empty()) add_speeds(report, k.model, k.solution, k.conditions, k.output, k.speeds_rad_s);
  if (k.output && !k.conditions.list.empty()) add_ratio(report, k.model, k.solution, k.conditions, *k.output);
  if (vm.count("modes")) {
    if (!k.output) io::fail_option("--modes", "needs --output-member MEMBER (and one --input)");
    if (k.solution.inputs.size() != 1) io::fail_option("--modes", "needs exactly one --input MEMBER");
    add_modes(report, k.model, k.conditions, k.conditions.list[k.solution.inputs[0]].member, *k.output);
  }
}

/// --centre-tolerance in mm (default 0.001 mm).
double centre_tolerance_mm(const po::variables_map& vm) {
  const io::OptionRange range{0, 1e7, false, false, "a length from 0 to 10 km"};  // 10 km: the generic limit
  return io::quantity_option(vm, "centre-tolerance", io::Quantity::length, "mm", range).value_or(1e-6) * 1e3;
}

/// The input speeds in rad/s when every input has one.
std::optional<std::vector<double>> input_speeds(const Conditions& conditions) {
  if (conditions.input_speeds_rad_s.empty() || !conditions.input_speeds_rad_s.front()) return std::nullopt;
  std::vector<double> speeds;
  for (const auto& s : conditions.input_speeds_rad_s) speeds.push_back(*s);
  return speeds;
}

}  // namespace

int run_train_command(plugin::CommandContext& context) {
  if (!context.args.empty() && context.args.front() == "synth")
    return run_train_synth_command(context, {context.args.begin() + 1, context.args.end()});

  po::options_description desc("gearkit train options");
  po::positional_options_description positional;
  io::add_positional_argument(desc, positional, "file", "FILE", "train model (YAML, see docs/train.md)");
  add_train_options(desc);
  po::variables_map vm;
  if (!io::parse_command_line(context.args, desc, positional, vm, usage, context.out)) return 0;
  const io::CommonOptions common = io::common_options(vm);

  const double default_efficiency = vm.count("mesh-efficiency") ? vm["mesh-efficiency"].as<double>() : 1.0;
  const TrainFile file = load_train_file(vm["file"].as<std::string>(), default_efficiency);
  const gt::TrainModel& model = file.model;
  const Conditions conditions = gather_conditions(model, vm, file.analysis);
  const std::optional<gt::MemberId> output = output_member(model, vm, file);

  io::Report report;
  report.title = "Gear train: " + (model.name().empty() ? vm["file"].as<std::string>() : model.name());
  report.json["train"] = model.name();
  add_equations(report, model);
  add_structure(report, model, gt::analyse_structure(model));
  if (vm.count("willis")) add_willis_in_vector(report, model, vm["willis"].as<std::string>());

  gt::SpeedSolution solution;
  try {
    solution = gt::solve_speeds(model, conditions.list);
  } catch (const gt::ConditionError& e) {
    fail_from(conditions.origins.at(e.index()), e.what());
  }
  const Kinematics kinematics{model, conditions, solution, output, input_speeds(conditions)};
  add_kinematics(report, vm, kinematics);
  if (vm.count("torque") && vm.count("power")) io::fail_option("--power", "give either --torque or --power, not both");
  if (vm.count("torque") || vm.count("power")) {
    add_load(report, vm, kinematics);
  } else if (vm["rate"].as<bool>()) {
    io::fail_option("--rate", "needs the load: --torque MEMBER=TORQUE or --power MEMBER=POWER");
  }
  add_assembly(report, model, centre_tolerance_mm(vm));
  io::OutputSet outputs(context.out);
  add_pictures(vm, model, conditions, solution, output, kinematics.speeds_rad_s, report.title.substr(12), outputs);
  return io::emit(report, common, outputs);
}

}  // namespace gearkit::plugins::train
