// `gearkit cam FILE.yaml`: a cam from its motion program (libcam): checks, profile by CGAL
// offsets, follower dynamics, and DXF/SVG/CSV/plot/G-code export for manufacturing.
#include "cam_command.hpp"

#include "cam_export.hpp"
#include "cam_gcode.hpp"
#include "cam_model.hpp"
#include "cam_report.hpp"
#include "cam_sheet.hpp"

#include <gearkit/io/command_line.hpp>
#include <gearkit/io/error.hpp>
#include <gearkit/io/output.hpp>
#include <gearkit/io/quantity.hpp>

#include <fmt/format.h>

#include <algorithm>

namespace gearkit::plugins::cam {

namespace gc = gearkit::cam;

namespace {

constexpr std::string_view kUsage =
    "gearkit cam FILE.yaml [--dxf FILE] [--svg FILE] [--plot FILE] [--csv FILE] [--dynamics-plot FILE] "
    "[--gcode FILE] [options] (all options: gearkit cam --help)";

struct Options {
  std::string file, dxf, svg, plot, csv, dynamics_plot, dyn, gcode;
  bool dxf_lines_arcs = false;
  std::optional<double> cutter_radius_mm;
  std::optional<double> follower_at;
  std::optional<double> jump_margin;
  GcodeOptions gcode_options;
};

Options read_options(const io::po::variables_map& vm) {
  Options o;
  o.file = vm["file"].as<std::string>();
  for (auto [key, target] : {std::pair{"dxf", &o.dxf}, {"svg", &o.svg}, {"plot", &o.plot}, {"csv", &o.csv},
                             {"dynamics-plot", &o.dynamics_plot}, {"dyn", &o.dyn}, {"gcode", &o.gcode}})
    if (vm.count(key)) *target = vm[key].as<std::string>();
  o.dxf_lines_arcs = vm.count("dxf-lines-arcs") > 0;
  const io::OptionRange radius{0, kMaxLengthMm, true, false, "a radius > 0 and up to 10000 mm"};
  if (const auto rc = io::quantity_option(vm, "cutter-radius", io::Quantity::length, "mm", radius))
    o.cutter_radius_mm = *rc * 1000;
  o.follower_at = io::quantity_option(vm, "follower-at", io::Quantity::angle, "deg");
  if (vm.count("jump-margin")) o.jump_margin = vm["jump-margin"].as<double>();
  if (vm.count("gcode-form")) {
    const std::string form = vm["gcode-form"].as<std::string>();
    if (form != "xy" && form != "polar") io::fail_option("--gcode-form", fmt::format("expected xy or polar, found {}", io::quote(form)));
    o.gcode_options.polar = form == "polar";
  }
  const io::OptionRange feed_range{0, 60000, true, false, "a feed > 0 and up to 60000 mm/min"};
  if (const auto feed = io::quantity_option(vm, "feed", io::Quantity::velocity, "mm/min", feed_range))
    o.gcode_options.feed_mm_min = *feed * 60000;
  return o;
}

/// Checks, profile(s), continuity and dynamics of the model.
CamResult analyse(const CamModel& model, const std::string& file) {
  CamResult result;
  const gc::CheckOptions checks{std::max(3600, model.samples), model.pressure_angle_limit};
  result.checks = gc::check_design(model.design, checks);
  const gc::ProfileOptions profile{model.tolerance_mm, model.cutter_radius_mm};
  try {
    result.profile = gc::synthesize_profile(model.design, profile);
    if (model.design.follower.closure == gc::Closure::conjugate)
      result.second_profile = gc::synthesize_profile(gc::conjugate_cam_of(model.design), profile);
  } catch (const gc::GeometryError& e) {
    io::fail_at(io::SourceMark{file, 0, 0}, fmt::format("cannot build the cam profile: {}", e.what()));
  }
  if (model.design.follower.closure == gc::Closure::groove)
    result.other_checks = gc::check_design(gc::outer_wall_of(model.design), checks);
  if (model.design.follower.closure == gc::Closure::conjugate)
    result.other_checks = gc::check_design(gc::conjugate_cam_of(model.design), checks);
  // The largest distance of the exported arcs from the analytic profile, found during the fit;
  // where the offset folds (undercut) the trimmed-away part has no analytic counterpart.
  result.deviation_mm = result.profile.profile_error;
  result.jumps = gc::continuity_check(model.design.program);
  result.samples = sample_turn(model);
  if (model.dynamics) result.dynamics = analyse_dynamics(model);
  return result;
}

/// What a groove or the G-code needs of the cutter.
void check_cutter(const CamModel& model, const Options& options) {
  if (model.design.follower.closure == gc::Closure::groove && model.cutter_radius_mm &&
      *model.cutter_radius_mm > model.design.follower.roller_radius) {
    const std::string why = fmt::format("a groove cam is cut from inside its groove: expected a cutter radius up to the "
                                        "roller radius {:.6g} mm, found {:.6g} mm",
                                        model.design.follower.roller_radius, *model.cutter_radius_mm);
    if (options.cutter_radius_mm) io::fail_option("--cutter-radius", why);
    io::fail_at(model.cutter_radius_mark, fmt::format("'cutter_radius': {}", why));
  }
  if (!options.gcode.empty() && !model.cutter_radius_mm)
    io::fail_option("--gcode", "expected a cutter radius (--cutter-radius or output.cutter_radius): G-code is the cutter's path");
  if ((!options.dynamics_plot.empty() || !options.dyn.empty()) && !model.dynamics)
    io::fail_option(options.dyn.empty() ? "--dynamics-plot" : "--dyn", "expected a dynamics: section in the model");
}

void add_exports(const CamModel& model, const CamResult& result, const io::Report& report, const Options& options,
                 io::OutputSet& outputs) {
  if (!options.dxf.empty()) {
    io::DxfOptions dxf;
    dxf.lines_and_arcs_only = options.dxf_lines_arcs;
    outputs.add("--dxf", options.dxf, io::to_dxf(cam_sheet(model, result, report, 0.0), dxf));
  }
  if (!options.svg.empty()) {
    io::SvgOptions svg;
    svg.title = fmt::format("gearkit cam: {}", model.name.empty() ? options.file : model.name);
    outputs.add("--svg", options.svg, io::to_svg(cam_sheet(model, result, report, model.follower_at), svg));
  }
  if (!options.plot.empty()) outputs.add("--plot", options.plot, io::to_svg(motion_plot(model, result.samples)));
  const CamDynamics* dyn = result.dynamics ? &*result.dynamics : nullptr;
  if (!options.csv.empty()) outputs.add("--csv", options.csv, motion_csv(model, result.samples, dyn));
  if (!options.dynamics_plot.empty()) outputs.add("--dynamics-plot", options.dynamics_plot, io::to_svg(dynamics_plot(model, *dyn)));
  if (!options.dyn.empty()) outputs.add("--dyn", options.dyn, dyn_model(model, *dyn, options.file));
  if (!options.gcode.empty()) outputs.add("--gcode", options.gcode, cam_gcode(model, result, options.gcode_options, options.file));
}

}  // namespace

int run_cam_command(plugin::CommandContext& context) {
  io::po::options_description desc("gearkit cam options");
  io::po::positional_options_description positional;
  io::add_positional_argument(desc, positional, "file", "FILE", "cam model (YAML, see docs/cam.md)");
  desc.add_options()
      ("dxf", io::po::value<std::string>()->value_name("FILE.dxf"),
       "write the cam (profile, pitch curve, base circle, tool path) as DXF R2000")
      ("dxf-lines-arcs", "write LINE and ARC entities instead of LWPOLYLINE bulges (still DXF R2000)")
      ("svg", io::po::value<std::string>()->value_name("FILE.svg"), "write an SVG drawing of the cam and its follower")
      ("follower-at", io::po::value<std::string>()->value_name("ANGLE"),
       "cam angle of the follower in the SVG drawing (default 0 deg) (bare number: deg)")
      ("plot", io::po::value<std::string>()->value_name("FILE.svg"), "write the s-v-a-j diagrams as SVG")
      ("csv", io::po::value<std::string>()->value_name("FILE.csv"), "write profile points, motion diagrams (and forces) as CSV")
      ("cutter-radius", io::po::value<std::string>()->value_name("LEN"), "cutter radius for the tool path (bare number: mm)")
      ("dynamics-plot", io::po::value<std::string>()->value_name("FILE.svg"),
       "write contact force, camshaft torque and Hertz stress as SVG")
      ("dyn", io::po::value<std::string>()->value_name("FILE.yaml"), "write the camshaft as a `gearkit dyn` model (flywheel)")
      ("jump-margin", io::po::value<double>()->value_name("FACTOR"),
       "size the spring to hold the follower up to FACTOR x the design speed (default: dynamics.jump_margin, else 1)")
      ("gcode", io::po::value<std::string>()->value_name("FILE.ngc"), "write the cutter-centre path as G-code (RS-274/NGC)")
      ("gcode-form", io::po::value<std::string>()->value_name("xy|polar"),
       "xy (2-axis mill, G2/G3 arcs; default) or polar (rotary table: X radius, C angle)")
      ("feed", io::po::value<std::string>()->value_name("RATE"),
       "G-code feed rate (default 200 mm/min) (unit required, e.g. 200mm/min)");
  io::add_common_options(desc);
  io::po::variables_map vm;
  if (!io::parse_command_line(context.args, desc, positional, vm, kUsage, context.out)) return 0;
  const Options options = read_options(vm);
  const io::CommonOptions common = io::common_options(vm);

  CamModel model = load_cam_model(options.file);
  if (options.cutter_radius_mm) model.cutter_radius_mm = options.cutter_radius_mm;
  if (options.follower_at) model.follower_at = *options.follower_at;
  if (options.jump_margin) {
    if (!model.dynamics) io::fail_option("--jump-margin", "expected a dynamics: section in the model (the margin sizes its spring)");
    if (const auto problem = jump_margin_problem(model.dynamics->design_speed, *options.jump_margin))
      io::fail_option("--jump-margin", *problem);
    model.dynamics->jump_margin = *options.jump_margin;
  }
  check_cutter(model, options);
  const CamResult result = analyse(model, options.file);

  const io::Report report = cam_report(model, result, options.file);
  io::OutputSet outputs(context.out);  // every file committed together, after the report renders
  add_exports(model, result, report, options, outputs);
  return io::emit(report, common, outputs);
}

}  // namespace gearkit::plugins::cam
