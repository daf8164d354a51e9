#include "gear_rating_options.hpp"

#include "gear_tolerance_options.hpp"

#include <gearkit/io/error.hpp>
#include <gearkit/io/quantity.hpp>

#include <fmt/format.h>

#include <array>
#include <charconv>
#include <cmath>
#include <map>
#include <numbers>

namespace gearkit::plugins::gear {

namespace gg = gearkit::gear;

namespace {

constexpr double kRpm = 30.0 / std::numbers::pi;  // (rad/s) -> 1/min

[[noreturn]] void fail(std::string_view key, std::string_view message) { io::fail_option(fmt::format("--{}", key), message); }

bool given(const io::po::variables_map& vm, const char* key) { return vm.count(key) > 0; }

std::string text_of(const io::po::variables_map& vm, const char* key) { return vm[key].as<std::string>(); }

double quantity(const io::po::variables_map& vm, const char* key, io::Quantity q, const char* unit) {
  try {
    return io::parse_option_quantity_si(text_of(vm, key), q, unit);
  } catch (const io::QuantityError& e) {
    fail(key, e.what());
  }
}

// A plain number > 0 (or >= 0 with `zero_ok`).
double positive(const io::po::variables_map& vm, const char* key, bool zero_ok = false) {
  const double v = quantity(vm, key, io::Quantity::dimensionless, "");
  if (!(std::isfinite(v) && (v > 0.0 || (zero_ok && v == 0.0)))) {
    fail(key, fmt::format("expected a number {} 0, found {}", zero_ok ? ">=" : ">", text_of(vm, key).substr(0, 60)));
  }
  return v;
}

// A length > 0 (or >= 0 with `zero_ok`) in `unit` ("um", "mm"), the unit of a bare number too.
double length_in(const io::po::variables_map& vm, const char* key, const char* unit, bool zero_ok = false) {
  const double v = quantity(vm, key, io::Quantity::length, unit) / io::unit_factor_si(unit, io::Quantity::length);
  if (!(v > 0.0 || (zero_ok && v == 0.0))) {
    fail(key, fmt::format("expected a length {} 0, found {}", zero_ok ? ">=" : ">", text_of(vm, key).substr(0, 60)));
  }
  return v;
}

int whole(const io::po::variables_map& vm, const char* key, int lo, int hi) {
  const std::string s = text_of(vm, key);
  int v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || end != s.data() + s.size() || v < lo || v > hi) {
    fail(key, fmt::format("expected a whole number {}..{}, found '{}'", lo, hi, s.substr(0, 60)));
  }
  return v;
}

template <class Enum>
Enum choice(const io::po::variables_map& vm, const char* key, const std::map<std::string, Enum>& choices) {
  const std::string s = text_of(vm, key);
  const auto it = choices.find(s);
  if (it == choices.end()) {
    std::string names;
    for (const auto& [n, e] : choices) names += fmt::format("{}{}", names.empty() ? "" : ", ", n);
    fail(key, fmt::format("expected one of {}, found '{}'", names, s.substr(0, 60)));
  }
  return it->second;
}

// One value for both gears or two separated by a comma ("0.5" or "0.4,0.8"), each >= 0 (> 0
// unless `zero_ok`): plain numbers, or quantities `q` whose bare numbers and result are in `unit`.
std::array<double, 2> per_gear(const io::po::variables_map& vm, const char* key, bool zero_ok,
                               io::Quantity q = io::Quantity::dimensionless, const char* unit = "") {
  const std::string s = text_of(vm, key);
  const auto comma = s.find(',');
  const std::string parts[2] = {s.substr(0, comma), comma == std::string::npos ? s : s.substr(comma + 1)};
  std::array<double, 2> v{};
  if (parts[1].find(',') != std::string::npos) {
    fail(key, fmt::format("expected one number or two (gear 1,gear 2), found {}", s.substr(0, 60)));
  }
  for (int i = 0; i < 2; ++i) {
    try {
      v[i] = io::parse_option_quantity_si(parts[i], q, unit) / (*unit ? io::unit_factor_si(unit, q) : 1.0);
    } catch (const io::QuantityError& e) {
      fail(key, e.what());
    }
    if (!(std::isfinite(v[i]) && (v[i] > 0.0 || (zero_ok && v[i] == 0.0)))) {
      fail(key, fmt::format("expected one number {} 0 or two (gear 1,gear 2), found {}", zero_ok ? ">=" : ">", s.substr(0, 60)));
    }
  }
  return v;
}

void read_torque(const io::po::variables_map& vm, gg::RatingInput& r) {
  if (given(vm, "torque1") && given(vm, "torque2")) fail("torque2", "cannot be combined with --torque1: give one of them");
  if (given(vm, "torque2") && given(vm, "power")) fail("power", "cannot be combined with --torque2: give one of them");
  if (given(vm, "torque2")) {
    r.T_2 = quantity(vm, "torque2", io::Quantity::torque, "N*m");
    if (!(r.T_2 > 0.0)) fail("torque2", fmt::format("expected a torque > 0, found {}", text_of(vm, "torque2").substr(0, 60)));
  } else if (given(vm, "torque1")) {
    r.T_1 = quantity(vm, "torque1", io::Quantity::torque, "N*m");
    if (!(r.T_1 > 0.0)) fail("torque1", fmt::format("expected a torque > 0, found {}", text_of(vm, "torque1").substr(0, 60)));
  } else {
    const double P = quantity(vm, "power", io::Quantity::power, "");
    if (!(P > 0.0)) fail("power", fmt::format("expected a power > 0, found {}", text_of(vm, "power").substr(0, 60)));
    r.T_1 = P / (r.n_1 / kRpm);
  }
}

void read_load(const io::po::variables_map& vm, gg::RatingInput& r) {
  if (given(vm, "torque1") && given(vm, "power")) fail("power", "cannot be combined with --torque1: give one of them");
  if (!given(vm, "speed1")) fail(given(vm, "power") ? "power" : given(vm, "torque2") ? "torque2" : "torque1", "the rating needs --speed1 (pinion speed, rpm)");
  r.n_1 = quantity(vm, "speed1", io::Quantity::angular_velocity, "rpm") * kRpm;
  if (!(r.n_1 > 0.0)) fail("speed1", fmt::format("expected a speed > 0, found {}", text_of(vm, "speed1").substr(0, 60)));
  read_torque(vm, r);
  if (given(vm, "application-factor")) r.K_A = positive(vm, "application-factor");
  if (r.K_A < 1.0) fail("application-factor", fmt::format("expected K_A >= 1, found {}", r.K_A));
  if (given(vm, "life")) {
    r.life_h = quantity(vm, "life", io::Quantity::time, "h") / 3600.0;
    if (!(r.life_h > 0.0)) fail("life", fmt::format("expected a life > 0 h, found {}", text_of(vm, "life").substr(0, 60)));
  }
  if (given(vm, "life-cycles")) {
    if (given(vm, "life")) fail("life-cycles", "cannot be combined with --life: give the life in hours or in load cycles");
    r.N_L1 = positive(vm, "life-cycles");
  }
  r.reversed_bending = {vm["reversed-bending1"].as<bool>(), vm["reversed-bending2"].as<bool>()};
}

// Usable tip diameters and tip chamfers (the rating's tips).
void read_tips(const io::po::variables_map& vm, gg::RatingInput& r) {
  for (int i = 0; i < 2; ++i) {
    const char* usable = i == 0 ? "usable-tip-diameter1" : "usable-tip-diameter2";
    const char* chamfer = i == 0 ? "tip-chamfer1" : "tip-chamfer2";
    if (given(vm, usable) && given(vm, chamfer)) fail(chamfer, fmt::format("cannot be combined with --{}: give one of them", usable));
    if (given(vm, usable)) r.d_Na[i] = quantity(vm, usable, io::Quantity::length, "mm") * 1000.0;
    if (given(vm, chamfer)) r.h_K[i] = quantity(vm, chamfer, io::Quantity::length, "mm") * 1000.0;
  }
}

void read_materials(const io::po::variables_map& vm, gg::RatingInput& r) {
  for (int i = 0; i < 2; ++i) {
    const char* key = i == 0 ? "material1" : "material2";
    if (!given(vm, key)) fail(key, "the rating needs both materials (a name such as 18CrNiMo7-6, or CLASS:GRADE:HARDNESS)");
    try {
      r.material[i] = material_named(text_of(vm, key));
    } catch (const std::invalid_argument& e) {
      fail(key, e.what());
    }
  }
}

void read_quality_and_deviations(const io::po::variables_map& vm, gg::RatingInput& r) {
  // One reader for the grade of the tolerances and of the rating (the edition decides the range);
  // "6,7": the mesh is rated with the coarser grade.
  const auto grades = read_quality(vm);
  if (grades[0]) {
    r.quality = std::max(*grades[0], grades[1].value_or(*grades[0]));
    r.iso1328_edition = read_iso1328_edition(vm);
  }
  const std::pair<const char*, double gg::RatingInput::*> deviations[] = {
      {"f-pb", &gg::RatingInput::f_pb}, {"f-falpha", &gg::RatingInput::f_falpha}, {"F-betax", &gg::RatingInput::F_betax},
      {"f-ma", &gg::RatingInput::f_ma}, {"f-sh", &gg::RatingInput::f_sh}, {"tip-relief", &gg::RatingInput::C_a}};
  for (const auto& [key, field] : deviations) {
    if (given(vm, key)) r.*field = length_in(vm, key, "um", true);
  }
}

// The pinion shaft and flank line modification of K_Hbeta method C (ISO 6336-1 7.6, Figure 13, Table 10).
void read_face_load_options(const io::po::variables_map& vm, gg::RatingInput& r) {
  gg::FaceLoadInput& f = r.face_load;
  auto length = [&](const char* key) {
    const double v = quantity(vm, key, io::Quantity::length, "mm") * 1000.0;
    if (!(std::isfinite(v) && v >= 0.0)) fail(key, fmt::format("expected a length >= 0 mm, found {}", text_of(vm, key).substr(0, 60)));
    return v;
  };
  if (given(vm, "shaft-span")) f.l = length("shaft-span");
  if (given(vm, "pinion-offset")) f.s = length("pinion-offset");
  if (given(vm, "shaft-diameter")) f.d_sh = length("shaft-diameter");
  namespace iso = gg::iso6336;
  if (given(vm, "shaft-arrangement")) {
    f.arrangement = choice<iso::ShaftArrangement>(vm, "shaft-arrangement", {{"a", iso::ShaftArrangement::a}, {"b", iso::ShaftArrangement::b},
                                                                            {"c", iso::ShaftArrangement::c}, {"d", iso::ShaftArrangement::d},
                                                                            {"e", iso::ShaftArrangement::e}});
  }
  if (given(vm, "stiffening")) f.stiffening = choice<bool>(vm, "stiffening", {{"yes", true}, {"no", false}});
  if (given(vm, "torque-share")) {
    f.torque_percent = positive(vm, "torque-share");
    if (f.torque_percent > 100.0) fail("torque-share", fmt::format("expected a percentage in (0, 100], found {}", f.torque_percent));
  }
  if (given(vm, "helix-modification")) {
    f.modification = choice<iso::HelixModification>(vm, "helix-modification",
                                                     {{"none", iso::HelixModification::none}, {"helix-correction", iso::HelixModification::helix_correction},
                                                      {"helix-correction-and-crowning", iso::HelixModification::helix_correction_and_crowning},
                                                      {"crowning", iso::HelixModification::crowning}, {"end-relief", iso::HelixModification::end_relief}});
  }
}

void read_surface_and_lubrication(const io::po::variables_map& vm, gg::RatingInput& r) {
  if (given(vm, "oil-viscosity")) r.nu_40 = positive(vm, "oil-viscosity");
  if (given(vm, "flank-roughness")) {
    const auto R_a = per_gear(vm, "flank-roughness", false, io::Quantity::length, "um");
    r.R_z_flank = {6.0 * R_a[0], 6.0 * R_a[1]};
  }
  if (given(vm, "flank-rz")) {
    if (given(vm, "flank-roughness")) fail("flank-rz", "cannot be combined with --flank-roughness (R_a): give one of them");
    r.R_z_flank = per_gear(vm, "flank-rz", false, io::Quantity::length, "um");
  }
  if (given(vm, "protuberance")) {
    const auto s_pr = per_gear(vm, "protuberance", true);
    r.s_pr = s_pr[0];
    if (s_pr[1] != s_pr[0]) r.s_pr_gear = {s_pr[0], s_pr[1]};
  }
  if (given(vm, "root-roughness")) r.R_z_root = per_gear(vm, "root-roughness", true, io::Quantity::length, "um");
  if (given(vm, "rim1")) r.s_R[0] = length_in(vm, "rim1", "mm");
  if (given(vm, "rim2")) r.s_R[1] = length_in(vm, "rim2", "mm");
  if (given(vm, "min-safety-pitting")) r.S_Hmin = positive(vm, "min-safety-pitting");
  if (given(vm, "min-safety-bending")) r.S_Fmin = positive(vm, "min-safety-bending");
  r.limited_pitting = vm["limited-pitting"].as<bool>();
  r.optimum_long_life = vm["optimum-long-life"].as<bool>();
  if (given(vm, "root-shift")) {
    r.root_shift = choice<gg::RootShift>(vm, "root-shift", {{"generating", gg::RootShift::generating}, {"nominal", gg::RootShift::nominal}});
  }
}

// The oil for scuffing (ISO/TS 6336-21): rated when --fzg-stage is given.
void read_scuffing_options(const io::po::variables_map& vm, gg::RatingInput& r) {
  namespace iso = gg::iso6336;
  gg::ScuffingInput& s = r.scuffing;
  if (given(vm, "fzg-stage")) s.fzg_stage = whole(vm, "fzg-stage", 1, 14);
  if (given(vm, "oil-temperature")) {
    s.theta_oil = quantity(vm, "oil-temperature", io::Quantity::dimensionless, "");
    if (!(s.theta_oil > -40.0 && s.theta_oil < 200.0)) fail("oil-temperature", fmt::format("expected -40 < T < 200 deg C, found {}", text_of(vm, "oil-temperature").substr(0, 60)));
  }
  if (given(vm, "oil-viscosity-100")) s.nu_100 = positive(vm, "oil-viscosity-100");
  if (given(vm, "oil-density")) s.rho_15 = positive(vm, "oil-density");
  if (given(vm, "oil-type")) {
    std::map<std::string, iso::OilBase> names;
    for (iso::OilBase b : iso::kOilBases) names[iso::to_string(b)] = b;
    s.oil = choice(vm, "oil-type", names);
  }
  if (given(vm, "lubrication")) {
    std::map<std::string, iso::Lubrication> names;
    for (iso::Lubrication l : iso::kLubrications) names[iso::to_string(l)] = l;
    s.lubrication = choice(vm, "lubrication", names);
  }
  if (given(vm, "driving-gear")) s.gear1_driving = whole(vm, "driving-gear", 1, 2) == 1;
  if (given(vm, "min-safety-scuffing")) s.S_Smin = positive(vm, "min-safety-scuffing");
}

void read_method_options(const io::po::variables_map& vm, gg::RatingInput& r) {
  if (given(vm, "method")) {
    r.method = choice<gg::RatingMethod>(vm, "method", {{"iso6336", gg::RatingMethod::iso6336}, {"agma", gg::RatingMethod::agma},
                                                       {"lewis-hertz", gg::RatingMethod::lewis_hertz}});
  }
  if (given(vm, "agma-quality")) r.Q_v = whole(vm, "agma-quality", 3, 16);
  if (given(vm, "reliability")) {
    r.reliability = positive(vm, "reliability");
    if (!(r.reliability > 0.5 && r.reliability < 1.0)) fail("reliability", fmt::format("expected 0.5 < R < 1, found {}", r.reliability));
  }
  if (given(vm, "mounting")) {
    r.agma_mounting = choice<gg::AgmaMounting>(vm, "mounting", {{"open", gg::AgmaMounting::open}, {"commercial", gg::AgmaMounting::commercial},
                                                               {"precision", gg::AgmaMounting::precision},
                                                               {"extra-precision", gg::AgmaMounting::extra_precision}});
  }
  r.agma_crowned = vm["crowned"].as<bool>();
  if (given(vm, "lewis-profile")) {
    r.lewis_profile = choice<gg::LewisProfile>(vm, "lewis-profile", {{"cast", gg::LewisProfile::cast}, {"cut", gg::LewisProfile::cut},
                                                                     {"hobbed", gg::LewisProfile::hobbed}, {"ground", gg::LewisProfile::ground}});
  }
  if (given(vm, "factor")) {
    for (const std::string& f : vm["factor"].as<std::vector<std::string>>()) {
      try {
        parse_factor(f, r.factors);
      } catch (const std::invalid_argument& e) {
        fail("factor", e.what());
      }
    }
  }
}

}  // namespace

