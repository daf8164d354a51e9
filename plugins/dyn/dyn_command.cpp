// `gearkit dyn FILE`: machine dynamics of a drive line — flywheel sizing over a steady cycle,
// energy and efficiency per cycle, and the equation of motion in time (docs/dyn.md).
#include "dyn_command.hpp"

#include "dyn_model.hpp"
#include "dyn_sections.hpp"

#include <gearkit/io/atomic_file.hpp>
#include <gearkit/io/command_line.hpp>
#include <gearkit/io/error.hpp>

#include <fmt/format.h>

#include <numbers>

namespace gearkit::plugins::dyn {

namespace po = boost::program_options;

namespace {

constexpr std::string_view usage =
    "gearkit dyn FILE.yaml [--plot FILE.svg] [--speed-plot FILE.svg] [--format text|json|csv|md|html] [--output FILE]";

void add_drive_line(const Model& m, io::Report& report) {
  io::Table t{"Drive line", {"shaft", "speed ratio w/w_motor", "efficiency from motor", "inertia [kg*m^2]"}, {}};
  nlohmann::json shafts = nlohmann::json::array();
  for (std::size_t k = 0; k < gd::shaft_count(m.line); ++k) {
    const double ratio = gd::speed_ratio(m.line, 0, k);
    const double eta = gd::efficiency_between(m.line, 0, k);
    t.add_row({m.line.shaft_names[k], io::fixed(ratio, 6), io::fixed(eta, 4), io::fixed(m.line.shaft_inertia[k], 6)});
    shafts.push_back({{"name", m.line.shaft_names[k]}, {"speed_ratio", ratio}, {"efficiency_from_motor", eta},
                      {"inertia_kgm2", m.line.shaft_inertia[k]}});
  }
  report.tables.push_back(std::move(t));
  report.json["shafts"] = shafts;
  report.json["motor_efficiency"] = m.line.motor_efficiency;
  if (m.motor.speed) report.json["motor_omega_rad_s"] = *m.motor.speed;
  const std::size_t load = gd::shaft_count(m.line) - 1;
  report.json["inertia_at_motor_kgm2"] = gd::reduced_inertia(m.line, 0);
  report.json["inertia_at_load_kgm2"] = gd::reduced_inertia(m.line, load);
  report.notes.push_back(fmt::format("Reduced inertia: {:.6g} kg*m^2 at the motor shaft, {:.6g} kg*m^2 at the '{}' shaft.",
                                     gd::reduced_inertia(m.line, 0), gd::reduced_inertia(m.line, load),
                                     m.line.shaft_names[load]));
}

}  // namespace

int run_dyn_command(plugin::CommandContext& context) {
  po::options_description desc("gearkit dyn options");
  po::positional_options_description positional;
  io::add_positional_argument(desc, positional, "file", "FILE", "machine model (YAML, see docs/dyn.md)");
  desc.add_options()
      ("plot", po::value<std::string>()->value_name("FILE.svg"),
       "write the torque-angle diagram with its energy areas (flywheel), or else the speed-time plot, as SVG")
      ("speed-plot", po::value<std::string>()->value_name("FILE.svg"), "write the speed-time plot (motion) as SVG");
  io::add_common_options(desc);
  po::variables_map vm;
  if (!io::parse_command_line(context.args, desc, positional, vm, usage, context.out)) return 0;
  const io::CommonOptions common = io::common_options(vm);

  const Model model = load_model(vm["file"].as<std::string>(),
                                 [&context](std::string_view type) { return context.host.find_element_type(type); });
  Output out;
  out.report.title = "Machine dynamics: " + (model.title.empty() ? model.file : model.title);
  if (!model.title.empty()) out.report.json["title"] = model.title;
  if (model.has_drive_line) add_drive_line(model, out.report);
  if (model.flywheel) add_flywheel(model, out);
  if (model.energy) add_energy(model, out);
  if (model.motion) add_motion(model, out);
  if (model.reduced_force) add_reduced_force(model, out);

  io::OutputSet outputs(context.out);  // every file committed together, after the report renders
  if (vm.count("plot")) {
    const io::Plot* plot = out.torque_plot ? &*out.torque_plot : (out.speed_plot ? &*out.speed_plot : nullptr);
    if (!plot) io::fail_option("--plot", "this model asks for no flywheel or motion, so there is nothing to plot");
    outputs.add("--plot", vm["plot"].as<std::string>(), io::to_svg(*plot));
  }
  if (vm.count("speed-plot")) {
    if (!out.speed_plot) io::fail_option("--speed-plot", "this model has no 'motion' question, so no speed to plot");
    outputs.add("--speed-plot", vm["speed-plot"].as<std::string>(), io::to_svg(*out.speed_plot));
  }
  return io::emit(out.report, common, outputs);
}

}  // namespace gearkit::plugins::dyn
