// `gearkit gear ...`: the gear table of a cylindrical involute pair (libgear) with its checks,
// measurements and, on request, the tooth-form drawing (SVG/DXF).
#include "gear_command.hpp"

#include "gear_options.hpp"
#include "gear_report.hpp"
#include "gear_tolerance_options.hpp"
#include "gear_tolerance_report.hpp"

#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/io/atomic_file.hpp>
#include <gearkit/io/command_line.hpp>
#include <gearkit/io/drawing.hpp>
#include <gearkit/io/error.hpp>

#include <fmt/format.h>

namespace gearkit::plugins::gear {

namespace gg = gearkit::gear;

namespace {

constexpr std::string_view kUsage =
    "gearkit gear --z1 N --z2 N --module LEN [--pressure-angle 20] [--helix-angle 0] "
    "[--x1 X --x2 X | --centre-distance LEN [--x1 X | --split balanced|proportional]] [--internal] [--transverse] "
    "[--face-width LEN] [--backlash LEN | --allowance1 LEN --allowance2 LEN] [--centre-distance-deviation LEN] "
    "[--pin-diameter LEN] [--quality Q[,Q2] [--iso1328-edition 2013|1995]] "
    "[--thickness-allowances1 UP,LOW --thickness-allowances2 UP,LOW | --din3967 27cd[,26cd]] [--min-backlash LEN] "
    "[--centre-distance-tolerance jsN | --centre-distance-allowances UP,LOW] [--temperature T[,T_HOUSING] "
    "[--expansion A1,A2,AH]] [--format text|json|csv|md] [--svg FILE] [--dxf FILE] [--draw pair|gear1|gear2]";

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

}  // namespace

int run_gear_command(kin::CommandContext& context) {
  io::po::options_description desc("gearkit gear options (bare numbers: mm and deg)");
  add_gear_options(desc);
  add_tolerance_options(desc);
  io::add_common_options(desc);
  io::po::positional_options_description none;
  io::po::variables_map vm;
  if (!io::parse_command_line(with_centre_spelling(context.args), desc, none, vm, kUsage, context.out)) return 0;
  const GearCommandOptions options = read_gear_options(vm);
  const std::optional<gg::InspectionInput> inspection_input = read_tolerance_options(vm);
  const io::CommonOptions common = io::common_options(vm);

  gg::GearPairResult result;
  try {
    result = gg::compute_gear_pair(options.input);
  } catch (const gg::GeometryError& e) {
    io::fail_option(fmt::format("--{}", option_for_field(e.field())), e.what());
  }

  std::optional<gg::InspectionResult> inspection;
  if (inspection_input) inspection = inspect(options.input, result, *inspection_input, vm);

  io::OutputSet outputs(context.out);  // every file committed together, after the report renders
  if (!options.svg.empty() || !options.dxf.empty()) {
    const io::Drawing drawing = gear_drawing(options.input, result, options.draw);
    if (!options.svg.empty()) {
      io::SvgOptions svg;
      svg.title = fmt::format("gearkit gear: z1 = {}, z2 = {}", options.input.z1, options.input.z2);
      outputs.add("--svg", options.svg, io::to_svg(drawing, svg));
    }
    if (!options.dxf.empty()) outputs.add("--dxf", options.dxf, io::to_dxf(drawing));
  }
  io::Report report = gear_report(options.input, result);
  if (inspection) add_inspection_report(report, *inspection);
  return io::emit(report, common, outputs);
}

}  // namespace gearkit::plugins::gear
