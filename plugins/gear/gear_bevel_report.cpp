#include "gear_bevel_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <string>

namespace gearkit::plugins::gear {

namespace gg = gearkit::gear;

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

std::string num(double v, int digits) { return std::isfinite(v) ? io::fixed(v, digits) : std::string("-"); }

// One table row per quantity and its JSON keys: the symbol, the gear's number for a per-gear
// quantity, the unit suffix ("delta" "deg" -> delta1_deg, delta2_deg).
class Rows {
 public:
  Rows(io::Table& table, nlohmann::json& json) : t_(table), j_(json) {}

  void pair(const std::string& name, const std::string& symbol, const char* unit, double v, int digits = 4) {
    t_.add_row({label(name, symbol, unit), num(v, digits)});
    j_[key(symbol, "", unit)] = io::json_number(v);
  }
  void both(const std::string& name, const std::string& symbol, const char* unit, double v1, double v2, int digits = 4) {
    t_.add_row({label(name, symbol, unit), num(v1, digits), num(v2, digits)});
    j_[key(symbol, "1", unit)] = io::json_number(v1);
    j_[key(symbol, "2", unit)] = io::json_number(v2);
  }
  // Angles are computed in rad and shown in deg.
  void angles(const std::string& name, const std::string& symbol, double a1, double a2) { both(name, symbol, "deg", a1 * kDeg, a2 * kDeg, 5); }

 private:
  static std::string label(const std::string& name, const std::string& symbol, const char* unit) {
    return *unit ? fmt::format("{} {} [{}]", name, symbol, unit) : fmt::format("{} {}", name, symbol);
  }
  static std::string key(const std::string& symbol, const char* index, const char* unit) {
    std::string k = symbol + index;
    if (*unit) k += std::string("_") + (std::string(unit) == "N m" ? "N_m" : unit);
    return k;
  }
  io::Table& t_;
  nlohmann::json& j_;
};

void geometry_rows(Rows& r, const gg::BevelPairInput& in, const gg::BevelPairResult& p) {
  const auto& a = p.gear[0];
  const auto& b = p.gear[1];
  auto both = [&](const char* name, const char* symbol, const char* unit, double gg::BevelGearResult::*f, int digits = 4) {
    r.both(name, symbol, unit, a.*f, b.*f, digits);
  };
  auto angles = [&](const char* name, const char* symbol, double gg::BevelGearResult::*f) { r.angles(name, symbol, a.*f, b.*f); };
  angles("pitch cone angle", "delta", &gg::BevelGearResult::delta);
  both("outer pitch diameter", "d_e", "mm", &gg::BevelGearResult::d_e);
  both("mean pitch diameter", "d_m", "mm", &gg::BevelGearResult::d_m);
  both("inner pitch diameter", "d_i", "mm", &gg::BevelGearResult::d_i);
  both("addendum modification (outer, m_et)", "x_he", "", &gg::BevelGearResult::x_he);
  both("profile shift (mean, m_mn)", "x_hm", "", &gg::BevelGearResult::x_hm);
  both("outer addendum", "h_ae", "mm", &gg::BevelGearResult::h_ae);
  both("outer dedendum", "h_fe", "mm", &gg::BevelGearResult::h_fe);
  both("mean addendum", "h_am", "mm", &gg::BevelGearResult::h_am);
  both("mean dedendum", "h_fm", "mm", &gg::BevelGearResult::h_fm);
  both("inner addendum", "h_ai", "mm", &gg::BevelGearResult::h_ai);
  both("inner dedendum", "h_fi", "mm", &gg::BevelGearResult::h_fi);
  angles("addendum angle", "theta_a", &gg::BevelGearResult::theta_a);
  angles("dedendum angle", "theta_f", &gg::BevelGearResult::theta_f);
  angles("face (tip) angle", "delta_a", &gg::BevelGearResult::delta_a);
  angles("root angle", "delta_f", &gg::BevelGearResult::delta_f);
  both("outer tip diameter", "d_ae", "mm", &gg::BevelGearResult::d_ae);
  both("outer root diameter", "d_fe", "mm", &gg::BevelGearResult::d_fe);
  both("inner tip diameter", "d_ai", "mm", &gg::BevelGearResult::d_ai);
  both("outer crown to crossing point", "t_xo", "mm", &gg::BevelGearResult::t_xo);
  both("inner crown to crossing point", "t_xi", "mm", &gg::BevelGearResult::t_xi);
  both("axial face width (tip)", "b_x", "mm", &gg::BevelGearResult::b_x);
  both("mean pitch point to crossing point", "t_zm", "mm", &gg::BevelGearResult::t_zm);
  both("virtual teeth", "z_v", "", &gg::BevelGearResult::z_v, 3);
  if (in.beta_m != 0.0) both("virtual teeth (normal)", "z_vn", "", &gg::BevelGearResult::z_vn, 3);
  both("virtual reference diameter", "d_v", "mm", &gg::BevelGearResult::d_v);
  both("virtual tip diameter", "d_va", "mm", &gg::BevelGearResult::d_va);
  both("virtual base diameter", "d_vb", "mm", &gg::BevelGearResult::d_vb);
  both("undercut limit of x_hm", "x_min", "", &gg::BevelGearResult::x_min);
}

void pair_rows(Rows& r, const gg::BevelPairInput& in, const gg::BevelPairResult& p) {
  r.pair("ratio", "u", "", p.u, 5);
  r.pair("shaft angle", "Sigma", "deg", in.Sigma * kDeg, 5);
  r.pair("normal pressure angle", "alpha_n", "deg", in.alpha_n * kDeg, 5);
  r.pair("mean spiral angle", "beta_m", "deg", in.beta_m * kDeg, 5);
  r.pair("face width", "b", "mm", in.b);
  r.pair("outer transverse module", "m_et", "mm", in.m_et);
  r.pair("mean transverse module", "m_mt", "mm", p.m_mt);
  r.pair("mean normal module", "m_mn", "mm", p.m_mn);
  r.pair("inner transverse module", "m_it", "mm", p.m_it);
  r.pair("outer transverse pitch", "p_et", "mm", p.p_et);
  r.pair("outer cone distance", "R_e", "mm", p.R_e);
  r.pair("mean cone distance", "R_m", "mm", p.R_m);
  r.pair("inner cone distance", "R_i", "mm", p.R_i);
  r.pair("clearance (outer)", "c", "mm", p.c);
  r.pair("mean working depth", "h_mw", "mm", p.h_mw);
  r.pair("virtual gear ratio", "u_v", "", p.u_v, 5);
  r.pair("virtual transverse pressure angle", "alpha_vt", "deg", p.alpha_vt * kDeg, 5);
  if (in.beta_m != 0.0) r.pair("virtual base spiral angle", "beta_vb", "deg", p.beta_vb * kDeg, 5);
  r.pair("virtual centre distance", "a_v", "mm", p.a_v);
  r.pair("virtual transverse contact ratio", "eps_va", "", p.eps_va, 3);
  if (in.beta_m != 0.0) {
    r.pair("virtual overlap ratio", "eps_vb", "", p.eps_vb, 3);
    r.pair("virtual total contact ratio", "eps_vg", "", p.eps_vg, 3);
  }
}

void add_forces(io::Report& report, const gg::BevelPairInput& in, const gg::BevelForces& f) {
  io::Table t{"Forces", {"quantity", "gear 1", "gear 2"}, {}};
  nlohmann::json& j = report.json["forces"];
  Rows r(t, j);
  const auto& a = f.gear[0];
  const auto& b = f.gear[1];
  t.add_row({"role", a.driving ? "driving" : "driven", b.driving ? "driving" : "driven"});
  t.add_row({"rotation (seen from the back)", gg::to_string(a.rotation), gg::to_string(b.rotation)});
  j["driver"] = a.driving ? 1 : 2;
  j["rotation1"] = gg::to_string(a.rotation);
  j["rotation2"] = gg::to_string(b.rotation);
  r.both("torque", "T", "N m", a.T, b.T, 3);
  r.both("tangential force", "F_t", "N", a.F_t, b.F_t, 2);
  r.both("radial force", "F_r", "N", a.F_r, b.F_r, 2);
  r.both("axial force", "F_a", "N", a.F_a, b.F_a, 2);
  r.both("normal tooth force", "F_n", "N", a.F_n, b.F_n, 2);
  j["beta_s_deg"] = io::json_number(f.beta_s * kDeg);
  report.tables.push_back(std::move(t));
  report.notes.push_back("Forces at the mean point of the face width, no friction: F_r > 0 towards the gear's own axis, F_a > 0 along "
                         "its axis away from the apex (out of mesh); F_t opposes the driving gear's rotation and drives the driven one.");
  if (in.type == gg::BevelType::spiral) {
    const int driver = a.driving ? 0 : 1;
    report.notes.push_back(fmt::format("The axial force on the driving gear {} points {} (hand {} of gear 1, {} seen from its back); "
                                       "reversing the sense of rotation reverses the spiral part of the axial force.",
                                       driver + 1, f.gear[driver].F_a >= 0.0 ? "away from the apex (out of mesh)" : "towards the apex (into mesh)",
                                       gg::to_string(in.hand1), gg::to_string(a.rotation)));
  }
}

}  // namespace

