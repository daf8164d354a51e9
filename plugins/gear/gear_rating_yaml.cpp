// YAML readers of the rating input shared by gear-pair and train files.
#include "gear_rating_yaml.hpp"

#include "gear_rating_options.hpp"

#include <gearkit/gear/inspection.hpp>
#include <gearkit/io/error.hpp>
#include <gearkit/io/yaml_model.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace gearkit::plugins::gear {

namespace gg = gearkit::gear;

using io::MapReader;
using io::Quantity;

gg::Material read_material(const YAML::Node& node, const std::string& file, const char* what) {
  if (node.IsScalar()) {
    try {
      return gg::material_by_name(io::scalar_text(node, file, what));
    } catch (const std::invalid_argument& e) {
      io::fail_at(io::mark_of(node, file), e.what());
    }
  }
  MapReader m(node, file, what);
  gg::Material mat;
  if (m.has("class")) {
    const std::string spec = fmt::format("{}:{}:{}", m.string("class"), m.choice("grade", {"ML", "MQ", "ME"}, "MQ"), m.number("hardness"));
    try {
      mat = gg::material_by_name(spec);
    } catch (const std::invalid_argument& e) {
      io::fail_at(m.mark("class"), e.what());
    }
  }
  mat.name = m.optional_string("name").value_or(mat.name.empty() ? std::string("user-defined") : mat.name);
  mat.sigma_Hlim = m.quantity_or("sigma_Hlim", Quantity::pressure, "MPa", mat.sigma_Hlim * 1e6) / 1e6;
  mat.sigma_Flim = m.quantity_or("sigma_Flim", Quantity::pressure, "MPa", mat.sigma_Flim * 1e6) / 1e6;
  mat.E = m.quantity_or("E", Quantity::pressure, "MPa", mat.E * 1e6) / 1e6;
  mat.nu = m.optional_number("nu").value_or(mat.nu);
  mat.HB = m.optional_number("HB").value_or(mat.HB);
  try {
    gg::validate(mat);
  } catch (const std::invalid_argument& e) {
    io::fail_at(m.mark(), e.what());
  }
  m.finish();
  return mat;
}

void read_accuracy(MapReader& r, gg::RatingInput& in) {
  if (auto q = r.optional_integer("quality")) {
    if (*q < -1000 || *q > 1000) io::fail_at(r.mark("quality"), fmt::format("expected an ISO 1328 grade, found {}", *q));
    in.quality = static_cast<int>(*q);
  }
  const std::string edition = r.choice("iso1328_edition", {"2013", "1995"}, "2013");
  in.iso1328_edition = edition == "1995" ? gg::Iso1328Edition::iso1995 : gg::Iso1328Edition::iso2013;
}

namespace {

double length_mm(MapReader& r, const char* key, double default_mm) {
  const double v = r.quantity_or(key, Quantity::length, "mm", default_mm / 1000.0) * 1000.0;
  if (!(std::isfinite(v) && v >= 0.0)) io::fail_at(r.mark(key), fmt::format("expected a length >= 0 mm, found {:g} mm", v));
  return v;
}

}  // namespace

void read_face_load(MapReader& r, gg::FaceLoadInput& f) {
  namespace iso = gg::iso6336;
  if (r.has("model")) f.model = r.choice("model", {"pinion-shaft", "sun"}) == "sun" ? gg::FaceLoadModel::sun : gg::FaceLoadModel::pinion_shaft;
  if (auto n = r.optional_integer("planets")) {
    if (*n < 1 || *n > 1000) io::fail_at(r.mark("planets"), fmt::format("expected 1..1000 planets, found {}", *n));
    f.planets = static_cast<int>(*n);
  }
  f.l = length_mm(r, "span", f.l);
  f.s = length_mm(r, "offset", f.s);
  f.d_sh = length_mm(r, "shaft_diameter", f.d_sh);
  if (r.has("arrangement")) f.arrangement = static_cast<iso::ShaftArrangement>(r.choice("arrangement", {"a", "b", "c", "d", "e"})[0] - 'a');
  if (r.has("stiffening")) f.stiffening = r.boolean("stiffening");
  if (auto k = r.optional_number("K_prime")) f.K_prime = *k;
  if (auto k = r.optional_number("torque_share")) {
    if (!(*k > 0.0 && *k <= 100.0)) io::fail_at(r.mark("torque_share"), fmt::format("expected a percentage in (0, 100], found {:g}", *k));
    f.torque_percent = *k;
  }
  if (r.has("helix_modification")) {
    static const std::vector<std::string> kNames = {"none", "helix-correction", "helix-correction-and-crowning", "crowning", "end-relief"};
    const std::string m = r.choice("helix_modification", kNames);
    f.modification = static_cast<iso::HelixModification>(std::find(kNames.begin(), kNames.end(), m) - kNames.begin());
  }
  r.finish();
}

