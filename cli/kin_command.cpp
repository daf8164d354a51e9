// `gearkit kin FILE.yaml [--at VALUE | --sweep START:END:STEP] [--driver NAME] [--outputs A,B]
//                        [--plot FILE] [--animate FILE] [--format text|json|csv|md|html]`
// Planar mechanism analysis: degrees of freedom, positions, velocities, accelerations, dead
// points, limit positions of outputs, instant centres, Grashof class and transmission angle,
// driving torque and joint reactions.
#include "kin_analysis.hpp"
#include "kin_animation_elements.hpp"
#include "kin_command.hpp"
#include "kin_coupler.hpp"
#include "kin_example.hpp"
#include "kin_units.hpp"
#include "kin_writer.hpp"

#include <gearkit/io/command_line.hpp>
#include <gearkit/io/error.hpp>
#include <gearkit/io/limits.hpp>
#include <gearkit/io/output.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace gearkit::cli {

namespace {

// START:END:STEP with the driver's unit as default.
mechanism::DriverRange parse_sweep(const std::string& text, io::Quantity q, std::string_view unit) {
  std::vector<std::string> parts;
  std::stringstream ss(text);
  for (std::string part; std::getline(ss, part, ':');) parts.push_back(part);
  if (parts.size() != 3)
    io::fail_option("--sweep", fmt::format("expected START:END:STEP (e.g. 0:360:1), found {}", io::quote(text)));
  mechanism::DriverRange r;
  try {
    r.start = io::parse_quantity_si(parts[0], q, unit);
    r.end = io::parse_quantity_si(parts[1], q, unit);
    r.step = io::parse_quantity_si(parts[2], q, unit);
  } catch (const std::exception& e) {
    io::fail_option("--sweep", e.what());
  }
  if (!(r.step > 0.0)) io::fail_option("--sweep", fmt::format("expected a STEP > 0, found {}", io::quote(parts[2])));
  if (r.start == r.end) io::fail_option("--sweep", "expected START different from END");
  if (std::abs(r.end - r.start) / r.step + 1 > io::limits::kSweepPositions)
    io::fail_option("--sweep", fmt::format("expected at most {:.0f} positions, found {:.6g}", io::limits::kSweepPositions,
                                           std::floor(std::abs(r.end - r.start) / r.step) + 1));
  return r;
}

// The work of a sweep grows with positions times coordinates (docs/cli.md, "Limits").
void check_sweep_work(const kin::Model& m, const mechanism::DriverRange& r, const std::string& where) {
  const double positions = std::floor(std::abs(r.end - r.start) / r.step) + 1;
  const double work = positions * m.coordinates();
  if (work > io::limits::kSweepWork)
    throw io::InputError(fmt::format("{}: expected at most {:.0f} positions times coordinates for a sweep, found {:.0f} "
                                     "positions x {} coordinates; take a larger step",
                                     where, io::limits::kSweepWork, positions, m.coordinates()));
}

// Continuation from the drawn input to --at takes |at - drawn| / step steps of the solver.
void check_continuation_work(const kin::Model& m, double distance, double step) {
  const double steps = std::ceil(std::abs(distance) / step);
  if (steps > io::limits::kContinuationSteps || steps * m.coordinates() > io::limits::kContinuationWork)
    io::fail_option("--at", fmt::format("expected a value within {:g} continuation steps of the drawn input (and at "
                                        "most {:g} steps times coordinates), found {:g} steps for {} coordinates",
                                        io::limits::kContinuationSteps, io::limits::kContinuationWork, steps,
                                        m.coordinates()));
}



// --min-transmission-angle: an acute angle, 0 to 90 deg (the transmission angle is acute).
double min_transmission_angle(const io::po::variables_map& vm) {
  const std::string text = vm["min-transmission-angle"].as<std::string>();
  double v = 0;
  try {
    v = io::parse_quantity_si(text, io::Quantity::angle, "deg");
  } catch (const std::exception& e) {
    io::fail_option("--min-transmission-angle", e.what());
  }
  if (!(v >= 0 && v <= M_PI / 2))
    io::fail_option("--min-transmission-angle", fmt::format("expected an angle from 0 to 90 deg, found {}", io::quote(text)));
  return v;
}

int driver_named(const mechanism::Mechanism& mech, const io::po::variables_map& vm) {
  if (!vm.count("driver")) return 0;
  const std::string name = vm["driver"].as<std::string>();
  for (std::size_t k = 0; k < mech.drivers.size(); ++k)
    if (mech.drivers[k].name == name) return static_cast<int>(k);
  io::fail_option("--driver", fmt::format("expected the name of a driver of the model, found {}", io::quote(name)));
}

void choose_outputs(mechanism::Mechanism& mech, const io::po::variables_map& vm) {
  if (!vm.count("outputs")) return;
  std::vector<kin::Output> chosen;
  std::stringstream ss(vm["outputs"].as<std::string>());
  for (std::string name; std::getline(ss, name, ',');) {
    auto it = std::find_if(mech.outputs.begin(), mech.outputs.end(), [&](const kin::Output& o) { return o.name == name; });
    if (it == mech.outputs.end())
      io::fail_option("--outputs", fmt::format("expected names of outputs defined in the model, found {}", io::quote(name)));
    chosen.push_back(*it);
  }
  mech.outputs = chosen;
}

// --at, --sweep or the driver's range in the file; checked against the limits of docs/cli.md.
void read_position_options(const mechanism::Mechanism& mech, const io::po::variables_map& vm, KinRequest& r) {
  const io::Quantity q = angular(mech, r.driver) ? io::Quantity::angle : io::Quantity::length;
  const std::string unit = input_unit(mech, r.driver);
  r.range = mech.drivers[static_cast<std::size_t>(r.driver)].range;
  if (vm.count("at")) {
    try {
      r.at = io::parse_quantity_si(vm["at"].as<std::string>(), q, unit);
    } catch (const std::exception& e) {
      io::fail_option("--at", e.what());
    }
    r.range.reset();
  }
  if (vm.count("sweep")) r.range = parse_sweep(vm["sweep"].as<std::string>(), q, unit);
  if (r.range) check_sweep_work(mech.model, *r.range, vm.count("sweep") ? "option '--sweep'" : r.file);
  if (!r.range) {
    const double drawn = mech.model.drivers()[static_cast<std::size_t>(r.driver)].value;
    check_continuation_work(mech.model, r.at.value_or(drawn) - drawn, angular(mech, r.driver) ? 2.0 * M_PI / 180.0 : 0.002);
  }
}

// Mobility against the number of drivers at the drawn configuration: a model must be exactly
// driven. @returns the mobility analysis, which the report shows.
kin::DofReport checked_mobility(const mechanism::Mechanism& mech, const std::string& file) {
  const kin::Model& m = mech.model;
  kin::Data probe(m);
  kin::assemble(m, probe, 0.0);  // the rank of an assembled configuration, even from a lazy drawing
  const kin::DofReport d = kin::dof(m, probe);
  if (d.drivers < d.dof)
    io::fail_at({file, 0, 0}, fmt::format("under-driven: the mechanism has {} degree(s) of freedom ({}; rank of Phi_q {}) "
                                          "but {} driver(s)", d.dof, d.gruebler_count, d.rank, d.drivers));
  if (d.drivers > d.dof)
    io::fail_at({file, 0, 0}, fmt::format("over-constrained: the mechanism has {} degree(s) of freedom ({}; rank of Phi_q {}) "
                                          "but {} driver(s)", d.dof, d.gruebler_count, d.rank, d.drivers));
  return d;
}

int run_analysis(const mechanism::Mechanism& mech, const KinRequest& r, std::ostream& out, std::ostream& err) {
  const kin::DofReport dof = checked_mobility(mech, r.file);
  KinWriter writer(mech, r, dof, out, err);
  kin::Data data(mech.model);
  kin::assemble(mech.model, data, 0.0);  // the drawing's branch, found even when its links are drawn in line
  if (!r.range) {
    const KinAnalysis a = analyse_single(mech, data, r.driver, r.at, dof, r.switch_branch);
    const double input = a.positions.empty() ? 0.0 : a.positions.front().input;
    writer.plan(input, input, 1);
    for (const KinPosition& p : a.positions) writer.add(p);
    return writer.finish(a);
  }
  kin::SweepOptions planned;
  planned.start = r.range->start;
  planned.end = r.range->end;
  planned.step = r.range->step;
  writer.plan(r.range->start, r.range->end, kin::sweep_sample_count(planned));
  const KinAnalysis a = analyse_sweep(mech, data, r.driver, *r.range, dof, [&](const KinPosition& p) { writer.add(p); },
                                      r.switch_branch);
  return writer.finish(a);
}

io::po::options_description kin_options() {
  io::po::options_description desc("gearkit kin options");
  desc.add_options()("file", io::po::value<std::string>()->value_name("FILE.yaml"), "mechanism model (see docs/kin.md)")(
      "at", io::po::value<std::string>()->value_name("VALUE"), "analyse one position at this input (bare number: deg, or mm for a slide)")(
      "sweep", io::po::value<std::string>()->value_name("START:END:STEP"), "sweep the driver over a range (bare number: deg, or mm for a slide)")(
      "driver", io::po::value<std::string>()->value_name("NAME"), "which driver --at/--sweep move (default: the first)")(
      "outputs", io::po::value<std::string>()->value_name("A,B,..."), "only these named outputs of the model")(
      "plot", io::po::value<std::string>()->value_name("FILE.svg"), "SVG plot of the outputs against the input")(
      "animate", io::po::value<std::string>()->value_name("FILE.svg"), "animated SVG of the mechanism through the sweep")(
      "equations", io::po::bool_switch(), "constraint equations, Jacobian, velocity and acceleration equations and "
      "velocity ratios in the coordinates of the file's equations: section (docs/kin.md)")(
      "example", io::po::value<std::string>()->value_name("chain:N"),
      "write a generated mechanism file instead of analysing one (chain:N: N four-bar loops)");
  add_coupler_options(desc);  // kin_coupler.cpp
  desc.add_options()("speed", io::po::value<std::string>()->value_name("SPEED"),
                     "input speed for the --animate loop time (default: the driver's speed in the file) (unit required, e.g. 60rpm)")(
      "min-transmission-angle", io::po::value<std::string>()->value_name("ANGLE"),
      "warn where a four-bar's transmission angle falls below this (default 40 deg) (bare number: deg)")(
      "branch", io::po::value<std::string>()->value_name("continue|switch"),
      "at a change point (two branches cross, e.g. a parallelogram lying flat): go on along the branch that "
      "continues the motion smoothly (default) or switch to the other");
  io::add_common_options(desc);
  return desc;
}

}  // namespace

