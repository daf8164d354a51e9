// `gearkit synth TASK FILE`: linkage synthesis from a task file (docs/synthesis.md). Each task
// reads its file, synthesises, checks the result with the solver, and writes the report, the
// mechanism file for `gearkit kin`, a drawing and a chart.
#include "synth_command.hpp"

#include "synth_output.hpp"

#include <gearkit/io/output.hpp>
#include <gearkit/io/command_line.hpp>
#include <gearkit/io/error.hpp>
#include <gearkit/io/quantity.hpp>
#include <gearkit/synth/function_generation.hpp>

#include <fmt/format.h>

#include <functional>
#include <map>
#include <numbers>

namespace gearkit::plugins::synth {

namespace po = boost::program_options;

namespace {

constexpr std::string_view usage =
    "gearkit synth function|motion|path|crank-rocker|dwell FILE.yaml [--mechanism OUT.yaml] "
    "[--drawing OUT.svg|OUT.dxf] [--plot OUT.svg] [options: gearkit synth --help]";

using Task = std::function<Output(const io::YamlDocument&, const Overrides&)>;

const std::map<std::string, Task>& tasks() {
  static const std::map<std::string, Task> t{{"function", run_function_task},
                                             {"motion", run_motion_task},
                                             {"path", run_path_task},
                                             {"crank-rocker", run_crank_rocker_task},
                                             {"dwell", run_dwell_task}};
  return t;
}

Overrides read_overrides(const po::variables_map& vm) {
  Overrides o;
  if (vm.count("evaluations")) o.evaluations = vm["evaluations"].as<long>();
  if (vm.count("restarts")) o.restarts = vm["restarts"].as<int>();
  if (vm.count("min-transmission-angle")) {
    const std::string text = vm["min-transmission-angle"].as<std::string>();
    try {
      o.min_transmission_angle = io::parse_quantity_si(text, io::Quantity::angle, "deg");
    } catch (const std::exception& e) {
      io::fail_option("--min-transmission-angle", e.what());
    }
    if (!(o.min_transmission_angle >= 0 && o.min_transmission_angle <= std::numbers::pi / 2))
      io::fail_option("--min-transmission-angle", fmt::format("expected an angle from 0 to 90 deg, found '{:.60}'", text));
  }
  if (vm.count("seed")) {
    const long long s = vm["seed"].as<long long>();
    if (s < 0 || s > 4294967295LL) io::fail_option("--seed", fmt::format("expected 0..4294967295, found {}", s));
    o.seed = static_cast<unsigned>(s);
  }
  return o;
}

Output run_task(const std::string& name, const std::string& file, const Overrides& overrides) {
  const auto it = tasks().find(name);
  if (it == tasks().end())
    throw io::InputError(fmt::format("expected a synthesis task (function, motion, path, crank-rocker, dwell), "
                                     "found '{:.60}'; usage: {}", name, usage));
  const io::YamlDocument doc = io::load_yaml_file(file);
  try {
    return it->second(doc, overrides);
  } catch (const gs::NoSolution& e) {
    throw io::InputError(fmt::format("{}: {}", file, e.what()));
  } catch (const std::invalid_argument& e) {
    throw io::InputError(fmt::format("{}: {}", file, e.what()));
  }
}

std::string drawing_text(const Output& out, const std::string& path) {
  const bool dxf = path.size() >= 4 && path.compare(path.size() - 4, 4, ".dxf") == 0;
  return dxf ? io::to_dxf(out.drawing) : io::to_svg(out.drawing, {5, 0.35, out.report.title});
}

}  // namespace

int run_synth_command(plugin::CommandContext& context) {
  po::options_description desc("gearkit synth options");
  po::positional_options_description positional;
  io::add_positional_argument(desc, positional, "task", "TASK", "function, motion, path, crank-rocker or dwell");
  io::add_positional_argument(desc, positional, "file", "FILE", "task file (YAML, see docs/synthesis.md)");
  desc.add_options()
      ("mechanism,m", po::value<std::string>()->value_name("OUT.yaml"), "write the result as a `gearkit kin` mechanism file")
      ("drawing", po::value<std::string>()->value_name("OUT.svg"), "draw the linkage at its positions (SVG, or DXF by extension)")
      ("plot", po::value<std::string>()->value_name("OUT.svg"), "write the task's chart (structural error, output, transmission angle)")
      ("seed", po::value<long long>()->value_name("N"), "path: random seed of the optimiser (default 1)")
      ("evaluations", po::value<long>()->value_name("N"), "path: objective evaluations (docs/cli.md for the limit)")
      ("restarts", po::value<int>()->value_name("N"), "path: independent optimiser runs (1..64)")
      ("min-transmission-angle", po::value<std::string>()->value_name("ANGLE"),
       "warn where the four-bar's transmission angle falls below this over its motion (default 40 deg) (bare number: deg)");
  io::add_common_options(desc);
  po::variables_map vm;
  if (!io::parse_command_line(context.args, desc, positional, vm, usage, context.out)) return 0;
  const io::CommonOptions common = io::common_options(vm);

  Output out = run_task(vm["task"].as<std::string>(), vm["file"].as<std::string>(), read_overrides(vm));
  io::round_json_numbers(out.report.json);  // 17.66 mm, not 17.660000000000004 after m -> mm
  io::OutputSet outputs(context.out);  // every file committed together, after the report renders
  if (vm.count("mechanism")) outputs.add("--mechanism", vm["mechanism"].as<std::string>(), out.mechanism_yaml);
  if (vm.count("drawing")) outputs.add("--drawing", vm["drawing"].as<std::string>(), drawing_text(out, vm["drawing"].as<std::string>()));
  if (vm.count("plot")) {
    if (!out.plot) io::fail_option("--plot", "this task has no chart");
    outputs.add("--plot", vm["plot"].as<std::string>(), io::to_svg(*out.plot));
  }
  return io::emit(out.report, common, outputs);
}

}  // namespace gearkit::plugins::synth
