// `gearkit gear rack`: a pinion against a rack (libgear rack_pinion.hpp, docs/gear-types.md).
#include "gear_types_commands.hpp"
#include "gear_types_common.hpp"
#include "gear_types_drawing.hpp"

#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/gear/rack_pinion.hpp>
#include <gearkit/io/command_line.hpp>
#include <gearkit/io/drawing.hpp>
#include <gearkit/io/report.hpp>

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace gearkit::plugins::gear {

namespace gg = gearkit::gear;
using namespace types;

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

constexpr std::string_view kUsage =
    "gearkit gear rack --z1 N --module LEN [--pressure-angle 20] [--helix-angle 0] [--x1 X | --datum-distance LEN | "
    "--mounting-distance LEN --rack-height LEN] [--rack-height LEN] [--face-width LEN] [--addendum 1] [--dedendum 1.25] "
    "[--root-radius 0.38] [--allowance1 LEN] [--allowance2 LEN] [--pin-diameter1 LEN] [--pin-diameter2 LEN] [--travel LEN] "
    "[--torque1 TORQUE] [--speed1 SPEED] [--format text|json|csv|md|html]";

void add_options(io::po::options_description& desc) {
  auto text = [] { return io::po::value<std::string>(); };
  desc.add_options()
      ("z1", text()->value_name("N"), "teeth of the pinion")
      ("module", text()->value_name("LEN"), "normal module m_n (bare number: mm)")
      ("pressure-angle", text()->value_name("ANGLE"), "normal pressure angle (default 20 deg) (bare number: deg)")
      ("helix-angle", text()->value_name("ANGLE"), "helix angle of the pinion, > 0 right hand (default 0: spur) (bare number: deg)")
      ("x1", text()->value_name("X"), "profile shift coefficient of the pinion (default 0)")
      ("datum-distance", text()->value_name("LEN"), "distance H_0 of the rack's datum line from the pinion axis: sets x1 (bare number: mm)")
      ("mounting-distance", text()->value_name("LEN"), "distance of the rack's back from the pinion axis, with --rack-height: sets x1 (bare number: mm)")
      ("rack-height", text()->value_name("LEN"), "height of the rack's datum line above its back (bare number: mm)")
      ("face-width", text()->value_name("LEN"), "face width b (bare number: mm)")
      ("addendum", text()->value_name("COEF"), "rack addendum coefficient h_aP* (default 1)")
      ("dedendum", text()->value_name("COEF"), "rack dedendum coefficient h_fP* (default 1.25)")
      ("root-radius", text()->value_name("COEF"), "rack root radius coefficient rho_fP* (default 0.38)")
      ("allowance1", text()->value_name("LEN"), "normal tooth thickness allowance of the pinion (negative: thinner) (bare number: mm)")
      ("allowance2", text()->value_name("LEN"), "normal tooth thickness allowance of the rack (negative: thinner) (bare number: mm)")
      ("pin-diameter1", text()->value_name("LEN"), "pin/ball diameter for the pinion (default: contact at d + 2 x m_n) (bare number: mm)")
      ("pin-diameter2", text()->value_name("LEN"), "pin diameter for the rack (default: contact on the datum line) (bare number: mm)")
      ("travel", text()->value_name("LEN"), "rack travel: the shortest rack for it (bare number: mm)")
      ("torque1", text()->value_name("TORQUE"), "torque on the pinion, its sense from --speed1 (unit required, e.g. 9kN*m)")
      ("speed1", text()->value_name("SPEED"), "speed of the pinion about its axis, signed (--speed1=-100rpm) (unit required, e.g. 1450rpm)")
      ("svg", text()->value_name("FILE"), "write the drawing (pinion and rack with the datum line, data block) as SVG")
      ("dxf", text()->value_name("FILE"), "write the drawing as DXF");
}

gg::RackPinionInput read_input(const io::po::variables_map& vm) {
  gg::RackPinionInput in;
  in.z1 = required_whole(vm, "z1", 3, 100000, "pinion teeth");
  const auto m = length_mm(vm, "module");
  if (!m) fail("module", "expected the normal module, found none");
  in.m_n = *m;
  if (auto v = angle_rad(vm, "pressure-angle")) in.alpha_n = *v;
  if (auto v = angle_rad(vm, "helix-angle")) in.beta = *v;
  if (auto v = number(vm, "x1")) in.x1 = *v;
  const char* shift_options[] = {"x1", "datum-distance", "mounting-distance"};
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (vm.count(shift_options[i]) && vm.count(shift_options[j]))
        fail(shift_options[j], fmt::format("cannot be combined with --{}: both set the pinion's profile shift", shift_options[i]));
  in.H_0 = length_mm(vm, "datum-distance");
  in.rack_height = length_mm(vm, "rack-height");
  if (auto a = length_mm(vm, "mounting-distance")) {
    if (!in.rack_height) fail("mounting-distance", "needs --rack-height (the datum line's height above the rack's back)");
    in.H_0 = *a - *in.rack_height;
  }
  if (auto v = length_mm(vm, "face-width")) in.face_width = *v;
  if (auto v = number(vm, "addendum")) in.h_aP = *v;
  if (auto v = number(vm, "dedendum")) in.h_fP = *v;
  if (auto v = number(vm, "root-radius")) in.rho_fP = *v;
  if (auto v = length_mm(vm, "allowance1")) in.A_sn1 = *v;
  if (auto v = length_mm(vm, "allowance2")) in.A_sn2 = *v;
  in.pin_diameter1 = length_mm(vm, "pin-diameter1");
  in.pin_diameter2 = length_mm(vm, "pin-diameter2");
  in.travel = length_mm(vm, "travel");
  return in;
}

std::string option_for_field(const std::string& f, const io::po::variables_map& vm) {
  if (f == "m_n") return "module";
  if (f == "alpha_n") return "pressure-angle";
  if (f == "beta") return "helix-angle";
  if (f == "H_0") return vm.count("mounting-distance") ? "mounting-distance" : "datum-distance";
  if (f == "rack") return vm.count("root-radius") ? "root-radius" : vm.count("dedendum") ? "dedendum" : "addendum";
  if (f == "A_sn1") return "allowance1";
  if (f == "A_sn2") return "allowance2";
  if (f == "rack_height") return "rack-height";
  if (f == "face_width") return "face-width";
  if (f == "pin_diameter1") return "pin-diameter1";
  if (f == "pin_diameter2") return "pin-diameter2";
  return f;
}

void pinion_table(io::Report& report, const gg::RackPinionInput& in, const gg::RackPinionResult& r) {
  io::Table t{"Pinion", {"quantity", "value"}, {}};
  auto row = [&t](std::string name, std::string value) { t.add_row({std::move(name), std::move(value)}); };
  row("number of teeth z", std::to_string(in.z1));
  row("normal module m_n [mm]", num(in.m_n));
  row("transverse module m_t [mm]", num(r.m_t));
  row("pressure angle alpha_n [deg]", num(in.alpha_n * kDeg));
  row("transverse pressure angle alpha_t [deg]", num(r.alpha_t * kDeg));
  row("helix angle beta [deg]", num(in.beta * kDeg));
  row("helix hand", in.beta > 0.0 ? "right" : in.beta < 0.0 ? "left" : "spur");
  row("profile shift coefficient x", num(r.x1));
  row("reference diameter d [mm]", num(r.d));
  row("base diameter d_b [mm]", num(r.d_b));
  row("tip diameter d_a [mm]", num(r.d_a));
  row("root diameter d_f [mm]", num(r.d_f));
  row("normal tooth thickness s_n [mm]", num(r.s_n));
  row("normal tip thickness s_an [mm]", num(r.s_an));
  row("undercut limit x_min (ISO) / x'_min (practical)", fmt::format("{} / {}", num(r.x_min), num(r.x_min_practical)));
  row(fmt::format("span over k = {} teeth W_k [mm] (nominal / actual)", r.k_span), fmt::format("{} / {}", num(r.W_k), num(r.W_k_actual)));
  row(fmt::format("over 2 pins/balls of {} mm M_d [mm] (nominal / actual)", num(r.pin_diameter1, 3)), fmt::format("{} / {}", num(r.M_d), num(r.M_d_actual)));
  report.tables.push_back(std::move(t));
  report.json["pinion"] = {{"z", in.z1}, {"m_n_mm", jnum(in.m_n)}, {"m_t_mm", jnum(r.m_t)}, {"alpha_n_deg", jnum(in.alpha_n * kDeg)},
                           {"alpha_t_deg", jnum(r.alpha_t * kDeg)}, {"beta_deg", jnum(in.beta * kDeg)},
                           {"hand", in.beta > 0.0 ? "right" : in.beta < 0.0 ? "left" : "spur"}, {"x", jnum(r.x1)},
                           {"d_mm", jnum(r.d)}, {"d_b_mm", jnum(r.d_b)}, {"d_a_mm", jnum(r.d_a)}, {"d_f_mm", jnum(r.d_f)},
                           {"s_n_mm", jnum(r.s_n)}, {"s_an_mm", jnum(r.s_an)}, {"z_n", jnum(r.z_n)}, {"x_min", jnum(r.x_min)},
                           {"x_min_practical", jnum(r.x_min_practical)}, {"k_span", r.k_span}, {"W_k_mm", jnum(r.W_k)},
                           {"W_k_actual_mm", jnum(r.W_k_actual)}, {"pin_diameter_mm", jnum(r.pin_diameter1)},
                           {"M_d_mm", jnum(r.M_d)}, {"M_d_actual_mm", jnum(r.M_d_actual)}};
}

void rack_and_mesh_tables(io::Report& report, const gg::RackPinionInput& in, const gg::RackPinionResult& r) {
  io::Table t{"Rack", {"quantity", "value"}, {}};
  t.add_row({"transverse pitch p_t [mm]", num(r.p_t)});
  t.add_row({"addendum h_a / dedendum h_f from the datum line [mm]", fmt::format("{} / {}", num(r.h_a2), num(r.h_f2))});
  t.add_row({"normal space width on the datum line e_n [mm]", num(r.e_n2)});
  t.add_row({fmt::format("over a pin of {} mm, from the datum line [mm] (nominal / actual)", num(r.pin_diameter2, 3)),
             fmt::format("{} / {}", num(r.M_r), num(r.M_r_actual))});
  if (in.rack_height) t.add_row({"over the pin from the rack's back [mm]", num(r.M_r_back)});
  if (in.travel) t.add_row({fmt::format("shortest rack for a travel of {} mm [mm]", num(*in.travel, 1)), fmt::format("{} ({} teeth)", num(r.rack_length, 3), r.rack_teeth)});
  report.tables.push_back(std::move(t));
  io::Table m{"Mesh", {"quantity", "value"}, {}};
  m.add_row({"datum line from the pinion axis H_0 [mm]", num(r.H_0)});
  if (in.rack_height) m.add_row({"rack's back from the pinion axis [mm]", num(r.a_back)});
  m.add_row({"rack travel per pinion turn [mm]", num(r.travel_per_turn)});
  m.add_row({"tip clearance c [mm]", num(r.c)});
  m.add_row({"length of the path of contact g_alpha [mm]", num(r.g_alpha)});
  m.add_row({"contact ratios eps_alpha / eps_beta / eps_gamma", fmt::format("{} / {} / {}", num(r.eps_alpha, 3), num(r.eps_beta, 3), num(r.eps_gamma, 3))});
  report.tables.push_back(std::move(m));
  report.json["rack"] = {{"p_t_mm", jnum(r.p_t)}, {"p_n_mm", jnum(r.p_n)}, {"h_a_mm", jnum(r.h_a2)}, {"h_f_mm", jnum(r.h_f2)},
                         {"e_n_mm", jnum(r.e_n2)}, {"pin_diameter_mm", jnum(r.pin_diameter2)}, {"M_r_mm", jnum(r.M_r)},
                         {"M_r_actual_mm", jnum(r.M_r_actual)}, {"M_r_back_mm", jnum(r.M_r_back)},
                         {"travel_mm", in.travel ? jnum(*in.travel) : nullptr}, {"length_mm", jnum(r.rack_length)},
                         {"teeth", in.travel ? nlohmann::json(r.rack_teeth) : nullptr}};
  report.json["mesh"] = {{"H_0_mm", jnum(r.H_0)}, {"a_back_mm", jnum(r.a_back)}, {"travel_per_turn_mm", jnum(r.travel_per_turn)},
                         {"c_mm", jnum(r.c)}, {"g_alpha_mm", jnum(r.g_alpha)}, {"eps_alpha", jnum(r.eps_alpha)},
                         {"eps_beta", jnum(r.eps_beta)}, {"eps_gamma", jnum(r.eps_gamma)},
                         {"engagement_half_length_mm", jnum(r.engagement_half_length)}};
}

// The torque drives in the sense of --speed1 (positive without it).
void forces_table(io::Report& report, const gg::RackPinionInput& in, const gg::RackPinionResult& r, double T, double n1) {
  const double signed_T = n1 < 0.0 ? -T : T;
  const gg::RackForces f = gg::rack_forces(signed_T, r.d, r.alpha_t, in.beta);
  io::Table t{"Forces", {"quantity", "value"}, {}};
  t.add_row({"torque on the pinion T1 [N m]", num(signed_T, 3)});
  t.add_row({"tangential F_t / radial F_r / axial F_a [N]", fmt::format("{} / {} / {}", num(f.F_t, 1), num(f.F_r, 1), num(f.F_a, 1))});
  t.add_row({"force on the rack (x, y, z) [N]", vec_text(f.on_rack)});
  t.add_row({"force on the pinion (x, y, z) [N]", vec_text(f.on_pinion)});
  const double v = std::numbers::pi * r.d * n1 / 60000.0;
  if (n1 != 0.0) t.add_row({"rack velocity along x [m/s], power [W]", fmt::format("{} , {}", num(v, 4), num(f.on_rack[0] * v, 1))});
  report.tables.push_back(std::move(t));
  report.notes.push_back("Forces: pinion axis +z, the rack below it along x, pitch point (0, -d/2, 0); the torque in the sense of --speed1 "
                         "(docs/gear-types.md).");
  report.json["forces"] = {{"T1_Nm", jnum(signed_T)}, {"F_t_N", jnum(f.F_t)}, {"F_r_N", jnum(f.F_r)}, {"F_a_N", jnum(f.F_a)},
                           {"F_rack_N", jvec(f.on_rack)}, {"F_pinion_N", jvec(f.on_pinion)}, {"v_rack_m_s", jnum(v)},
                           {"P_W", jnum(f.on_rack[0] * v)}};
}

}  // namespace

