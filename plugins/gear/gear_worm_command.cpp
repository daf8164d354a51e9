// `gearkit gear worm`: a cylindrical worm and its wheel (libgear worm.hpp, docs/gear-types.md).
#include "gear_types_commands.hpp"
#include "gear_types_common.hpp"
#include "gear_types_drawing.hpp"

#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/gear/worm.hpp>
#include <gearkit/io/command_line.hpp>
#include <gearkit/io/drawing.hpp>
#include <gearkit/io/report.hpp>

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gearkit::plugins::gear {

namespace gg = gearkit::gear;
using namespace types;

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

constexpr std::string_view kUsage =
    "gearkit gear worm --z1 N --z2 N --module LEN (--q Q | --worm-diameter LEN) [--flank ZA|ZN|ZI|ZK] [--pressure-angle 20] "
    "[--hand right|left] [--x2 X | --centre-distance LEN] [--addendum 1] [--dedendum 1.25] [--friction MU] "
    "[--friction-static 0.15] [--speed1 SPEED] [--torque1 TORQUE | --torque2 TORQUE] [--driver worm|wheel] "
    "[--svg FILE] [--dxf FILE] [--format text|json|csv|md|html]";

void add_options(io::po::options_description& desc) {
  auto text = [] { return io::po::value<std::string>(); };
  desc.add_options()
      ("z1", text()->value_name("N"), "threads (starts) of the worm")
      ("z2", text()->value_name("N"), "teeth of the wheel")
      ("module", text()->value_name("LEN"), "axial module m_x of the worm (= transverse module of the wheel) (bare number: mm)")
      ("q", text()->value_name("Q"), "diameter quotient q = d_m1 / m_x")
      ("worm-diameter", text()->value_name("LEN"), "worm reference diameter d_m1, instead of --q (bare number: mm)")
      ("flank", text()->value_name("ZA|ZN|ZI|ZK"), "flank form; the pressure angle is axial for ZA, normal for ZN, ZI, ZK (default ZI)")
      ("pressure-angle", text()->value_name("ANGLE"), "pressure angle of the flank form's section (default 20 deg) (bare number: deg)")
      ("hand", text()->value_name("right|left"), "hand of the worm's thread and the wheel's teeth (default right)")
      ("x2", text()->value_name("X"), "profile shift coefficient of the wheel (default 0)")
      ("centre-distance", text()->value_name("LEN"), "centre distance a: sets x2 (bare number: mm)")
      ("addendum", text()->value_name("COEF"), "addendum coefficient h_aP* of worm and wheel (default 1)")
      ("dedendum", text()->value_name("COEF"), "dedendum coefficient h_fP* of worm and wheel (default 1.25)")
      ("friction", text()->value_name("MU"), "friction coefficient running (default: AGMA 6034 from the sliding velocity, steel on bronze)")
      ("friction-static", text()->value_name("MU"), "friction coefficient at rest, for the static self-locking check (default 0.15)")
      ("speed1", text()->value_name("SPEED"), "speed of the worm about its axis, signed (--speed1=-1450rpm) (unit required, e.g. 1450rpm)")
      ("torque1", text()->value_name("TORQUE"), "torque on the worm: forces and efficiency (unit required, e.g. 9kN*m)")
      ("torque2", text()->value_name("TORQUE"), "torque on the wheel, instead of --torque1 (unit required, e.g. 9kN*m)")
      ("driver", text()->value_name("worm|wheel"), "which gear drives (default worm)")
      ("svg", text()->value_name("FILE"), "write the drawing (wheel mid-plane with the worm's axial section, section through the wheel axis, data block) as SVG")
      ("dxf", text()->value_name("FILE"), "write the drawing as DXF");
}

gg::WormInput read_input(const io::po::variables_map& vm) {
  gg::WormInput in;
  in.z1 = required_whole(vm, "z1", 1, 20, "worm threads");
  in.z2 = required_whole(vm, "z2", 1, 100000, "wheel teeth");
  const auto m = length_mm(vm, "module");
  if (!m) fail("module", "expected the axial module, found none");
  in.m_x = *m;
  if (vm.count("q") && vm.count("worm-diameter")) fail("worm-diameter", "cannot be combined with --q: both set the worm's diameter");
  in.q = number(vm, "q");
  in.d_m1 = length_mm(vm, "worm-diameter");
  if (!in.q && !in.d_m1) fail("q", "expected the diameter quotient (or --worm-diameter), found none");
  const std::string flank = choice(vm, "flank", {"ZA", "ZN", "ZI", "ZK"}, "ZI");
  in.flank = flank == "ZA" ? gg::WormFlank::ZA : flank == "ZN" ? gg::WormFlank::ZN : flank == "ZK" ? gg::WormFlank::ZK : gg::WormFlank::ZI;
  if (auto v = angle_rad(vm, "pressure-angle")) in.alpha_0 = *v;
  in.right_hand = choice(vm, "hand", {"right", "left"}, "right") == "right";
  if (vm.count("x2") && vm.count("centre-distance")) fail("centre-distance", "cannot be combined with --x2: both set the wheel's profile shift");
  if (auto v = number(vm, "x2")) in.x2 = *v;
  in.centre_distance = length_mm(vm, "centre-distance");
  if (auto v = number(vm, "addendum")) in.h_aP = *v;
  if (auto v = number(vm, "dedendum")) in.h_fP = *v;
  in.mu = number(vm, "friction");
  if (auto v = number(vm, "friction-static")) in.mu_static = *v;
  in.n1 = speed_rpm(vm, "speed1").value_or(0.0);
  return in;
}

std::string option_for_field(const std::string& f) {
  if (f == "m_x") return "module";
  if (f == "alpha_0") return "pressure-angle";
  if (f == "d_m1") return "worm-diameter";
  if (f == "centre_distance") return "centre-distance";
  if (f == "h_aP") return "addendum";
  if (f == "mu") return "friction";
  if (f == "mu_static") return "friction-static";
  if (f == "n1") return "speed1";
  return f;
}

void worm_tables(io::Report& report, const gg::WormInput& in, const gg::WormResult& w) {
  const char* hand = in.right_hand ? "right" : "left";
  io::Table t{"Worm (gear 1) and wheel (gear 2)", {"quantity", "worm", "wheel"}, {}};
  auto row = [&t](std::string name, std::string a, std::string b) { t.add_row({std::move(name), std::move(a), std::move(b)}); };
  row("threads z1 / teeth z2", std::to_string(in.z1), std::to_string(in.z2));
  row("flank form, hand", fmt::format("{}, {}", gg::to_string(in.flank), hand), hand);
  row("axial module m_x = wheel's transverse module [mm]", num(in.m_x), num(in.m_x));
  row("normal module m_n [mm]", num(w.m_n), num(w.m_n));
  row("axial pressure angle alpha_x [deg]", num(w.alpha_x * kDeg), num(w.alpha_x * kDeg));
  row("normal pressure angle alpha_n [deg]", num(w.alpha_n * kDeg), num(w.alpha_n * kDeg));
  row("diameter quotient q", num(w.q), "");
  row("lead angle gamma_m at d_m1 / gamma_w at d_w1 [deg]", fmt::format("{} / {}", num(w.gamma * kDeg), num(w.gamma_w * kDeg)), "");
  row("axial pitch p_x / lead p_z [mm]", fmt::format("{} / {}", num(w.p_x), num(w.p_z)), "");
  if (in.flank == gg::WormFlank::ZI) row("base lead angle gamma_b [deg] / base diameter d_b1 [mm]", fmt::format("{} / {}", num(w.gamma_b * kDeg), num(w.d_b1)), "");
  row("profile shift coefficient x", "", num(w.x2));
  row("reference diameter d_m1 / d2 [mm]", num(w.d_m1), num(w.d2));
  row("working diameter d_w1 / d_w2 [mm]", num(w.d_w1), num(w.d2));
  row("tip diameter d_a1 / throat diameter d_a2 [mm]", num(w.d_a1), num(w.d_a2));
  row("root diameter d_f [mm]", num(w.d_f1), num(w.d_f2));
  row("outside diameter d_e2 [mm] (recommended)", "", num(w.d_e2));
  row("throat radius r_k [mm]", "", num(w.r_k));
  row("worm length b1 (shortest) / face width b2 (recommended) [mm]", num(w.b1, 2), num(w.b2, 2));
  report.tables.push_back(std::move(t));
  report.json["worm"] = {{"z1", in.z1}, {"flank", gg::to_string(in.flank)}, {"hand", hand}, {"m_x_mm", jnum(in.m_x)}, {"m_n_mm", jnum(w.m_n)},
                         {"alpha_x_deg", jnum(w.alpha_x * kDeg)}, {"alpha_n_deg", jnum(w.alpha_n * kDeg)}, {"q", jnum(w.q)},
                         {"gamma_deg", jnum(w.gamma * kDeg)}, {"gamma_w_deg", jnum(w.gamma_w * kDeg)}, {"gamma_b_deg", jnum(w.gamma_b * kDeg)},
                         {"p_x_mm", jnum(w.p_x)}, {"p_z_mm", jnum(w.p_z)}, {"d_m1_mm", jnum(w.d_m1)}, {"d_w1_mm", jnum(w.d_w1)},
                         {"d_a1_mm", jnum(w.d_a1)}, {"d_f1_mm", jnum(w.d_f1)}, {"d_b1_mm", jnum(w.d_b1)}, {"b1_mm", jnum(w.b1)}};
  report.json["wheel"] = {{"z2", in.z2}, {"hand", hand}, {"x2", jnum(w.x2)}, {"d2_mm", jnum(w.d2)}, {"d_a2_mm", jnum(w.d_a2)},
                          {"d_f2_mm", jnum(w.d_f2)}, {"d_e2_mm", jnum(w.d_e2)}, {"r_k_mm", jnum(w.r_k)}, {"b2_mm", jnum(w.b2)}};
}

void pair_table(io::Report& report, const gg::WormInput& in, const gg::WormResult& w) {
  io::Table t{"Pair", {"quantity", "value"}, {}};
  t.add_row({"centre distance a [mm]", num(w.a)});
  t.add_row({"ratio u = z2 / z1", num(w.u)});
  t.add_row({"speeds n1 about +x / n2 about +y [1/min]", fmt::format("{} / {}", num(in.n1, 2), num(w.n2, 3))});
  t.add_row({"sliding velocity v_g [m/s]", num(w.v_g)});
  t.add_row({fmt::format("friction coefficient mu ({})", w.mu_from_velocity ? "AGMA 6034 from v_g" : "given"), num(w.mu)});
  t.add_row({"friction angle rho' running / at rest [deg]", fmt::format("{} / {}", num(w.rho * kDeg), num(w.rho_static * kDeg))});
  t.add_row({"efficiency worm driving eta_12 / wheel driving eta_21", fmt::format("{} / {}", num(w.eta_12), num(w.eta_21))});
  t.add_row({"self-locking at rest / running", fmt::format("{} / {}", w.self_locking_static ? "yes" : "no", w.self_locking_dynamic ? "yes" : "no")});
  report.tables.push_back(std::move(t));
  report.json["pair"] = {{"a_mm", jnum(w.a)}, {"u", jnum(w.u)}, {"n1_rpm", jnum(in.n1)}, {"n2_rpm", jnum(w.n2)}, {"v1_m_s", jnum(w.v1)},
                         {"v2_m_s", jnum(w.v2)}, {"v_g_m_s", jnum(w.v_g)}, {"mu", jnum(w.mu)},
                         {"mu_source", w.mu_from_velocity ? "agma6034" : "given"}, {"rho_deg", jnum(w.rho * kDeg)},
                         {"rho_static_deg", jnum(w.rho_static * kDeg)}, {"eta_worm_driving", jnum(w.eta_12)},
                         {"eta_wheel_driving", jnum(w.eta_21)}, {"self_locking", w.self_locking_static || w.self_locking_dynamic},
                         {"self_locking_static", w.self_locking_static}, {"self_locking_dynamic", w.self_locking_dynamic}};
}

void forces_table(io::Report& report, const gg::WormResult& w, double T, bool on_worm, bool worm_drives) {
  gg::WormForces f;
  try {
    f = gg::worm_forces(w, T, on_worm, worm_drives);
  } catch (const std::domain_error&) {
    report.warnings.push_back("no forces for the wheel driving: the mesh is self-locking running (eta_21 <= 0), the wheel cannot turn the worm");
    return;
  }
  io::Table t{"Forces", {"quantity", "worm", "wheel"}, {}};
  auto row = [&t](std::string name, std::string a, std::string b) { t.add_row({std::move(name), std::move(a), std::move(b)}); };
  row("driver", worm_drives ? "yes" : "", worm_drives ? "" : "yes");
  row("torque T [N m]", num(f.T1, 3), num(f.T2, 3));
  row("tangential force F_t [N]", num(f.F_t1, 1), num(f.F_t2, 1));
  row("axial force F_a [N]", num(f.F_a1, 1), num(f.F_a2, 1));
  row("radial force F_r [N]", num(f.F_r, 1), num(f.F_r, 1));
  row("normal force F_n [N]", num(f.F_n, 1), num(f.F_n, 1));
  row("force vector (x, y, z) [N]", vec_text(f.on_worm), vec_text(f.on_wheel));
  if (w.v1 > 0.0) row("power in / out / friction loss [W]", fmt::format("{} / {} / {}", num(f.P_in, 1), num(f.P_out, 1), num(f.P_loss, 1)), "");
  report.tables.push_back(std::move(t));
  report.json["forces"] = {{"driver", worm_drives ? "worm" : "wheel"}, {"T1_Nm", jnum(f.T1)}, {"T2_Nm", jnum(f.T2)},
                           {"F_t1_N", jnum(f.F_t1)}, {"F_a1_N", jnum(f.F_a1)}, {"F_r1_N", jnum(f.F_r)}, {"F_t2_N", jnum(f.F_t2)},
                           {"F_a2_N", jnum(f.F_a2)}, {"F_r2_N", jnum(f.F_r)}, {"F_n_N", jnum(f.F_n)}, {"F1_N", jvec(f.on_worm)},
                           {"F2_N", jvec(f.on_wheel)}, {"P_in_W", jnum(f.P_in)}, {"P_out_W", jnum(f.P_out)}, {"P_loss_W", jnum(f.P_loss)}};
}

}  // namespace

