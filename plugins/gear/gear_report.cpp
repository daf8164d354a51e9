#include "gear_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace gearkit::plugins::gear {

namespace gg = gearkit::gear;

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

std::string num(double v, int digits = 4) { return std::isfinite(v) ? io::fixed(v, digits) : std::string("-"); }

// NaN and infinities become JSON null.
nlohmann::json jnum(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

std::string kind(const gg::GearPairInput& in) {
  return fmt::format("{} {}", in.internal ? "internal" : "external", in.helix_angle != 0.0 ? "helical" : "spur");
}

// Diameters, or with --radii the radii course notes print (OTM 2015 problem 3: r, r', r_b,
// r_c, r_f): the same quantities halved.
void size_rows(io::Table& t, const gg::GearPairResult& r, bool radii) {
  const auto& g1 = r.gear[0];
  const auto& g2 = r.gear[1];
  const double f = radii ? 0.5 : 1.0;
  auto row = [&](const char* diameter, const char* radius, double gg::GearResult::*field) {
    t.add_row({radii ? radius : diameter, num(f * (g1.*field)), num(f * (g2.*field))});
  };
  row("reference diameter d [mm]", "reference radius r [mm]", &gg::GearResult::d);
  row("working diameter d_w [mm]", "working radius r_w [mm]", &gg::GearResult::d_w);
  row("base diameter d_b [mm]", "base radius r_b [mm]", &gg::GearResult::d_b);
  row("tip diameter d_a [mm]", "tip radius r_a [mm]", &gg::GearResult::d_a);
  row("root diameter d_f [mm]", "root radius r_f [mm]", &gg::GearResult::d_f);
}

void gear_rows(io::Table& t, const gg::GearPairInput& in, const gg::GearPairResult& r, bool helical, bool allowances, bool radii) {
  const auto& g1 = r.gear[0];
  const auto& g2 = r.gear[1];
  auto row = [&t](std::string name, std::string a, std::string b) { t.add_row({std::move(name), std::move(a), std::move(b)}); };
  auto both = [&](std::string name, double gg::GearResult::*field, int digits = 4) {
    row(std::move(name), num(g1.*field, digits), num(g2.*field, digits));
  };
  row("number of teeth z", std::to_string(g1.z), std::to_string(g2.z));
  both("normal module m_n [mm]", &gg::GearResult::m_n);
  if (helical) both("transverse module m_t [mm]", &gg::GearResult::m_t);
  row("pressure angle alpha_n [deg]", num(g1.alpha_n * kDeg), num(g2.alpha_n * kDeg));
  if (helical) {
    row("transverse pressure angle alpha_t [deg]", num(g1.alpha_t * kDeg), num(g2.alpha_t * kDeg));
    row("helix angle beta [deg]", num(g1.beta * kDeg), num(g2.beta * kDeg));
    row("helix hand (beta > 0: gear 1 right)", gg::to_string(gg::helix_hand(in, 0)), gg::to_string(gg::helix_hand(in, 1)));
    row("base helix angle beta_b [deg]", num(g1.beta_b * kDeg), num(g2.beta_b * kDeg));
  }
  both("profile shift coefficient x", &gg::GearResult::x);
  both("profile shift x m_n [mm]", &gg::GearResult::shift_mm);
  size_rows(t, r, radii);
  // Transverse values (the only ones for spur gears, as in the OTM 2015 table).
  both(helical ? "transverse pitch p_t [mm]" : "pitch p [mm]", &gg::GearResult::p_t);
  both(helical ? "transverse base pitch p_bt [mm]" : "base pitch p_b [mm]", &gg::GearResult::p_bt);
  both(helical ? "transverse tooth thickness s_t [mm]" : "tooth thickness s [mm]", &gg::GearResult::s_t);
  both(helical ? "transverse space width e_t [mm]" : "space width e [mm]", &gg::GearResult::e_t);
  if (helical) {
    both("normal tooth thickness s_n [mm]", &gg::GearResult::s_n);
    both("virtual number of teeth z_n", &gg::GearResult::z_n, 3);
  }
  both("tip thickness s_an [mm]", &gg::GearResult::s_an);
  both("undercut limit x_min (ISO, rack tip radius)", &gg::GearResult::x_min);
  both("practical undercut limit x'_min (DIN 3960)", &gg::GearResult::x_min_practical);
  both("form diameter d_Ff [mm]", &gg::GearResult::d_Ff);
  row("teeth spanned k", g1.k_span ? std::to_string(g1.k_span) : "-", g2.k_span ? std::to_string(g2.k_span) : "-");
  both("span W_k [mm]", &gg::GearResult::W_k);
  both(helical ? "ball diameter D_M [mm]" : "pin diameter D_M [mm]", &gg::GearResult::pin_diameter);
  row(fmt::format("{} M_d [mm]", g2.internal ? (helical ? "over (1) / between (2) balls" : "over (1) / between (2) pins")
                                             : (helical ? "over balls" : "over pins")),
      num(g1.M_d), num(g2.M_d));
  both("chordal thickness [mm]", &gg::GearResult::chordal_s);
  both("chordal height [mm]", &gg::GearResult::chordal_h);
  if (allowances) {
    both("thickness allowance A_sn [mm]", &gg::GearResult::A_sn);
    both("span with allowance [mm]", &gg::GearResult::W_k_actual);
    both("M_d with allowance [mm]", &gg::GearResult::M_d_actual);
  }
}

void pair_rows(io::Table& t, const gg::GearPairResult& r, bool helical, bool backlash) {
  const auto& p = r.pair;
  auto row = [&t](std::string name, std::string v) { t.add_row({std::move(name), std::move(v)}); };
  row("working pressure angle alpha_wt [deg]", num(p.alpha_wt * kDeg));
  row("working centre distance a [mm]", num(p.a));
  row("reference centre distance a_d [mm]", num(p.a_d));
  row("shift sum x1 + x2", num(p.sum_x));
  row("centre distance modification y", num(p.y));
  row(fmt::format("tip shortening k ({})", p.tip_shortened ? "applied" : "not applied"), num(p.k));
  row("mounting", gg::to_string(p.mounting));
  row("shift split", gg::to_string(p.split));
  row("gear ratio u = z2/z1", num(p.u));
  row("transverse contact ratio eps_alpha", num(p.eps_alpha, 3));
  if (helical) {
    row("overlap ratio eps_beta", num(p.eps_beta, 3));
    row("total contact ratio eps_gamma", num(p.eps_gamma, 3));
  }
  row("tip clearance, tip 1 - root 2 [mm]", num(p.c1));
  row("tip clearance, tip 2 - root 1 [mm]", num(p.c2));
  row("max specific sliding at root 1", num(p.zeta1, 3));
  row("max specific sliding at root 2", num(p.zeta2, 3));
  if (backlash) {
    row("centre distance deviation A_a [mm]", num(p.A_a));
    row("circumferential backlash j_wt [mm]", num(p.j_wt));
    row("normal backlash j_bn [mm]", num(p.j_bn));
  }
}

nlohmann::json gear_json(const gg::GearResult& g) {
  return {{"z", g.z},
          {"internal", g.internal},
          {"x", g.x},
          {"shift_mm", g.shift_mm},
          {"m_n_mm", g.m_n},
          {"m_t_mm", g.m_t},
          {"alpha_n_deg", g.alpha_n * kDeg},
          {"alpha_t_deg", g.alpha_t * kDeg},
          {"beta_deg", g.beta * kDeg},
          {"beta_b_deg", g.beta_b * kDeg},
          {"d_mm", g.d},
          {"d_b_mm", g.d_b},
          {"d_w_mm", g.d_w},
          {"d_a_mm", g.d_a},
          {"d_f_mm", g.d_f},
          {"d_Ff_mm", jnum(g.d_Ff)},
          {"p_mm", g.p_t},
          {"p_n_mm", g.p_n},
          {"p_b_mm", g.p_bt},
          {"p_bn_mm", g.p_en},
          {"s_mm", g.s_t},
          {"e_mm", g.e_t},
          {"s_n_mm", g.s_n},
          {"e_n_mm", g.e_n},
          {"s_a_mm", jnum(g.s_an)},
          {"z_n", g.z_n},
          {"W_k_mm", jnum(g.W_k)},
          {"k_span", g.k_span > 0 ? nlohmann::json(g.k_span) : nlohmann::json(nullptr)},
          {"pin_diameter_mm", g.pin_diameter},
          {"M_d_mm", jnum(g.M_d)},
          {"chordal_thickness_mm", g.chordal_s},
          {"chordal_height_mm", g.chordal_h},
          {"x_min", jnum(g.x_min)},
          {"x_min_practical", jnum(g.x_min_practical)},
          {"A_sn_mm", g.A_sn},
          {"W_k_actual_mm", jnum(g.W_k_actual)},
          {"M_d_actual_mm", jnum(g.M_d_actual)}};
}

nlohmann::json pair_json(const gg::PairResult& p, bool internal) {
  nlohmann::json j = {{"internal", internal},
          {"alpha_wt_deg", p.alpha_wt * kDeg},
          {"centre_distance_mm", p.a},
          {"reference_centre_distance_mm", p.a_d},
          {"y", p.y},
          {"k", p.k},
          {"tip_shortening_applied", p.tip_shortened},
          {"sum_x", p.sum_x},
          {"mounting", gg::to_string(p.mounting)},
          {"shift_split", gg::to_string(p.split)},
          {"ratio", p.u},
          {"contact_ratio_alpha", p.eps_alpha},
          {"contact_ratio_beta", p.eps_beta},
          {"contact_ratio_total", p.eps_gamma},
          {"tip_clearance_mm", {p.c1, p.c2}},
          {"specific_sliding_max", {jnum(p.zeta1), jnum(p.zeta2)}},
          {"centre_distance_deviation_mm", p.A_a},
          {"backlash_circumferential_mm", p.j_wt},
          {"backlash_normal_mm", p.j_bn}};
  // The American spellings of gearkit 0.1, kept as aliases for one release (docs/gear.md).
  j["center_distance_mm"] = p.a;
  j["reference_center_distance_mm"] = p.a_d;
  j["center_distance_deviation_mm"] = p.A_a;
  return j;
}

// Which undercut criterion says what, when they disagree (a gear between x'_min and x_min).
void undercut_note(io::Report& report, const gg::GearPairInput& in, const gg::GearPairResult& r) {
  for (int i = 0; i < 2; ++i) {
    const gg::GearResult& g = r.gear[static_cast<std::size_t>(i)];
    if (g.internal || !(g.x < g.x_min - 1e-9) || !(g.x >= g.x_min_practical - 1e-9)) continue;
    report.notes.push_back(fmt::format(
        "Undercut of gear {}: ISO's x_min = {:.4f} is the least shift with no undercut at all (the straight flank of the "
        "rack, tip radius rho_fP* = {:g}, ends at or above the interference point); the practical limit x'_min = {:.4f} "
        "(DIN 3960; (14 - z)/17 at 20 deg, as course notes write it) accepts a slight undercut that leaves the working "
        "flank. With x = {:.4f} the course's answer is \"no undercut\" and ISO's is \"undercut\". The generated "
        "involute then starts at d_Ff = {:.3f} mm: an involute-interference warning for the mating tip is the same "
        "undercut seen from the mesh (generation removed the flank the tip would cut into, so the teeth do not collide, "
        "but the contact below d_Ff is not on the involute).",
        i + 1, g.x_min, gg::tool_rack(in, i, g.alpha_n).rho_fP, g.x_min_practical, g.x, g.d_Ff));
  }
}

}  // namespace