void add_rating_options(io::po::options_description& desc) {
  namespace po = io::po;
  auto text = [] { return po::value<std::string>(); };
  desc.add_options()
      ("torque1", text()->value_name("TORQUE"), "rating: torque on gear 1 (unit required, e.g. 9kN*m)")
      ("torque2", text()->value_name("TORQUE"), "rating: torque on gear 2, instead of --torque1 (T_1 = T_2 z1/z2, mesh efficiency 1) (unit required, e.g. 9kN*m)")
      ("power", text()->value_name("POWER"), "rating: transmitted power, instead of --torque1 (unit required, e.g. 7.5kW)")
      ("speed1", text()->value_name("SPEED"), "rating: speed of gear 1 (unit required, e.g. 1450rpm)")
      ("material1", text()->value_name("NAME"), "rating: material of gear 1 (18CrNiMo7-6, 42CrMo4, ..., or CLASS:GRADE:HARDNESS)")
      ("material2", text()->value_name("NAME"), "rating: material of gear 2")
      ("method", text()->value_name("iso6336|agma|lewis-hertz"), "rating method (default iso6336)")
      ("application-factor", text()->value_name("K_A"), "application factor K_A (default 1)")
      ("life", text()->value_name("TIME"), "required life (default 20000 h) (bare number: h)")
      ("life-cycles", text()->value_name("N"), "required life as load cycles of gear 1 (instead of --life)")
      ("reversed-bending1", po::bool_switch(), "gear 1 is loaded on both flanks (idler, planet): fully reversed bending, Y_M = 0.7")
      ("reversed-bending2", po::bool_switch(), "gear 2 is loaded on both flanks: Y_M = 0.7")
      ("usable-tip-diameter1", text()->value_name("LEN"), "usable tip diameter d_Na1 (end of the involute below a chamfer) (bare number: mm)")
      ("usable-tip-diameter2", text()->value_name("LEN"), "usable tip diameter d_Na2 (bare number: mm)")
      ("tip-chamfer1", text()->value_name("LEN"), "radial tip chamfer h_K1, d_Na1 = d_a1 - 2 h_K1 (bare number: mm)")
      ("tip-chamfer2", text()->value_name("LEN"), "radial tip chamfer h_K2 (bare number: mm)")
      ("oil-viscosity", text()->value_name("NU40"), "kinematic viscosity at 40 C, a plain number (default 220) (bare number: mm^2/s)")
      ("oil-viscosity-100", text()->value_name("NU100"), "scuffing: kinematic viscosity at 100 C, a plain number (bare number: mm^2/s)")
      ("oil-temperature", text()->value_name("TEMP"), "scuffing: oil temperature (sump or injection), a plain number (bare number: deg C)")
      ("oil-density", text()->value_name("RHO15"), "scuffing: oil density at 15 C, a plain number (default 0.89) (bare number: kg/dm^3)")
      ("oil-type", text()->value_name("mineral|pao|pag|pag-water-soluble|phosphate-ester|traction"), "scuffing: base oil, the lubricant factor X_L (default mineral)")
      ("fzg-stage", text()->value_name("STAGE"), "scuffing: failure load stage 1..14 of the oil in the FZG test A/8.3/90 (ISO 14635-1); rates scuffing by ISO/TS 6336-21")
      ("lubrication", text()->value_name("dip|spray|immersed"), "scuffing: lubrication method, X_S (default dip)")
      ("driving-gear", text()->value_name("1|2"), "scuffing: the gear that drives, for the approach factor X_Q (default 1)")
      ("min-safety-scuffing", text()->value_name("S"), "required S_intS (default 2.0)")
      ("flank-roughness", text()->value_name("LEN[,LEN2]"), "flank roughness R_a of both gears or gear 1,gear 2 (default 0.5 um: R_z = 3 um) (bare number: um)")
      ("flank-rz", text()->value_name("LEN[,LEN2]"), "flank roughness R_z, instead of --flank-roughness (bare number: um)")
      ("root-roughness", text()->value_name("LEN[,LEN2]"), "root roughness R_z of both gears or gear 1,gear 2 (default 10 um) (bare number: um)")
      ("protuberance", text()->value_name("COEF[,COEF2]"), "residual protuberance of the tool s_pr / m_n = (p_r - q)/m_n, both gears or gear 1,gear 2 (ISO 6336-3 Eq. 19; default 0)")
      ("f-pb", text()->value_name("LEN"), "transverse base pitch deviation f_pb (default from --quality) (bare number: um)")
      ("f-falpha", text()->value_name("LEN"), "profile form deviation f_falpha (default from --quality) (bare number: um)")
      ("F-betax", text()->value_name("LEN"), "initial equivalent misalignment F_betax, instead of f_ma, f_sh (bare number: um)")
      ("f-ma", text()->value_name("LEN"), "mesh misalignment from manufacturing f_ma (default f_HbetaT of --quality) (bare number: um)")
      ("f-sh", text()->value_name("LEN"), "misalignment from shaft deflection f_sh (default ISO 6336-1 Eq. 43) (bare number: um)")
      ("tip-relief", text()->value_name("LEN"), "tip relief C_a (default: by running-in) (bare number: um)")
      ("shaft-span", text()->value_name("LEN"), "K_Hbeta: bearing span l of the pinion shaft (ISO 6336-1 Eq. 43) (bare number: mm)")
      ("pinion-offset", text()->value_name("LEN"), "K_Hbeta: offset s of the pinion from the middle of the span (bare number: mm)")
      ("shaft-diameter", text()->value_name("LEN"), "K_Hbeta: outer diameter d_sh of the pinion shaft (bare number: mm)")
      ("shaft-arrangement", text()->value_name("a|b|c|d|e"), "K_Hbeta: arrangement of ISO 6336-1 Figure 13 for K' (default a)")
      ("stiffening", text()->value_name("yes|no"), "K_Hbeta: K' with or without stiffening (default: yes when d_1/d_sh >= 1.15)")
      ("torque-share", text()->value_name("PERCENT"), "K_Hbeta: percentage k of the pinion torque on this mesh, B* (default 100)")
      ("helix-modification", text()->value_name("none|helix-correction|helix-correction-and-crowning|crowning|end-relief"),
       "K_Hbeta: flank line modification, B_1 and B_2 of ISO 6336-1 Table 10 (default none)")
      ("rim1", text()->value_name("LEN"), "rim thickness of gear 1 (default solid) (bare number: mm)")
      ("rim2", text()->value_name("LEN"), "rim thickness of gear 2 (default solid) (bare number: mm)")
      ("min-safety-pitting", text()->value_name("S"), "required S_Hmin (default 1.0)")
      ("min-safety-bending", text()->value_name("S"), "required S_Fmin (default 1.4)")
      ("limited-pitting", po::bool_switch(), "Z_NT line with limited pitting permitted")
      ("optimum-long-life", po::bool_switch(), "Z_NT = Y_NT = 1 at 1e10 cycles (optimum conditions) instead of 0.85")
      ("root-shift", text()->value_name("generating|nominal"), "profile shift for Y_F, Y_S (default generating: with the allowance)")
      ("agma-quality", text()->value_name("QV"), "AGMA quality number Q_v (default 17 - ISO grade)")
      ("reliability", text()->value_name("R"), "AGMA reliability (default 0.99)")
      ("mounting", text()->value_name("open|commercial|precision|extra-precision"), "AGMA gearing condition (default commercial)")
      ("crowned", po::bool_switch(), "AGMA: crowned teeth (C_mc = 0.8)")
      ("lewis-profile", text()->value_name("cast|cut|hobbed|ground"), "Lewis: tooth manufacture for the Barth factor (default hobbed)")
      ("factor", po::value<std::vector<std::string>>()->composing()->value_name("NAME=VALUE"),
       "impose a factor (K_v, K_Hbeta, Z_NT1, Y_F, J1, ...), repeatable");
  if (!desc.find_nothrow("quality", false)) {
    desc.add_options()("quality", text()->value_name("GRADE[,GRADE]"), "ISO 1328-1:2013 flank tolerance class 1..11 (both gears, or gear 1,gear 2)");
  }
}

