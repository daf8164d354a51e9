// `gearkit gear crossed`: crossed helical (screw) gears (libgear crossed_helical.hpp,
// docs/gear-types.md).
#include "gear_types_commands.hpp"
#include "gear_types_common.hpp"

#include <gearkit/gear/crossed_helical.hpp>
#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/io/command_line.hpp>
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
    "gearkit gear crossed --z1 N --z2 N --module LEN --helix-angle1 ANGLE --helix-angle2 ANGLE [--pressure-angle 20] "
    "[--addendum 1] [--dedendum 1.25] [--friction 0.05] [--speed1 SPEED] [--torque1 TORQUE | --torque2 TORQUE] "
    "[--driver gear1|gear2] [--format text|json|csv|md|html]";

void add_options(io::po::options_description& desc) {
  auto text = [] { return io::po::value<std::string>(); };
  desc.add_options()
      ("z1", text()->value_name("N"), "teeth of gear 1")
      ("z2", text()->value_name("N"), "teeth of gear 2")
      ("module", text()->value_name("LEN"), "normal module m_n of both gears (bare number: mm)")
      ("pressure-angle", text()->value_name("ANGLE"), "normal pressure angle (default 20 deg) (bare number: deg)")
      ("helix-angle1", text()->value_name("ANGLE"), "helix angle of gear 1, > 0 right hand (bare number: deg)")
      ("helix-angle2", text()->value_name("ANGLE"), "helix angle of gear 2, > 0 right hand; shaft angle = sum (bare number: deg)")
      ("addendum", text()->value_name("COEF"), "addendum coefficient h_aP* (default 1)")
      ("dedendum", text()->value_name("COEF"), "dedendum coefficient h_fP* (default 1.25)")
      ("friction", text()->value_name("MU"), "friction coefficient (default 0.05)")
      ("speed1", text()->value_name("SPEED"), "speed of gear 1 about its axis, signed (--speed1=-1450rpm) (unit required, e.g. 1450rpm)")
      ("torque1", text()->value_name("TORQUE"), "torque on gear 1: forces (unit required, e.g. 9kN*m)")
      ("torque2", text()->value_name("TORQUE"), "torque on gear 2, instead of --torque1 (unit required, e.g. 9kN*m)")
      ("driver", text()->value_name("gear1|gear2"), "which gear drives (default gear1)");
}

gg::CrossedHelicalInput read_input(const io::po::variables_map& vm) {
  gg::CrossedHelicalInput in;
  in.z1 = required_whole(vm, "z1", 3, 100000, "teeth of gear 1");
  in.z2 = required_whole(vm, "z2", 3, 100000, "teeth of gear 2");
  const auto m = length_mm(vm, "module");
  if (!m) fail("module", "expected the normal module, found none");
  in.m_n = *m;
  if (auto v = angle_rad(vm, "pressure-angle")) in.alpha_n = *v;
  const auto b1 = angle_rad(vm, "helix-angle1");
  if (!b1) fail("helix-angle1", "expected the helix angle of gear 1, found none");
  const auto b2 = angle_rad(vm, "helix-angle2");
  if (!b2) fail("helix-angle2", "expected the helix angle of gear 2, found none");
  in.beta1 = *b1;
  in.beta2 = *b2;
  if (auto v = number(vm, "addendum")) in.h_aP = *v;
  if (auto v = number(vm, "dedendum")) in.h_fP = *v;
  in.mu = number(vm, "friction");
  in.n1 = speed_rpm(vm, "speed1").value_or(0.0);
  return in;
}

std::string option_for_field(const std::string& f) {
  if (f == "m_n") return "module";
  if (f == "alpha_n") return "pressure-angle";
  if (f == "beta1") return "helix-angle1";
  if (f == "beta2") return "helix-angle2";
  if (f == "h_aP") return "addendum";
  if (f == "mu") return "friction";
  if (f == "n1") return "speed1";
  return f;
}

const char* hand_of(double beta) { return beta > 0.0 ? "right" : "left"; }