io::Report gear_report(const gg::GearPairInput& in, const gg::GearPairResult& r, bool radii) {
  io::Report report;
  const bool helical = in.helix_angle != 0.0;
  const bool allowances = r.gear[0].A_sn != 0.0 || r.gear[1].A_sn != 0.0;
  const bool backlash = allowances || in.A_a != 0.0 || in.backlash_target.has_value();
  report.title = fmt::format("Gear table: {} pair, z1 = {}, z2 = {}, m_n = {:g} mm", kind(in), r.gear[0].z, r.gear[1].z,
                             r.gear[0].m_n);
  io::Table gears{"Gears", {"quantity", "gear 1", in.internal ? "gear 2 (ring)" : "gear 2"}, {}};
  gear_rows(gears, in, r, helical, allowances, radii);
  io::Table pair{"Pair", {"quantity", "value"}, {}};
  pair_rows(pair, r, helical, backlash);
  report.tables.push_back(std::move(gears));
  report.tables.push_back(std::move(pair));
  report.notes.push_back("Lengths in mm (ISO 21771 symbols, basic rack ISO 53); diameters of a ring are magnitudes "
                         "(its d_a < d < d_f); spans are normal-section, pins measured in the transverse plane.");
  if (in.internal) {
    report.notes.push_back("Ring shift x2 uses the ISO 21771 sign (x2 > 0 thickens the ring teeth); KHK/JIS tables "
                           "use the opposite sign.");
  }
  undercut_note(report, in, r);
  report.warnings = r.warnings;
  report.json["pair"] = pair_json(r.pair, in.internal);
  report.json["pair"]["undercut_limit"] = gg::to_string(in.undercut_limit);
  report.json["gears"] = {gear_json(r.gear[0]), gear_json(r.gear[1])};
  for (int i = 0; i < 2; ++i) report.json["gears"][static_cast<std::size_t>(i)]["helix_hand"] = gg::to_string(gg::helix_hand(in, i));
  if (radii)
    for (std::size_t i = 0; i < 2; ++i) {
      const gg::GearResult& g = r.gear[i];
      nlohmann::json& j = report.json["gears"][i];
      j["r_mm"] = 0.5 * g.d;
      j["r_w_mm"] = 0.5 * g.d_w;
      j["r_b_mm"] = 0.5 * g.d_b;
      j["r_a_mm"] = 0.5 * g.d_a;
      j["r_f_mm"] = 0.5 * g.d_f;
    }
  return report;
}

}  // namespace gearkit::plugins::gear