io::Report bevel_report(const gg::BevelPairInput& in, const gg::BevelPairResult& p, const std::optional<gg::BevelForces>& forces) {
  io::Report report;
  report.title = fmt::format("Bevel gear pair: {}, z1 = {}, z2 = {}, m_et = {:g} mm, Sigma = {:g} deg, b = {:g} mm ({} proportions, {} depth)",
                             gg::to_string(in.type), in.z1, in.z2, in.m_et, in.Sigma * kDeg, in.b, gg::to_string(in.system), gg::to_string(in.taper));
  nlohmann::json& j = report.json["bevel"];
  j["type"] = gg::to_string(in.type);
  j["system"] = gg::to_string(in.system);
  j["depth"] = gg::to_string(in.taper);
  j["z1"] = in.z1;
  j["z2"] = in.z2;
  io::Table pair{"Pair", {"quantity", "value"}, {}};
  Rows pr(pair, j);
  pair_rows(pr, in, p);
  io::Table gears{"Gears", {"quantity", "gear 1", "gear 2"}, {}};
  if (in.type == gg::BevelType::spiral) {
    gears.add_row({"hand of spiral", gg::to_string(p.gear[0].hand), gg::to_string(p.gear[1].hand)});
    j["hand1"] = gg::to_string(p.gear[0].hand);
    j["hand2"] = gg::to_string(p.gear[1].hand);
  }
  Rows gr(gears, j);
  geometry_rows(gr, in, p);
  report.tables.push_back(std::move(pair));
  report.tables.push_back(std::move(gears));
  if (forces) add_forces(report, in, *forces);
  report.notes.push_back("Cone geometry ISO 23509; proportions Gleason (KHK gear technical reference) or ISO 23509; virtual gears ISO 10300-1. "
                         "t_xo: axial distance from the crossing point of the axes to the crown. Conventions: docs/bevel.md.");
  report.warnings = p.warnings;
  return report;
}

}  // namespace gearkit::plugins::gear