bool rating_requested(const io::po::variables_map& vm) { return given(vm, "torque1") || given(vm, "torque2") || given(vm, "power"); }

bool any_rating_option(const io::po::variables_map& vm) {
  for (const char* key : {"torque1", "power", "speed1", "material1", "material2", "method", "application-factor", "life",
                          "oil-viscosity", "flank-roughness", "flank-rz", "protuberance", "root-roughness", "f-pb", "f-falpha", "F-betax", "f-ma", "f-sh",
                          "tip-relief", "shaft-span", "pinion-offset", "shaft-diameter", "shaft-arrangement", "stiffening", "torque-share",
                          "helix-modification", "rim1", "rim2", "min-safety-pitting", "min-safety-bending", "root-shift", "agma-quality",
                          "reliability", "mounting", "lewis-profile", "factor", "torque2", "life-cycles", "usable-tip-diameter1",
                          "usable-tip-diameter2", "tip-chamfer1", "tip-chamfer2", "oil-viscosity-100", "oil-temperature", "oil-density",
                          "oil-type", "fzg-stage", "lubrication", "driving-gear", "min-safety-scuffing"}) {
    if (given(vm, key)) return true;
  }
  return vm["limited-pitting"].as<bool>() || vm["optimum-long-life"].as<bool>() || vm["crowned"].as<bool>() ||
         vm["reversed-bending1"].as<bool>() || vm["reversed-bending2"].as<bool>();
}