int run_gear_worm_command(plugin::CommandContext& context) {
  io::po::options_description desc("gearkit gear worm options (bare numbers: mm and deg)");
  add_options(desc);
  io::add_common_options(desc);
  io::po::positional_options_description none;
  io::po::variables_map vm;
  const std::vector<std::string> args(context.args.begin() + 1, context.args.end());
  if (!io::parse_command_line(args, desc, none, vm, kUsage, context.out)) return 0;
  const gg::WormInput in = read_input(vm);
  if (vm.count("torque1") && vm.count("torque2")) fail("torque2", "cannot be combined with --torque1: give one of them");
  const auto T1 = torque_Nm(vm, "torque1"), T2 = torque_Nm(vm, "torque2");
  const bool worm_drives = choice(vm, "driver", {"worm", "wheel"}, "worm") == "worm";
  const io::CommonOptions common = io::common_options(vm);
  gg::WormResult w;
  try {
    w = gg::compute_worm(in);
  } catch (const gg::GeometryError& e) {
    fail(option_for_field(e.field()), e.what());
  }
  io::Report report;
  report.title = fmt::format("Worm pair: z1 = {}, z2 = {}, m_x = {:g} mm, {} {}-hand, q = {:.4f}, a = {:.4f} mm", in.z1, in.z2, in.m_x,
                             gg::to_string(in.flank), in.right_hand ? "right" : "left", w.q, w.a);
  worm_tables(report, in, w);
  pair_table(report, in, w);
  report.warnings = w.warnings;
  if (T1 || T2) forces_table(report, w, T1 ? *T1 : *T2, T1.has_value(), worm_drives);
  report.notes.push_back("Efficiency and forces at the pitch point on the worm's working cylinder d_w1 = 2 a - d2. Forces: wheel axis +y "
                         "through the origin, worm axis along +x through (0, 0, a); hands and senses: docs/gear-types.md.");
  io::OutputSet outputs(context.out);  // every file committed together, after the report renders
  if (vm.count("svg") || vm.count("dxf")) {
    const io::Drawing drawing = worm_drawing(in, w, 1e-3);
    if (vm.count("svg")) {
      io::SvgOptions svg;
      svg.title = fmt::format("gearkit gear worm: z1 = {}, z2 = {}, m_x = {:g} mm", in.z1, in.z2, in.m_x);
      outputs.add("--svg", vm["svg"].as<std::string>(), io::to_svg(drawing, svg));
    }
    if (vm.count("dxf")) outputs.add("--dxf", vm["dxf"].as<std::string>(), io::to_dxf(drawing));
  }
  return io::emit(report, common, outputs);
}

}  // namespace gearkit::plugins::gear