void gear_table(io::Report& report, const gg::CrossedHelicalInput& in, const gg::CrossedHelicalResult& c) {
  io::Table t{"Gears", {"quantity", "gear 1", "gear 2"}, {}};
  const auto& g1 = c.gear[0];
  const auto& g2 = c.gear[1];
  auto both = [&t](std::string name, double a, double b) { t.add_row({std::move(name), num(a), num(b)}); };
  t.add_row({"number of teeth z", std::to_string(g1.z), std::to_string(g2.z)});
  t.add_row({"helix hand", hand_of(g1.beta), hand_of(g2.beta)});
  both("helix angle beta [deg]", g1.beta * kDeg, g2.beta * kDeg);
  both("normal module m_n [mm]", in.m_n, in.m_n);
  both("transverse module m_t [mm]", g1.m_t, g2.m_t);
  both("transverse pressure angle alpha_t [deg]", g1.alpha_t * kDeg, g2.alpha_t * kDeg);
  both("reference diameter d [mm]", g1.d, g2.d);
  both("tip diameter d_a [mm]", g1.d_a, g2.d_a);
  both("root diameter d_f [mm]", g1.d_f, g2.d_f);
  both("lead p_z [mm]", g1.p_z, g2.p_z);
  report.tables.push_back(std::move(t));
  nlohmann::json gears = nlohmann::json::array();
  for (const auto& g : c.gear)
    gears.push_back({{"z", g.z}, {"hand", hand_of(g.beta)}, {"beta_deg", jnum(g.beta * kDeg)}, {"m_n_mm", jnum(in.m_n)},
                     {"m_t_mm", jnum(g.m_t)}, {"alpha_t_deg", jnum(g.alpha_t * kDeg)}, {"d_mm", jnum(g.d)}, {"d_a_mm", jnum(g.d_a)},
                     {"d_f_mm", jnum(g.d_f)}, {"p_z_mm", jnum(g.p_z)}});
  report.json["gears"] = gears;
}

void pair_table(io::Report& report, const gg::CrossedHelicalResult& c) {
  io::Table t{"Pair", {"quantity", "value"}, {}};
  t.add_row({"shaft angle Sigma = beta1 + beta2 [deg]", num(c.Sigma * kDeg)});
  t.add_row({"centre distance a [mm]", num(c.a)});
  t.add_row({"ratio u = z2 / z1", num(c.u)});
  t.add_row({"speeds n1 about x / n2 about g2 [1/min]", fmt::format("{} / {}", num(c.n1, 2), num(c.n2, 3))});
  t.add_row({"sliding velocity v_g [m/s]", num(c.v_g)});
  t.add_row({"friction coefficient mu / angle rho' [deg]", fmt::format("{} / {}", num(c.mu), num(c.rho * kDeg))});
  t.add_row({"efficiency gear 1 driving eta_12 / gear 2 driving eta_21", fmt::format("{} / {}", num(c.eta_12), num(c.eta_21))});
  report.tables.push_back(std::move(t));
  report.json["pair"] = {{"Sigma_deg", jnum(c.Sigma * kDeg)}, {"a_mm", jnum(c.a)}, {"u", jnum(c.u)}, {"n1_rpm", jnum(c.n1)},
                         {"n2_rpm", jnum(c.n2)}, {"v1_m_s", jnum(c.v1)}, {"v2_m_s", jnum(c.v2)}, {"v_g_m_s", jnum(c.v_g)},
                         {"mu", jnum(c.mu)}, {"rho_deg", jnum(c.rho * kDeg)}, {"eta_12", jnum(c.eta_12)}, {"eta_21", jnum(c.eta_21)},
                         {"self_locking_12", c.self_locking_12}, {"self_locking_21", c.self_locking_21}};
}