gg::RatingInput read_rating_options(const io::po::variables_map& vm) {
  gg::RatingInput r;
  read_load(vm, r);
  read_materials(vm, r);
  read_quality_and_deviations(vm, r);
  read_face_load_options(vm, r);
  read_surface_and_lubrication(vm, r);
  read_method_options(vm, r);
  read_scuffing_options(vm, r);
  read_tips(vm, r);
  return r;
}

void parse_factor(std::string_view text, gg::ImposedFactors& factors) {
  const auto eq = text.find('=');
  if (eq == std::string_view::npos) {
    throw std::invalid_argument(fmt::format("expected NAME=VALUE, found '{}'", text.substr(0, 60)));
  }
  const std::string_view name = text.substr(0, eq), value = text.substr(eq + 1);
  const auto which = gg::factors_named(name);
  if (which.empty()) {
    throw std::invalid_argument(fmt::format("unknown factor '{}'; expected one of {}", name.substr(0, 60), gg::factor_names()));
  }
  double v = 0;
  const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
  if (value.empty() || ec != std::errc() || end != value.data() + value.size() || !std::isfinite(v) || !(v > 0.0)) {
    throw std::invalid_argument(fmt::format("expected a number > 0 for {}, found '{}'", name, value.substr(0, 60)));
  }
  for (gg::Factor f : which) factors.set(f, v);
}