int run_kin_command(plugin::CommandContext& context) {
  const io::po::options_description desc = kin_options();
  io::po::positional_options_description positional;
  positional.add("file", 1);
  io::po::variables_map vm;
  const char* usage =
      "gearkit kin FILE.yaml [--at VALUE | --sweep START:END:STEP] [--driver NAME] [--outputs A,B] [--plot FILE] "
      "[--animate FILE] [--branch continue|switch] [--equations] [--format text|json|csv|md|html]";
  if (!io::parse_command_line(context.args, desc, positional, vm, usage, context.out)) return 0;
  KinRequest r;
  r.common = io::common_options(vm);
  if (vm.count("example")) {
    if (vm.count("file")) io::fail_option("--example", "expected no mechanism file with --example, found one");
    io::OutputSet outputs(context.out);
    outputs.add("--output", r.common.output, example_mechanism_yaml(vm["example"].as<std::string>()));
    outputs.commit();
    return 0;
  }
  if (!vm.count("file")) throw io::InputError(fmt::format("expected the FILE argument, found none; usage: {}", usage));
  if (vm.count("at") && vm.count("sweep")) io::fail_option("--at", "expected either --at or --sweep, found both");
  r.file = vm["file"].as<std::string>();
  mechanism::Mechanism mech =
      mechanism::load_mechanism(r.file, [&context](std::string_view type) { return context.host.find_element_type(type); });
  if (mech.drivers.empty())
    io::fail_at({r.file, 0, 0}, "expected at least one driver (an input angle or slider displacement), found none");
  r.driver = driver_named(mech, vm);
  choose_outputs(mech, vm);
  read_position_options(mech, vm, r);
  r.equations = vm["equations"].as<bool>();
  if (vm.count("plot")) r.plot = vm["plot"].as<std::string>();
  if (vm.count("animate")) r.animate = vm["animate"].as<std::string>();
  r.speed = animation_speed(vm, mech, r.driver);
  if (vm.count("branch")) {
    const std::string branch = vm["branch"].as<std::string>();
    if (branch != "continue" && branch != "switch")
      io::fail_option("--branch", fmt::format("expected continue or switch, found {}", io::quote(branch)));
    r.switch_branch = branch == "switch";
  }
  if (vm.count("min-transmission-angle")) r.min_transmission_angle = min_transmission_angle(vm);
  r.vm = &vm;
  return run_analysis(mech, r, context.out, context.err);
}

}  // namespace gearkit::cli
