// `gearkit gear ...`: the gear table of a cylindrical involute pair (libgear) with its checks,
// measurements, accuracy and inspection data, on request the load capacity (ISO 6336, AGMA,
// Lewis/Hertz) and the tooth-form drawing (SVG/DXF); the pair from options or from a gear-pair
// file; `gearkit gear size`.
#include "gear_command.hpp"
#include "gear_bevel_command.hpp"

#include "gear_drawing.hpp"

#include "gear_options.hpp"
#include "gear_pair_file.hpp"
#include "gear_rating_options.hpp"
#include "gear_rating_report.hpp"
#include "gear_rating_yaml.hpp"
#include "gear_report.hpp"
#include "gear_size.hpp"
#include "gear_tolerance_options.hpp"
#include "gear_tolerance_report.hpp"
#include "gear_types_commands.hpp"

#include <gearkit/gear/accuracy.hpp>
#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/gear/inspection.hpp>
#include <gearkit/gear/rating.hpp>
#include <gearkit/io/atomic_file.hpp>
#include <gearkit/io/command_line.hpp>
#include <gearkit/io/drawing.hpp>
#include <gearkit/io/limits.hpp>
#include <gearkit/io/error.hpp>

#include <fmt/format.h>

#include <optional>
#include <set>

namespace gearkit::plugins::gear {

namespace gg = gearkit::gear;

namespace {

constexpr std::string_view kUsage =
    "gearkit gear [PAIR.yaml] --z1 N --z2 N --module LEN [--ratio U] [--pressure-angle 20] [--helix-angle 0] "
    "[--x1 X --x2 X | --centre-distance LEN [--x1 X | --split balanced|proportional|min-shift [--undercut-limit "
    "iso|practical]]] [--radii] [--internal] [--transverse] "
    "[--face-width LEN | --face-width1 LEN --face-width2 LEN [--face-offset LEN]] [--rack1 H_aP,H_fP,RHO_fP] [--rack2 ...] [--tip-diameter1 D] [--root-diameter1 D] [--backlash LEN | --allowance1 LEN --allowance2 LEN] [--centre-distance-deviation LEN] "
    "[--pin-diameter LEN] [--quality Q[,Q2] [--iso1328-edition 2013|1995]] "
    "[--thickness-allowances1 UP,LOW --thickness-allowances2 UP,LOW | --din3967 27cd[,26cd]] [--min-backlash LEN] "
    "[--centre-distance-tolerance jsN | --centre-distance-allowances UP,LOW] [--temperature T[,T_HOUSING] "
    "[--expansion A1,A2,AH]] [--torque1 TORQUE | --torque2 TORQUE | --power POWER --speed1 SPEED --material1 M --material2 M "
    "[--method iso6336|agma|lewis-hertz] [--factor NAME=VALUE]...] [--format text|json|csv|md|html] [--svg FILE] [--dxf FILE] "
    "[--draw pair|gear1|gear2] [--tolerance LEN] [--cutter-teeth N] [--cutter-tip-radius LEN]\n       gearkit gear size --help";

// gearkit 0.1 spelled two options the American way; the old names stay accepted for one release
// (docs/gear.md) and are read as the new ones.
std::vector<std::string> with_centre_spelling(std::vector<std::string> args) {
  for (std::string& a : args)
    for (std::string_view old : {"--center-distance-deviation", "--center-distance"})
      if (a.starts_with(old) && (a.size() == old.size() || a[old.size()] == '=')) {
        a.replace(0, std::string_view("--center-").size(), "--centre-");
        break;
      }
  return args;
}

// The inspection analysis; its errors name the option the user gave for the field at fault.
gg::InspectionResult inspect(const gg::GearPairInput& input, const gg::GearPairResult& table,
                             const gg::InspectionInput& inspection, const io::po::variables_map& vm) {
  try {
    return gg::compute_inspection(input, table, inspection);
  } catch (const gg::GeometryError& e) {
    std::string option = tolerance_option_for_field(e.field());
    if (option == "centre-distance-allowances" && vm.count(option) == 0) {
      option = vm.count("centre-distance-tolerance") ? "centre-distance-tolerance" : "quality";
    }
    io::fail_option(fmt::format("--{}", option.empty() ? e.field() : option), e.what());
  }
}

// The pair, its inspection and its load, from the options or from a pair file.
struct Request {
  GearCommandOptions options;
  std::optional<gg::InspectionInput> inspection;
  std::optional<gg::RatingInput> rating;
  std::optional<PairFile> file;
};

Request read_request(const io::po::variables_map& vm) {
  Request q;
  if (vm.count("file")) {
    static const std::set<std::string> output = {"file", "format", "output", "strict", "svg", "dxf", "draw", "tolerance", "cutter-teeth", "cutter-tip-radius", "help"};
    for (const auto& [name, value] : vm) {
      if (!value.defaulted() && !output.count(name)) {
        io::fail_option(fmt::format("--{}", name), "cannot be combined with a gear-pair file (the file holds the pair and its load)");
      }
    }
    q.file = read_pair_file(vm["file"].as<std::string>());
    q.options.input = q.file->geometry;
    q.rating = q.file->rating;
    read_drawing_options(vm, q.options);
    return q;
  }
  q.options = read_gear_options(vm);
  q.inspection = read_tolerance_options(vm);
  // One allowance per gear: the inspection's (given, DIN 3967 or ISO/TR 10064-2) serves the root
  // rating too, so a second value from --allowance or --backlash would contradict it.
  if (q.inspection) {
    const char* source = vm.count("thickness-allowances1") ? "thickness-allowances1" : vm.count("thickness-allowances2") ? "thickness-allowances2"
                         : vm.count("din3967") ? "din3967" : "quality";
    for (const char* key : {"allowance1", "allowance2", "backlash"})
      if (vm.count(key))
        io::fail_option(fmt::format("--{}", key), fmt::format("cannot be combined with --{}: its tooth thickness allowances are the ones of the "
                                                              "inspection and of the root rating (give them with --thickness-allowances1/2)", source));
  }
  if (rating_requested(vm)) {
    q.rating = read_rating_options(vm);
  } else if (any_rating_option(vm)) {
    io::fail_option("--torque1", "the load-capacity options need the load: give --torque1 or --power (with --speed1)");
  }
  return q;
}

// The root rating's generating shift x_E from the upper allowances A_sne of the inspection, so
// that one allowance serves table, inspection and rating. A pair file with a grade and no
// allowance1/2 gets those of ISO/TR 10064-2 for its grade, as `--quality` does.
void root_allowances(const Request& q, const gg::GearPairResult& table, const gg::InspectionResult* inspection, gg::RatingInput& rating) {
  if (inspection) {
    for (int i = 0; i < 2; ++i) rating.A_sne[i] = inspection->gear[i].allowances.A_sne;
    return;
  }
  if (q.file) grade_allowances(*q.file, table, rating);
}

[[noreturn]] void fail_field(const Request& q, const std::string& option, const std::string& field, const std::string& message) {
  if (q.file) io::fail_at(mark_for_field(*q.file, field), message);
  io::fail_option(fmt::format("--{}", option), message);
}

// A drawing holds every tooth flank as a polyline: about 50 kB of memory per tooth.
void check_drawn_teeth(const GearCommandOptions& options) {
  const long long z1 = options.input.z1, z2 = std::abs(options.input.z2);
  const long long drawn = options.draw == "gear1" ? z1 : options.draw == "gear2" ? z2 : z1 + z2;
  if (drawn > io::limits::kDrawnTeeth)
    io::fail_option(options.svg.empty() ? "--dxf" : "--svg",
                    fmt::format("expected at most {} teeth to draw, found {} (--draw {}); draw one gear or none",
                                io::limits::kDrawnTeeth, drawn, options.draw));
}

void add_drawings(io::OutputSet& outputs, const GearCommandOptions& options, const gg::GearPairResult& result,
                  const gg::InspectionResult* inspection) {
  if (options.svg.empty() && options.dxf.empty()) return;
  check_drawn_teeth(options);
  const io::Drawing drawing = gear_drawing(options.input, result, options, inspection);
  if (!options.svg.empty()) {
    io::SvgOptions svg;
    svg.title = fmt::format("gearkit gear: z1 = {}, z2 = {}", options.input.z1, options.input.z2);
    outputs.add("--svg", options.svg, io::to_svg(drawing, svg));
  }
  if (!options.dxf.empty()) outputs.add("--dxf", options.dxf, io::to_dxf(drawing));
}

}  // namespace

int run_gear_command(plugin::CommandContext& context) {
  if (!context.args.empty() && context.args.front() == "size") return run_gear_size_command(context);
  if (!context.args.empty() && context.args.front() == "rack") return run_gear_rack_command(context);
  if (!context.args.empty() && context.args.front() == "worm") return run_gear_worm_command(context);
  if (!context.args.empty() && context.args.front() == "crossed") return run_gear_crossed_command(context);
  if (!context.args.empty() && context.args.front() == "bevel") return run_gear_bevel_command(context);
  io::po::options_description desc("gearkit gear options (bare numbers: mm and deg; rating: N*m, kW, rpm, h, um)");
  add_gear_options(desc);
  add_tolerance_options(desc);
  add_rating_options(desc);
  io::add_common_options(desc);
  io::po::positional_options_description positional;
  io::add_positional_argument(desc, positional, "file", "PAIR.yaml", "gear-pair file (docs/rating.md)", false);
  io::po::variables_map vm;
  if (!io::parse_command_line(with_centre_spelling(context.args), desc, positional, vm, kUsage, context.out)) return 0;
  const Request q = read_request(vm);
  const io::CommonOptions common = io::common_options(vm);

  gg::GearPairResult result;
  try {
    result = gg::compute_gear_pair(q.options.input);
  } catch (const gg::GeometryError& e) {
    fail_field(q, option_for_field(e.field()), e.field(), e.what());
  }
  std::optional<gg::InspectionResult> inspection;
  if (q.inspection) inspection = inspect(q.options.input, result, *q.inspection, vm);

  io::Report report = gear_report(q.options.input, result, q.options.radii);
  if (inspection) add_inspection_report(report, *inspection);
  if (!q.options.svg.empty() || !q.options.dxf.empty() || vm.count("cutter-teeth") || vm.count("cutter-tip-radius")) {
    add_ring_cutting_report(report, q.options.input, result, q.options);
  }
  if (q.rating) {
    gg::RatingInput rating = *q.rating;
    root_allowances(q, result, inspection ? &*inspection : nullptr, rating);
    try {
      add_rating_report(report, rating, gg::rate_gear_pair(q.options.input, result, rating));
    } catch (const gg::RatingError& e) {
      fail_field(q, option_for_rating_field(e.field()), e.field(), e.what());
    }
  }
  io::OutputSet outputs(context.out);  // every file committed together, after the report renders
  add_drawings(outputs, q.options, result, inspection ? &*inspection : nullptr);
  return io::emit(report, common, outputs);
}

}  // namespace gearkit::plugins::gear