// Keys of one gear (suffix 1 or 2): roughness, tool protuberance, fully reversed bending, usable tip.
void read_per_gear_keys(MapReader& r, gg::RatingInput& in, std::map<std::string, io::SourceMark>& marks) {
  auto um = [](MapReader& m, const std::string& key) { return m.quantity(key, Quantity::length, "um") * 1e6; };
  for (int i = 0; i < 2; ++i) {
    const std::string n = std::to_string(i + 1);
    const std::string ra = "flank_roughness" + n, rz = "flank_rz" + n, root = "root_roughness" + n, s_pr = "protuberance" + n;
    if (r.has(ra) && r.has(rz)) io::fail_at(r.mark(rz), fmt::format("give {} (R_a) or {}, not both", ra, rz));
    if (r.has(ra)) in.R_z_flank[i] = 6.0 * um(r, ra);
    if (r.has(rz)) in.R_z_flank[i] = um(r, rz);
    if (r.has(root)) in.R_z_root[i] = um(r, root);
    if (r.has(s_pr)) in.s_pr_gear[i] = r.number(s_pr);
    in.reversed_bending[i] = r.boolean_or("reversed_bending" + n, in.reversed_bending[i]);
    const std::string usable = "usable_tip_diameter" + n, chamfer = "tip_chamfer" + n;
    if (r.has(usable)) in.d_Na[i] = r.quantity(usable, Quantity::length, "mm") * 1000.0;
    if (r.has(chamfer)) in.h_K[i] = r.quantity(chamfer, Quantity::length, "mm") * 1000.0;
    marks["d_Na" + n] = r.mark(usable);
    marks["h_K" + n] = r.mark(chamfer);
  }
  if (r.has("flank_roughness1")) marks["R_z_flank"] = r.mark("flank_roughness1");
  if (r.has("root_roughness1")) marks["R_z_root"] = r.mark("root_roughness1");
  if (r.has("protuberance1")) marks["s_pr"] = r.mark("protuberance1");
}

// The oil for scuffing (ISO/TS 6336-21; docs/rating.md "Scuffing").
void read_scuffing_keys(MapReader& r, gg::RatingInput& in, std::map<std::string, io::SourceMark>& marks) {
  namespace iso = gg::iso6336;
  gg::ScuffingInput& s = in.scuffing;
  if (r.has("fzg_stage")) {
    const long long stage = r.integer("fzg_stage");
    if (stage < 1 || stage > 14) io::fail_at(r.mark("fzg_stage"), fmt::format("expected an FZG load stage 1..14, found {}", stage));
    s.fzg_stage = static_cast<int>(stage);
  }
  s.theta_oil = r.optional_number("oil_temperature").value_or(s.theta_oil);
  s.nu_100 = r.optional_number("oil_viscosity_100").value_or(s.nu_100);
  s.rho_15 = r.optional_number("oil_density").value_or(s.rho_15);
  if (r.has("oil_type")) {
    std::vector<std::string> names;
    for (iso::OilBase b : iso::kOilBases) names.emplace_back(iso::to_string(b));
    const std::string name = r.choice("oil_type", names);
    for (iso::OilBase b : iso::kOilBases) if (name == iso::to_string(b)) s.oil = b;
  }
  if (r.has("lubrication")) {
    std::vector<std::string> names;
    for (iso::Lubrication l : iso::kLubrications) names.emplace_back(iso::to_string(l));
    const std::string name = r.choice("lubrication", names);
    for (iso::Lubrication l : iso::kLubrications) if (name == iso::to_string(l)) s.lubrication = l;
  }
  if (r.has("driving_gear")) s.gear1_driving = r.choice("driving_gear", {"1", "2"}) == "1";
  s.S_Smin = r.optional_number("min_safety_scuffing").value_or(s.S_Smin);
  for (auto [field, key] : {std::pair{"fzg_stage", "fzg_stage"}, {"theta_oil", "oil_temperature"}, {"nu_100", "oil_viscosity_100"},
                            {"rho_15", "oil_density"}, {"S_Smin", "min_safety_scuffing"}}) {
    if (r.has(key)) marks[field] = r.mark(key);
  }
  // Oil data the stage needs but the file lacks is reported at the stage.
  for (auto [field, key] : {std::pair{"theta_oil", "oil_temperature"}, {"nu_100", "oil_viscosity_100"}}) {
    if (r.has("fzg_stage") && !r.has(key)) marks[field] = r.mark("fzg_stage");
  }
}