int run_gear_rack_command(plugin::CommandContext& context) {
  io::po::options_description desc("gearkit gear rack options (bare numbers: mm and deg)");
  add_options(desc);
  io::add_common_options(desc);
  io::po::positional_options_description none;
  io::po::variables_map vm;
  const std::vector<std::string> args(context.args.begin() + 1, context.args.end());
  if (!io::parse_command_line(args, desc, none, vm, kUsage, context.out)) return 0;
  const gg::RackPinionInput in = read_input(vm);
  const auto T = torque_Nm(vm, "torque1");
  const double n1 = speed_rpm(vm, "speed1").value_or(0.0);
  const io::CommonOptions common = io::common_options(vm);
  gg::RackPinionResult r;
  try {
    r = gg::compute_rack_pinion(in);
  } catch (const gg::GeometryError& e) {
    fail(option_for_field(e.field(), vm), e.what());
  }
  io::Report report;
  report.title = fmt::format("Rack and pinion: z1 = {}, m_n = {:g} mm, alpha_n = {:g} deg, beta = {:g} deg, x1 = {:.4f}", in.z1, in.m_n,
                             in.alpha_n * kDeg, in.beta * kDeg, r.x1);
  pinion_table(report, in, r);
  rack_and_mesh_tables(report, in, r);
  if (T) forces_table(report, in, r, *T, n1);
  report.warnings = r.warnings;
  io::OutputSet outputs(context.out);  // every file committed together, after the report renders
  if (vm.count("svg") || vm.count("dxf")) {
    const io::Drawing drawing = rack_drawing(in, r, 1e-3);
    if (vm.count("svg")) {
      io::SvgOptions svg;
      svg.title = fmt::format("gearkit gear rack: z1 = {}, m_n = {:g} mm", in.z1, in.m_n);
      outputs.add("--svg", vm["svg"].as<std::string>(), io::to_svg(drawing, svg));
    }
    if (vm.count("dxf")) outputs.add("--dxf", vm["dxf"].as<std::string>(), io::to_dxf(drawing));
  }
  return io::emit(report, common, outputs);
}

}  // namespace gearkit::plugins::gear
