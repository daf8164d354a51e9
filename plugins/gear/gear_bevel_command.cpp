// `gearkit gear bevel`: options -> gearkit::gear::BevelPairInput, table, forces, report.
#include "gear_bevel_command.hpp"

#include "gear_bevel_drawing.hpp"
#include "gear_bevel_report.hpp"

#include <gearkit/gear/bevel.hpp>
#include <gearkit/io/command_line.hpp>
#include <gearkit/io/error.hpp>
#include <gearkit/io/output.hpp>

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace gearkit::plugins::gear {

namespace gg = gearkit::gear;

namespace {

constexpr std::string_view kUsage =
    "gearkit gear bevel --z1 N --z2 N --module LEN --face-width LEN [--shaft-angle 90] [--pressure-angle 20] "
    "[--type straight|zerol|spiral [--spiral-angle ANGLE --hand1 left|right]] [--system gleason|iso23509] [--x1 X] "
    "[--depth standard|constant-clearance|uniform] [--torque1 TORQUE | --torque2 TORQUE [--rotation1 ccw|cw]] "
    "[--svg FILE] [--dxf FILE] [--format text|json|csv|md|html] [--output FILE] [--strict]";

[[noreturn]] void fail(std::string_view key, std::string_view message) { io::fail_option(fmt::format("--{}", key), message); }

std::string text_of(const io::po::variables_map& vm, const char* key) { return vm[key].as<std::string>(); }

// A word from a closed list: its index, or a refusal naming the accepted words.
std::size_t choice(const io::po::variables_map& vm, const char* key, const std::vector<std::string>& words) {
  const std::string v = text_of(vm, key);
  for (std::size_t i = 0; i < words.size(); ++i)
    if (v == words[i]) return i;
  std::string list;
  for (const auto& w : words) list += (list.empty() ? "" : ", ") + w;
  fail(key, fmt::format("expected one of {}, found '{}'", list, v.substr(0, 60)));
}

double length_mm(const io::po::variables_map& vm, const char* key) { return *io::quantity_option(vm, key, io::Quantity::length, "mm") * 1e3; }

double angle_rad(const io::po::variables_map& vm, const char* key) { return *io::quantity_option(vm, key, io::Quantity::angle, "deg"); }

int teeth(const io::po::variables_map& vm, const char* key) {
  if (!vm.count(key)) fail(key, "is required: the number of teeth");
  return vm[key].as<int>();
}

gg::BevelPairInput read_pair(const io::po::variables_map& vm) {
  gg::BevelPairInput in;
  in.z1 = teeth(vm, "z1");
  in.z2 = teeth(vm, "z2");
  if (!vm.count("module")) fail("module", "is required: the outer transverse module m_et");
  in.m_et = length_mm(vm, "module");
  if (!vm.count("face-width")) fail("face-width", "is required: the face width b (Gleason/KHK: at most R_e/3 and 10 m_et)");
  in.b = length_mm(vm, "face-width");
  if (vm.count("shaft-angle")) in.Sigma = angle_rad(vm, "shaft-angle");
  if (vm.count("pressure-angle")) in.alpha_n = angle_rad(vm, "pressure-angle");
  if (vm.count("type")) in.type = static_cast<gg::BevelType>(choice(vm, "type", {"straight", "zerol", "spiral"}));
  if (vm.count("spiral-angle")) {
    if (in.type != gg::BevelType::spiral) fail("spiral-angle", "needs --type spiral (straight and Zerol bevels have beta_m = 0)");
    in.beta_m = angle_rad(vm, "spiral-angle");
  } else if (in.type == gg::BevelType::spiral) {
    fail("spiral-angle", "is required with --type spiral: the mean spiral angle beta_m (e.g. 35)");
  }
  if (vm.count("hand1")) {
    if (in.type != gg::BevelType::spiral) fail("hand1", "applies to spiral bevels only (--type spiral)");
    in.hand1 = choice(vm, "hand1", {"right", "left"}) == 0 ? gg::SpiralHand::right : gg::SpiralHand::left;
  } else if (in.type == gg::BevelType::spiral) {
    fail("hand1", "is required with --type spiral: the hand of gear 1's spiral, left or right");
  }
  if (vm.count("system")) in.system = choice(vm, "system", {"gleason", "iso23509"}) == 0 ? gg::BevelSystem::gleason : gg::BevelSystem::iso23509;
  if (vm.count("depth")) in.taper = static_cast<gg::DepthTaper>(choice(vm, "depth", {"standard", "constant-clearance", "uniform"}));
  if (vm.count("x1")) in.x1 = vm["x1"].as<double>();
  return in;
}

std::optional<gg::BevelLoad> read_load(const io::po::variables_map& vm, const gg::BevelPairInput& in) {
  const bool t1 = vm.count("torque1") > 0, t2 = vm.count("torque2") > 0;
  if (t1 && t2) fail("torque2", "cannot be combined with --torque1: give the torque of the driving gear only");
  if (!t1 && !t2) {
    if (vm.count("rotation1")) fail("rotation1", "needs the load: give --torque1 or --torque2");
    return std::nullopt;
  }
  gg::BevelLoad load;
  load.driver = t1 ? 1 : 2;
  const char* key = t1 ? "torque1" : "torque2";
  load.T = *io::quantity_option(vm, key, io::Quantity::torque, "N*m");
  if (!(load.T > 0.0)) fail(key, fmt::format("expected a torque > 0 (the driving gear's), found '{}'", text_of(vm, key).substr(0, 60)));
  if (vm.count("rotation1")) {
    load.rotation1 = choice(vm, "rotation1", {"ccw", "cw"}) == 0 ? gg::Rotation::ccw : gg::Rotation::cw;
  } else if (in.type == gg::BevelType::spiral) {
    fail("rotation1", "is required for the forces of a spiral bevel: the sense of gear 1 seen from its back, ccw or cw");
  }
  return load;
}

std::string option_for_field(const std::string& field) {
  if (field == "shaft_angle") return "shaft-angle";
  if (field == "pressure_angle") return "pressure-angle";
  if (field == "face_width") return "face-width";
  if (field == "spiral_angle") return "spiral-angle";
  return field;  // z1, z2, module, x1
}

void add_options(io::po::options_description& desc) {
  auto text = [] { return io::po::value<std::string>(); };
  desc.add_options()("z1", io::po::value<int>()->value_name("N"), "teeth of gear 1 (the pinion)")
      ("z2", io::po::value<int>()->value_name("N"), "teeth of gear 2 (the wheel)")
      ("module", text()->value_name("LEN"), "outer transverse module m_et (bare number: mm)")
      ("face-width", text()->value_name("LEN"), "face width b (bare number: mm)")
      ("shaft-angle", text()->value_name("ANGLE"), "shaft angle Sigma, default 90 (bare number: deg)")
      ("pressure-angle", text()->value_name("ANGLE"), "normal pressure angle alpha_n, default 20 (bare number: deg)")
      ("type", text()->value_name("TYPE"), "straight (default), zerol or spiral")
      ("spiral-angle", text()->value_name("ANGLE"), "mean spiral angle beta_m of a spiral bevel (bare number: deg)")
      ("hand1", text()->value_name("HAND"), "hand of gear 1's spiral: left or right (gear 2 has the other)")
      ("system", text()->value_name("SYSTEM"), "tooth proportions: gleason (default; outer end, unequal addendum) or iso23509 (mean point, profile shift)")
      ("x1", io::po::value<double>()->value_name("X"), "gleason: addendum modification x_he1 at the outer end (default: the Gleason formula); "
                                                       "iso23509: profile shift x_hm1 at the mean point (default 0); x2 = -x1")
      ("depth", text()->value_name("TAPER"), "tooth depth along the face: constant-clearance (default), standard or uniform")
      ("torque1", text()->value_name("TORQUE"), "forces: torque on gear 1, which drives (unit required, e.g. 50N*m)")
      ("torque2", text()->value_name("TORQUE"), "forces: torque on gear 2, which drives, instead of --torque1 (unit required, e.g. 50N*m)")
      ("rotation1", text()->value_name("SENSE"), "forces: sense of gear 1 seen from its back, ccw (default) or cw; required for spiral bevels")
      ("svg", text()->value_name("FILE"), "write the pair in axial section with its data block as SVG")
      ("dxf", text()->value_name("FILE"), "write the same drawing as DXF (AutoCAD 2000, mm)");
}

}  // namespace

int run_gear_bevel_command(plugin::CommandContext& context) {
  io::po::options_description desc("gearkit gear bevel options");
  add_options(desc);
  io::add_common_options(desc);
  io::po::positional_options_description none;
  io::po::variables_map vm;
  const std::vector<std::string> args(context.args.begin() + 1, context.args.end());
  if (!io::parse_command_line(args, desc, none, vm, kUsage, context.out)) return 0;
  const gg::BevelPairInput input = read_pair(vm);
  const std::optional<gg::BevelLoad> load = read_load(vm, input);
  const io::CommonOptions common = io::common_options(vm);
  gg::BevelPairResult result;
  std::optional<gg::BevelForces> forces;
  try {
    result = gg::compute_bevel_pair(input);
    if (load) forces = gg::bevel_forces(input, result, *load);
  } catch (const gg::GeometryError& e) {
    fail(option_for_field(e.field()), e.what());
  }
  io::OutputSet outputs(context.out);  // the drawings and the report committed together
  if (vm.count("svg") || vm.count("dxf")) {
    const io::Drawing drawing = bevel_drawing(input, result);
    if (vm.count("svg")) {
      io::SvgOptions svg;
      svg.title = fmt::format("gearkit gear bevel: z1 = {}, z2 = {}", input.z1, input.z2);
      outputs.add("--svg", text_of(vm, "svg"), io::to_svg(drawing, svg));
    }
    if (vm.count("dxf")) outputs.add("--dxf", text_of(vm, "dxf"), io::to_dxf(drawing));
  }
  return io::emit(bevel_report(input, result, forces), common, outputs);
}

}  // namespace gearkit::plugins::gear