void read_rating_keys(MapReader& r, gg::RatingInput& in, std::map<std::string, io::SourceMark>& marks) {
  auto um = [](MapReader& m, const char* key) { return m.quantity(key, Quantity::length, "um") * 1e6; };
  read_accuracy(r, in);
  marks["quality"] = r.mark("quality");
  in.nu_40 = r.optional_number("oil_viscosity").value_or(in.nu_40);
  read_scuffing_keys(r, in, marks);
  if (r.has("flank_roughness") && r.has("flank_rz")) io::fail_at(r.mark("flank_rz"), "give flank_roughness (R_a) or flank_rz, not both");
  if (r.has("flank_roughness")) in.R_z_flank.fill(6.0 * um(r, "flank_roughness"));
  if (r.has("flank_rz")) in.R_z_flank.fill(um(r, "flank_rz"));
  in.s_pr = r.optional_number("protuberance").value_or(in.s_pr);
  if (r.has("root_roughness")) in.R_z_root.fill(um(r, "root_roughness"));
  read_per_gear_keys(r, in, marks);
  if (auto d = r.optional_node("deviations")) {
    MapReader dv(*d, r.file(), "deviations");
    for (auto [key, field] : {std::pair{"f_pb", &gg::RatingInput::f_pb}, {"f_falpha", &gg::RatingInput::f_falpha},
                              {"F_betax", &gg::RatingInput::F_betax}, {"f_ma", &gg::RatingInput::f_ma},
                              {"f_sh", &gg::RatingInput::f_sh}, {"tip_relief", &gg::RatingInput::C_a}}) {
      if (dv.has(key)) in.*field = um(dv, key);
      marks[key] = dv.mark(key);
    }
    dv.finish();
  }
  if (auto fl = r.optional_node("face_load")) {
    MapReader fr(*fl, r.file(), "face_load");
    marks["face_load"] = fr.mark();
    read_face_load(fr, in.face_load);
  }
  in.S_Hmin = r.optional_number("min_safety_pitting").value_or(in.S_Hmin);
  in.S_Fmin = r.optional_number("min_safety_bending").value_or(in.S_Fmin);
  in.limited_pitting = r.boolean_or("limited_pitting", in.limited_pitting);
  in.optimum_long_life = r.boolean_or("optimum_long_life", in.optimum_long_life);
  if (auto fs = r.optional_node("factors")) {
    MapReader fr(*fs, r.file(), "factors");
    for (const auto& kv : *fs) {
      const std::string name = kv.first.as<std::string>();
      try {
        parse_factor(fmt::format("{}={}", name, io::scalar_text(kv.second, r.file(), "factor")), in.factors);
      } catch (const std::invalid_argument& e) {
        io::fail_at(io::mark_of(kv.first, r.file()), e.what());
      }
      fr.node(name);
    }
    marks["factor"] = fr.mark();
    fr.finish();
  }
}

std::optional<gg::Rack> read_tool(MapReader& r, int i, const gg::GearPairInput& pair, std::map<std::string, io::SourceMark>& marks) {
  const char* key = i == 0 ? "rack1" : "rack2";
  const auto node = r.optional_node(key);
  if (!node) return std::nullopt;
  MapReader k(*node, r.file(), key);
  gg::Rack tool{pair.pressure_angle, k.optional_number("addendum").value_or(pair.h_aP), k.optional_number("dedendum").value_or(pair.h_fP),
                k.optional_number("root_radius").value_or(pair.rho_fP)};
  marks[i == 0 ? "tool1" : "tool2"] = k.mark();
  k.finish();
  return tool;
}

std::array<double, 2> upper_allowances_of_grade(const gg::GearPairInput& pair, const gg::GearPairResult& table, int grade,
                                                gg::Iso1328Edition edition) {
  gg::InspectionInput ii;
  ii.grade = {grade, grade};
  ii.edition = edition;
  const gg::InspectionResult by_grade = gg::compute_inspection(pair, table, ii);
  return {by_grade.gear[0].allowances.A_sne, by_grade.gear[1].allowances.A_sne};
}

}  // namespace gearkit::plugins::gear
