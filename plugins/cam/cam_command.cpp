// `gearkit cam FILE.yaml`: a cam from its motion program (libcam): checks, profile by CGAL
// offsets, and DXF/SVG/CSV/plot export for manufacturing.
#include "cam_command.hpp"

#include "cam_export.hpp"
#include "cam_model.hpp"
#include "cam_report.hpp"

#include <gearkit/io/atomic_file.hpp>
#include <gearkit/io/command_line.hpp>
#include <gearkit/io/error.hpp>
#include <gearkit/io/quantity.hpp>

#include <fmt/format.h>

#include <algorithm>

namespace gearkit::plugins::cam {

namespace gc = gearkit::cam;

namespace {

constexpr std::string_view kUsage =
    "gearkit cam FILE.yaml [--dxf FILE] [--dxf-lines-arcs] [--svg FILE] [--follower-at ANGLE] [--plot FILE] "
    "[--csv FILE] [--cutter-radius LEN] [--format text|json|csv|md]";

struct Options {
  std::string file, dxf, svg, plot, csv;
  bool dxf_lines_arcs = false;
  std::optional<double> cutter_radius_mm;
  std::optional<double> follower_at;
};

Options read_options(const io::po::variables_map& vm) {
  Options o;
  o.file = vm["file"].as<std::string>();
  for (auto [key, target] : {std::pair{"dxf", &o.dxf}, {"svg", &o.svg}, {"plot", &o.plot}, {"csv", &o.csv}})
    if (vm.count(key)) *target = vm[key].as<std::string>();
  o.dxf_lines_arcs = vm.count("dxf-lines-arcs") > 0;
  auto quantity = [&](const char* key, io::Quantity q, const char* unit) -> std::optional<double> {
    if (!vm.count(key)) return std::nullopt;
    try {
      return io::parse_quantity_si(vm[key].as<std::string>(), q, unit);
    } catch (const io::QuantityError& e) {
      io::fail_option(fmt::format("--{}", key), e.what());
    }
  };
  if (const auto rc = quantity("cutter-radius", io::Quantity::length, "mm")) {
    if (!(*rc > 0)) io::fail_option("--cutter-radius", fmt::format("expected a radius > 0, found {} mm", *rc * 1000));
    o.cutter_radius_mm = *rc * 1000;
  }
  o.follower_at = quantity("follower-at", io::Quantity::angle, "deg");
  return o;
}

}  // namespace

int run_cam_command(plugin::CommandContext& context) {
  io::po::options_description desc("gearkit cam options (bare numbers: mm and deg)");
  desc.add_options()
      ("file", io::po::value<std::string>()->required(), "cam model (YAML, see docs/cam.md)")
      ("dxf", io::po::value<std::string>(), "write the cam (profile, pitch curve, base circle, tool path) as DXF R2000")
      ("dxf-lines-arcs", "write LINE and ARC entities instead of LWPOLYLINE bulges (still DXF R2000)")
      ("svg", io::po::value<std::string>(), "write an SVG drawing of the cam and its follower")
      ("follower-at", io::po::value<std::string>(), "cam angle of the follower in the SVG drawing (default 0 deg)")
      ("plot", io::po::value<std::string>(), "write the s-v-a-j diagrams as SVG")
      ("csv", io::po::value<std::string>(), "write profile points and motion diagrams as CSV")
      ("cutter-radius", io::po::value<std::string>(), "cutter radius for the tool path (e.g. 8 mm)");
  io::add_common_options(desc);
  io::po::positional_options_description positional;
  positional.add("file", 1);
  io::po::variables_map vm;
  if (!io::parse_command_line(context.args, desc, positional, vm, kUsage, context.out)) return 0;
  const Options options = read_options(vm);
  const io::CommonOptions common = io::common_options(vm);

  CamModel model = load_cam_model(options.file);
  if (options.cutter_radius_mm) model.cutter_radius_mm = options.cutter_radius_mm;
  if (options.follower_at) model.follower_at = *options.follower_at;

  CamResult result;
  result.checks = gc::check_design(model.design, {std::max(3600, model.samples), model.pressure_angle_limit});
  try {
    result.profile = gc::synthesize_profile(model.design, {model.tolerance_mm, model.cutter_radius_mm});
  } catch (const gc::GeometryError& e) {
    io::fail_at(io::SourceMark{options.file, 0, 0}, fmt::format("cannot build the cam profile: {}", e.what()));
  }
  // The largest distance of the exported arcs from the analytic profile, found during the fit;
  // where the offset folds (undercut) the trimmed-away part has no analytic counterpart.
  result.deviation_mm = result.profile.profile_error;
  result.jumps = gc::continuity_check(model.design.program);
  result.samples = sample_turn(model);

  io::OutputSet outputs(context.out);  // every file committed together, after the report renders
  if (!options.dxf.empty()) {
    io::DxfOptions dxf;
    dxf.lines_and_arcs_only = options.dxf_lines_arcs;
    outputs.add("--dxf", options.dxf, io::to_dxf(cam_drawing(model, result.profile, false), dxf));
  }
  if (!options.svg.empty()) {
    io::SvgOptions svg;
    svg.title = fmt::format("gearkit cam: {}", model.name.empty() ? options.file : model.name);
    outputs.add("--svg", options.svg, io::to_svg(cam_drawing(model, result.profile, true), svg));
  }
  if (!options.plot.empty()) outputs.add("--plot", options.plot, io::to_svg(motion_plot(model, result.samples)));
  if (!options.csv.empty()) outputs.add("--csv", options.csv, motion_csv(model, result.samples));

  return io::emit(cam_report(model, result, options.file), common, outputs);
}

}  // namespace gearkit::plugins::cam