std::string option_for_rating_field(const std::string& field) {
  static const std::map<std::string, std::string> options = {
      {"T_1", "torque1"}, {"n_1", "speed1"}, {"K_A", "application-factor"}, {"quality", "quality"}, {"life_h", "life"},
      {"nu_40", "oil-viscosity"}, {"S_Hmin", "min-safety-pitting"}, {"S_Fmin", "min-safety-bending"},
      {"material1", "material1"}, {"material2", "material2"}, {"f_pb", "f-pb"}, {"f_falpha", "f-falpha"},
      {"f_ma", "f-ma"}, {"F_betax", "F-betax"}, {"face_width", "face-width"}, {"Q_v", "agma-quality"},
      {"reliability", "reliability"}, {"factor", "factor"}, {"R_z_flank", "flank-roughness"}, {"R_z_root", "root-roughness"},
      {"s_R", "rim1"}, {"face_load", "shaft-span"}, {"tooth_root", "x1"}, {"spectrum", "life"}, {"T_2", "torque2"}, {"N_L1", "life-cycles"},
      {"d_Na1", "usable-tip-diameter1"}, {"d_Na2", "usable-tip-diameter2"}, {"h_K1", "tip-chamfer1"}, {"h_K2", "tip-chamfer2"},
      {"s_pr", "protuberance"}, {"A_sne", "thickness-allowances1"}, {"fzg_stage", "fzg-stage"}, {"theta_oil", "oil-temperature"},
      {"nu_100", "oil-viscosity-100"}, {"rho_15", "oil-density"}, {"S_Smin", "min-safety-scuffing"}};
  const auto it = options.find(field);
  return it == options.end() ? field : it->second;
}

gg::Material material_named(std::string_view name) { return gg::material_by_name(name); }

}  // namespace gearkit::plugins::gear