void forces_table(io::Report& report, const gg::CrossedHelicalInput& in, const gg::CrossedHelicalResult& c, double T, int on_gear, int driver) {
  gg::CrossedForces f;
  try {
    f = gg::crossed_forces(c, in.alpha_n, T, on_gear, driver);
  } catch (const std::domain_error&) {
    report.warnings.push_back(fmt::format("no forces: gear {} cannot drive (self-locking)", driver));
    return;
  }
  io::Table t{"Forces", {"quantity", "gear 1", "gear 2"}, {}};
  auto row = [&t](std::string name, std::string a, std::string b) { t.add_row({std::move(name), std::move(a), std::move(b)}); };
  row("driver", driver == 1 ? "yes" : "", driver == 2 ? "yes" : "");
  row("torque T [N m]", num(f.T1, 3), num(f.T2, 3));
  row("tangential force F_t [N]", num(f.F_t1, 1), num(f.F_t2, 1));
  row("axial force F_a along x / along g2 [N]", num(f.F_a1, 1), num(f.F_a2, 1));
  row("radial force F_r [N]", num(f.F_r, 1), num(f.F_r, 1));
  row("force vector (x, y, z) [N]", vec_text(f.on_1), vec_text(f.on_2));
  if (c.v1 > 0.0) row("power in / out / friction loss [W]", fmt::format("{} / {} / {}", num(f.P_in, 1), num(f.P_out, 1), num(f.P_loss, 1)), "");
  report.tables.push_back(std::move(t));
  report.json["forces"] = {{"driver", driver == 1 ? "gear1" : "gear2"}, {"T1_Nm", jnum(f.T1)}, {"T2_Nm", jnum(f.T2)},
                           {"F_t1_N", jnum(f.F_t1)}, {"F_t2_N", jnum(f.F_t2)}, {"F_a1_N", jnum(f.F_a1)}, {"F_a2_N", jnum(f.F_a2)},
                           {"F_r_N", jnum(f.F_r)}, {"F_n_N", jnum(f.F_n)}, {"F1_N", jvec(f.on_1)}, {"F2_N", jvec(f.on_2)},
                           {"P_in_W", jnum(f.P_in)}, {"P_out_W", jnum(f.P_out)}, {"P_loss_W", jnum(f.P_loss)}};
}

}  // namespace

int run_gear_crossed_command(plugin::CommandContext& context) {
  io::po::options_description desc("gearkit gear crossed options (bare numbers: mm and deg)");
  add_options(desc);
  io::add_common_options(desc);
  io::po::positional_options_description none;
  io::po::variables_map vm;
  const std::vector<std::string> args(context.args.begin() + 1, context.args.end());
  if (!io::parse_command_line(args, desc, none, vm, kUsage, context.out)) return 0;
  const gg::CrossedHelicalInput in = read_input(vm);
  if (vm.count("torque1") && vm.count("torque2")) fail("torque2", "cannot be combined with --torque1: give one of them");
  const auto T1 = torque_Nm(vm, "torque1"), T2 = torque_Nm(vm, "torque2");
  const int driver = choice(vm, "driver", {"gear1", "gear2"}, "gear1") == "gear1" ? 1 : 2;
  const io::CommonOptions common = io::common_options(vm);
  gg::CrossedHelicalResult c;
  try {
    c = gg::compute_crossed_helical(in);
  } catch (const gg::GeometryError& e) {
    fail(option_for_field(e.field()), e.what());
  }
  io::Report report;
  report.title = fmt::format("Crossed helical pair: z1 = {}, z2 = {}, m_n = {:g} mm, beta1 = {:g} deg, beta2 = {:g} deg, Sigma = {:g} deg",
                             in.z1, in.z2, in.m_n, in.beta1 * kDeg, in.beta2 * kDeg, c.Sigma * kDeg);
  gear_table(report, in, c);
  pair_table(report, c);
  report.warnings = c.warnings;
  if (T1 || T2) forces_table(report, in, c, T1 ? *T1 : *T2, T1 ? 1 : 2, driver);
  if (!in.mu) report.notes.push_back("friction coefficient 0.05 assumed (steel on steel, lubricated); give --friction");
  report.notes.push_back("Unshifted gears. Forces: x along gear 1's axis, z from gear 1's axis to gear 2's, gear 2's axis "
                         "g2 = (cos Sigma, -sin Sigma, 0); hands and senses: docs/gear-types.md.");
  return io::emit(report, common, context.out);
}

}  // namespace gearkit::plugins::gear
