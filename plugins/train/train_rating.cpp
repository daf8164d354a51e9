#include "train_rating.hpp"

#include "../gear/gear_rating_yaml.hpp"
#include "../gear/gear_rating_report.hpp"

#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/gear/rating.hpp>
#include <gearkit/io/error.hpp>
#include <gearkit/io/yaml_model.hpp>
#include <gearkit/train/rational.hpp>
#include <gearkit/train/torques.hpp>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <tuple>

namespace gearkit::plugins::train {

namespace gg = gearkit::gear;
namespace gt = gearkit::train;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct GearData {
  double face_width_mm = kNaN;
  std::optional<gg::Material> material;
  io::SourceMark mark;
};

// A mesh's own `rating:` (the rating keys of a gear-pair file), read when the mesh is rated.
struct MeshData {
  YAML::Node node;  ///< null: none
  std::string file;
};

// The `rating:` section, the gears' `face_width` / `material` and the meshes' `rating:`.
struct RatingData {
  gg::RatingInput base;
  double face_width_mm = kNaN;
  std::optional<gg::Material> material;
  std::optional<double> K_gamma;
  io::SourceMark mark;
  std::map<std::string, io::SourceMark> marks;  ///< RatingInput field -> where its key was written
  std::map<std::string, GearData> gears;
  std::vector<MeshData> meshes;  ///< in file order (the model's mesh order)
};

// The key of the `rating:` section that sets each RatingInput field a rating error can name.
constexpr std::pair<const char*, const char*> kFieldKeys[] = {
    {"quality", "quality"}, {"life_h", "life"}, {"K_A", "application_factor"}, {"K_gamma", "load_sharing"},
    {"nu_40", "oil_viscosity"}, {"R_z_flank", "flank_roughness"}, {"R_z_root", "root_roughness"},
    {"S_Hmin", "min_safety_pitting"}, {"S_Fmin", "min_safety_bending"}, {"method", "method"}, {"fzg_stage", "fzg_stage"},
    {"theta_oil", "oil_temperature"}, {"nu_100", "oil_viscosity_100"}, {"rho_15", "oil_density"}, {"S_Smin", "min_safety_scuffing"}};

void read_section(io::MapReader& r, RatingData& d) {
  const std::string method = r.choice("method", {"iso6336", "agma", "lewis-hertz"}, "iso6336");
  d.base.method = method == "agma" ? gg::RatingMethod::agma : method == "lewis-hertz" ? gg::RatingMethod::lewis_hertz
                                                                                      : gg::RatingMethod::iso6336;
  d.base.life_h = r.quantity_or("life", io::Quantity::time, "h", d.base.life_h * 3600.0) / 3600.0;
  plugins::gear::read_accuracy(r, d.base);
  d.base.K_A = r.optional_number("application_factor").value_or(1.0);
  d.K_gamma = r.optional_number("load_sharing");
  d.base.nu_40 = r.optional_number("oil_viscosity").value_or(d.base.nu_40);
  plugins::gear::read_scuffing_keys(r, d.base, d.marks);
  if (r.has("flank_roughness")) d.base.R_z_flank.fill(6.0e6 * r.quantity("flank_roughness", io::Quantity::length, "um"));
  if (r.has("root_roughness")) d.base.R_z_root.fill(1.0e6 * r.quantity("root_roughness", io::Quantity::length, "um"));
  d.base.S_Hmin = r.optional_number("min_safety_pitting").value_or(d.base.S_Hmin);
  d.base.S_Fmin = r.optional_number("min_safety_bending").value_or(d.base.S_Fmin);
  if (auto w = r.optional_quantity("face_width", io::Quantity::length, "mm")) d.face_width_mm = *w * 1000.0;
  if (auto m = r.optional_node("material")) d.material = plugins::gear::read_material(*m, r.file(), "material");
  d.mark = r.mark();
  for (const auto& [field, key] : kFieldKeys) d.marks[field] = r.mark(key);
  r.finish();
}

// Where to report a rating error naming `field`: its key in `rating:`, else the section (or file).
io::SourceMark mark_for_field(const RatingData& d, const std::string& field) {
  const auto it = d.marks.find(field);
  return it == d.marks.end() ? d.mark : it->second;
}

RatingData read_rating_data(const std::string& path) {
  const io::YamlDocument doc = io::load_yaml_file(path);
  RatingData d;
  d.mark = io::mark_of(doc.root, doc.file);
  if (const YAML::Node section = doc.root["rating"]) {
    io::MapReader r(section, doc.file, "rating");
    read_section(r, d);
  }
  for (const YAML::Node& item : doc.root["gears"]) {
    GearData g;
    g.mark = io::mark_of(item, doc.file);
    if (const YAML::Node w = item["face_width"]) g.face_width_mm = io::scalar_quantity(w, doc.file, io::Quantity::length, "mm") * 1000.0;
    if (const YAML::Node m = item["material"]) g.material = plugins::gear::read_material(m, doc.file, "material");
    d.gears[item["name"].as<std::string>()] = g;
  }
  for (const YAML::Node& item : doc.root["meshes"]) d.meshes.push_back({item["rating"], doc.file});
  return d;
}

// Load sharing of planets K_gamma by their number (IEC 61400-4 Table 3 values, as the Drivetrain
// ISO 6336 code uses them): 1 for one to three... planets on a floating member are not assumed.
double default_K_gamma(int planets) {
  switch (planets) {
    case 1:
    case 2: return 1.0;
    case 3: return 1.1;
    case 4: return 1.25;
    case 5: return 1.35;
    case 6: return 1.44;
    default: return 1.47;
  }
}

struct MeshPlan {
  gt::GearId pinion = 0, wheel = 0;
  int planets = 1;  // planets sharing the mesh torque
};

MeshPlan plan_of(const gt::TrainModel& model, const gt::Mesh& mesh) {
  const gt::Gear& a = model.gear(mesh.gear_a);
  const gt::Gear& b = model.gear(mesh.gear_b);
  MeshPlan p;
  const bool a_is_pinion = b.kind == gt::GearKind::internal || (a.kind != gt::GearKind::internal && a.z <= b.z);
  p.pinion = a_is_pinion ? mesh.gear_a : mesh.gear_b;
  p.wheel = a_is_pinion ? mesh.gear_b : mesh.gear_a;
  for (gt::GearId g : {mesh.gear_a, mesh.gear_b}) {
    if (model.is_planet(model.gear(g).member)) p.planets = model.member(model.gear(g).member).planet_count;
  }
  return p;
}

const GearData& gear_data(const RatingData& d, const gt::Gear& g) {
  static const GearData none;
  const auto it = d.gears.find(g.name);
  return it == d.gears.end() ? none : it->second;
}

gg::GearPairInput pair_of(const gt::TrainModel& model, const RatingData& d, const MeshPlan& p) {
  const gt::Gear& g1 = model.gear(p.pinion);
  const gt::Gear& g2 = model.gear(p.wheel);
  for (const gt::Gear* g : {&g1, &g2}) {
    if (!g->module_mm) io::fail_at(gear_data(d, *g).mark, fmt::format("gear {}: the rating needs its module", io::quote(g->name)));
  }
  gg::GearPairInput in;
  in.z1 = g1.z;
  in.z2 = g2.z;
  in.internal = g2.kind == gt::GearKind::internal;
  in.module = *g1.module_mm;
  in.pressure_angle = g1.alpha_n;
  in.helix_angle = std::fabs(g1.beta);
  in.x1 = g1.x;
  in.x2 = g2.x;
  std::array<double, 2> w{};
  for (int i = 0; i < 2; ++i) {
    const gt::Gear& g = i == 0 ? g1 : g2;
    w[i] = std::isnan(gear_data(d, g).face_width_mm) ? d.face_width_mm : gear_data(d, g).face_width_mm;
    if (std::isnan(w[i])) io::fail_at(gear_data(d, g).mark, fmt::format("gear {}: the rating needs its face_width", io::quote(g.name)));
  }
  // Faces centred on each other: the mesh carries the narrower width; the wider gear's root
  // carries at most one module more on each side (ISO 6336-3; GearPairInput::face_widths).
  in.face_width = std::min(w[0], w[1]);
  if (w[0] != w[1]) in.face_widths = {w[0], w[1]};
  return in;
}

gg::Material material_of(const RatingData& d, const gt::Gear& g) {
  const GearData& gd = gear_data(d, g);
  if (gd.material) return *gd.material;
  if (d.material) return *d.material;
  io::fail_at(gd.mark, fmt::format("gear {}: the rating needs its material (or rating: material:)", io::quote(g.name)));
}

int meshes_of(const gt::TrainModel& model, gt::GearId g) {
  int n = 0;
  for (const auto& m : model.meshes()) n += (m.gear_a == g || m.gear_b == g) ? 1 : 0;
  return n;
}

}  // namespace

namespace {

// A sun: an external gear on the carrier's axis meshing with planets (more than one).
bool is_sun_mesh(const gt::TrainModel& model, const MeshPlan& p) {
  const gt::Gear& g1 = model.gear(p.pinion);
  const gt::Gear& g2 = model.gear(p.wheel);
  return p.planets > 1 && g1.kind == gt::GearKind::external && !model.is_planet(g1.member) && model.is_planet(g2.member);
}

// The mesh's own `rating:` keys over the file's `rating:` section (plugins/gear read_rating_keys),
// and the face-load model: a sun mesh takes FaceLoadModel::sun (the sun twisted by all planets, no
// bending by a bearing span; docs/rating.md) unless its `face_load:` names a model or a shaft.
// The mesh's tools and upper thickness allowances: gear 1 is the mesh's pinion (plan_of).
struct MeshTools {
  std::array<std::optional<gg::Rack>, 2> tool;
  std::array<std::optional<double>, 2> A_sne;  ///< mm
};

void read_mesh_tools(io::MapReader& r, const gg::GearPairInput& pair, MeshTools& t, std::map<std::string, io::SourceMark>& marks) {
  for (int i = 0; i < 2; ++i) {
    t.tool[i] = plugins::gear::read_tool(r, i, pair, marks);
    const std::string key = i == 0 ? "allowance1" : "allowance2";
    if (r.has(key)) t.A_sne[i] = r.quantity(key, io::Quantity::length, "mm") * 1000.0;
  }
}

std::map<std::string, io::SourceMark> read_mesh_rating(const gt::TrainModel& model, const RatingData& d, gt::MeshId k,
                                                       const MeshPlan& p, const gg::GearPairInput& pair, gg::RatingInput& in,
                                                       MeshTools& tools) {
  std::map<std::string, io::SourceMark> marks;
  in.face_load.planets = p.planets;
  bool model_given = false;
  if (k < d.meshes.size() && d.meshes[k].node) {
    io::MapReader r(d.meshes[k].node, d.meshes[k].file, "mesh rating");
    plugins::gear::read_rating_keys(r, in, marks);
    read_mesh_tools(r, pair, tools, marks);
    if (!r.has("iso1328_edition")) in.iso1328_edition = d.base.iso1328_edition;
    if (auto K_A = r.optional_number("application_factor")) {
      in.K_A = *K_A;
      marks["K_A"] = r.mark("application_factor");
    }
    model_given = d.meshes[k].node["face_load"] && d.meshes[k].node["face_load"]["model"];
    r.finish();
  }
  if (is_sun_mesh(model, p) && !model_given && !in.face_load.has_shaft()) in.face_load.model = gg::FaceLoadModel::sun;
  return marks;
}

// The upper allowances of the root rating's generating shift: the mesh's allowance1/2, else those
// ISO/TR 10064-2 gives the mesh's grade (as `gearkit gear` does for a pair file with a grade).
// Where the grade gives none (the standard's ranges), the nominal shift is used and a warning says so.
std::string root_allowances(const std::string& mesh, const gg::GearPairInput& pair, const gg::GearPairResult& table,
                            const MeshTools& tools, gg::RatingInput& in, std::vector<std::string>& warnings) {
  if (tools.A_sne[0] || tools.A_sne[1]) {
    for (int i = 0; i < 2; ++i) in.A_sne[i] = tools.A_sne[i].value_or(0.0);
    return "the mesh's allowance1/2";
  }
  if (!in.quality || *in.quality < gg::min_grade(in.iso1328_edition) || *in.quality > gg::max_grade(in.iso1328_edition)) return {};
  try {
    const auto A_sne = plugins::gear::upper_allowances_of_grade(pair, table, *in.quality, in.iso1328_edition);
    for (int i = 0; i < 2; ++i) in.A_sne[i] = A_sne[i];
    return fmt::format("ISO/TR 10064-2 for grade {}", *in.quality);
  } catch (const gg::GeometryError& e) {
    warnings.push_back(fmt::format("mesh '{}': the tooth root is rated without thickness allowances: ISO/TR 10064-2 gives none "
                                   "for its grade ({}); give allowance1 and allowance2 in its rating", mesh, e.what()));
  }
  return {};
}

struct MeshRating {
  std::string mesh, pinion, wheel;
  gg::RatingInput input;
  gg::PairRating rating;
  std::string allowances_from = {};  ///< where input.A_sne came from, for the report's note
  std::array<double, 2> beta = {};   ///< each gear's own helix angle, rad (train file: > 0 right hand)
};

// A train file gives each gear its own signed helix angle (docs/train.md): > 0 right hand.
const char* hand_of(double beta) { return beta > 0.0 ? "right" : beta < 0.0 ? "left" : "spur"; }

// The hand of every helical gear of the rated meshes, in one note (issue 25: the hand in every report).
void note_helix_hands(io::Report& report, const std::vector<MeshRating>& rated) {
  std::vector<std::string> hands;
  for (const auto& m : rated)
    for (int i = 0; i < 2; ++i) {
      const std::string entry = fmt::format("{} {}", i == 0 ? m.pinion : m.wheel, hand_of(m.beta[i]));
      if (m.beta[i] != 0.0 && std::find(hands.begin(), hands.end(), entry) == hands.end()) hands.push_back(entry);
    }
  if (!hands.empty()) report.notes.push_back(fmt::format("Helix hands: {}.", fmt::join(hands, ", ")));
}

// One mesh: its pair, torques per planet, relative speed, cycles per turn and load sharing.
std::optional<MeshRating> rate_mesh(const gt::TrainModel& model, const RatingData& d, gt::MeshId k, double T_pinion_total,
                                    double n_pinion_rpm, std::vector<std::string>& warnings) {
  const gt::Mesh& mesh = model.mesh(k);
  const MeshPlan p = plan_of(model, mesh);
  const gt::Gear& g1 = model.gear(p.pinion);
  const gt::Gear& g2 = model.gear(p.wheel);
  if (n_pinion_rpm == 0.0 || T_pinion_total == 0.0) {
    warnings.push_back(fmt::format("mesh '{}' carries no load or does not turn relative to its carrier: not rated", mesh.name));
    return std::nullopt;
  }
  MeshRating m{mesh.name, g1.name, g2.name, d.base, {}, {}, {g1.beta, g2.beta}};
  gg::RatingInput& in = m.input;
  // An idler or a planet between two meshes is bent both ways: the default a mesh's
  // reversed_bending1/2 may override, so it is set before the mesh's keys are read.
  in.reversed_bending = {meshes_of(model, p.pinion) > 1, meshes_of(model, p.wheel) > 1};
  gg::GearPairInput pair = pair_of(model, d, p);
  MeshTools tools;
  const std::map<std::string, io::SourceMark> mesh_marks = read_mesh_rating(model, d, k, p, pair, in, tools);
  pair.tool = tools.tool;
  in.T_1 = T_pinion_total / p.planets;
  in.n_1 = n_pinion_rpm;
  in.material = {material_of(d, g1), material_of(d, g2)};
  in.K_gamma = p.planets > 1 ? d.K_gamma.value_or(default_K_gamma(p.planets)) : 1.0;
  // A gear on a planet meets this mesh once per relative turn; a gear on the carrier's axis meets
  // every planet: N cycles per relative turn.
  in.cycles_per_rev = {model.is_planet(g1.member) ? 1.0 : p.planets, model.is_planet(g2.member) ? 1.0 : p.planets};
  try {
    const gg::GearPairResult table = gg::compute_gear_pair(pair);
    m.allowances_from = root_allowances(mesh.name, pair, table, tools, in, warnings);
    m.rating = gg::rate_gear_pair(pair, table, in);
  } catch (const gg::GeometryError& e) {
    io::fail_at(gear_data(d, g1).mark, fmt::format("mesh {}: {}", io::quote(mesh.name), e.what()));
  } catch (const gg::RatingError& e) {
    const auto it = mesh_marks.find(e.field());
    io::fail_at(it != mesh_marks.end() ? it->second : mark_for_field(d, e.field()), fmt::format("mesh {}: {}", io::quote(mesh.name), e.what()));
  }
  return m;
}

void report_meshes(io::Report& report, const std::vector<MeshRating>& rated) {
  io::Table t{"Load capacity of the meshes (per planet where planets share a mesh)",
              {"mesh", "gear", "T [N m]", "n rel. carrier [1/min]", "K_gamma", "S_H", "S_F", "life [h]"}, {}};
  nlohmann::json list = nlohmann::json::array();
  double weakest = std::numeric_limits<double>::infinity();
  std::string weakest_text;
  for (const auto& m : rated) {
    for (int i = 0; i < 2; ++i) {
      const auto& g = m.rating.gear[i];
      const double life = std::min(g.life_H_h, g.life_F_h);
      t.add_row({m.mesh, i == 0 ? m.pinion : m.wheel, io::fixed(i == 0 ? m.input.T_1 : m.input.T_1 * m.rating.gear[0].n / g.n, 2),
                 io::fixed(g.n, 2), io::fixed(m.input.K_gamma, 3), io::fixed(g.S_H, 3), io::fixed(g.S_F, 3),
                 std::isfinite(life) ? io::fixed(life, 0) : "unlimited"});
      for (auto [what, S, S_min] : {std::tuple{"pitting", g.S_H, m.input.S_Hmin}, {"tooth root", g.S_F, m.input.S_Fmin}}) {
        if (S / S_min < weakest) {
          weakest = S / S_min;
          weakest_text = fmt::format("mesh '{}', gear '{}', {}: S = {:.3f} (required {:.2f})", m.mesh, i == 0 ? m.pinion : m.wheel,
                                     what, S, S_min);
        }
      }
    }
    nlohmann::json j = plugins::gear::rating_json(m.input, m.rating);
    j["mesh"] = m.mesh;
    j["gear_names"] = {m.pinion, m.wheel};
    j["K_gamma"] = m.input.K_gamma;
    j["helix_hands"] = {hand_of(m.beta[0]), hand_of(m.beta[1])};
    list.push_back(j);
    for (const auto& w : m.rating.warnings) report.warnings.push_back(fmt::format("mesh '{}': {}", m.mesh, w));
    if (m.input.method == gg::RatingMethod::iso6336 && m.input.face_load.model == gg::FaceLoadModel::sun && std::isfinite(m.rating.f_sh)) {
      report.notes.push_back(fmt::format("Mesh '{}': face load by the sun model ({} planets, B* = {:g}, no bending term): f_sh = {:.3f} um, "
                                         "K_Hbeta = {:.3f} (docs/rating.md, \"Face load factor\").",
                                         m.mesh, m.input.face_load.planets, m.rating.B_star, m.rating.f_sh, m.rating.K_Hbeta));
    }
    if (m.input.method == gg::RatingMethod::iso6336 && m.input.root_shift == gg::RootShift::generating && (m.input.A_sne[0] || m.input.A_sne[1]))
      report.notes.push_back(fmt::format("Mesh '{}': tooth root (Y_F, Y_S) at the generating shift x_E = x + A_sne/(2 m_n tan alpha_n), "
                                         "upper allowances A_sne = {:.4f} / {:.4f} mm ({}).",
                                         m.mesh, m.input.A_sne[0].value_or(0.0), m.input.A_sne[1].value_or(0.0),
                                         m.allowances_from));
  }
  report.tables.push_back(std::move(t));
  if (!weakest_text.empty()) report.notes.push_back("Weakest: " + weakest_text + ".");
  report.json["rating"] = {{"meshes", list}, {"weakest", weakest_text}};
}

// Scuffing of the meshes rated for it (ISO/TS 6336-21; the oil keys of `rating:`): a table only
// when one is, the details in each mesh's JSON "scuffing".
void report_scuffing(io::Report& report, const std::vector<MeshRating>& rated) {
  io::Table t{"Scuffing of the meshes: ISO/TS 6336-21, integral temperature",
              {"mesh", "theta_flaint [K]", "theta_int [C]", "theta_intS [C]", "S_intS", "S_Smin"}, {}};
  for (const auto& m : rated) {
    if (!m.rating.scuffing) continue;
    const gg::ScuffingRating& s = *m.rating.scuffing;
    t.add_row({m.mesh, io::fixed(s.theta_flaint, 2), io::fixed(s.theta_int, 2), io::fixed(s.theta_intS, 2), io::fixed(s.S_intS, 3),
               io::fixed(m.input.scuffing.S_Smin, 2)});
  }
  if (!t.rows.empty()) report.tables.push_back(std::move(t));
}

}  // namespace

void add_mesh_ratings(io::Report& report, const std::string& file, const gt::TrainModel& model, const gt::SpeedSolution& speeds,
                      const std::vector<gt::Condition>& conditions, const std::vector<double>& input_speeds_rad_s,
                      gt::MemberId output, gt::MemberId given_member, double given_torque_Nm) {
  const RatingData d = read_rating_data(file);
  const gt::TorqueSolution ts = gt::solve_torques(model, conditions, output, given_member);
  if (!ts.balanced) {
    report.warnings.push_back("no mesh rating: " + ts.message);
    return;
  }
  std::vector<MeshRating> rated;
  for (gt::MeshId k = 0; k < model.meshes().size(); ++k) {
    const gt::Mesh& mesh = model.mesh(k);
    if (!ts.mesh_multiplier[k]) {
      report.warnings.push_back(fmt::format("mesh '{}': torque statically indeterminate, not rated", mesh.name));
      continue;
    }
    const auto [T_a, T_b] = gt::mesh_gear_torques(model, k, *ts.mesh_multiplier[k], gt::MeshDriver::none);
    const MeshPlan p = plan_of(model, mesh);
    const double T_pinion = std::fabs(gt::to_double(p.pinion == mesh.gear_a ? T_a : T_b)) * given_torque_Nm;
    const double w = gt::speed_value(speeds, model.gear(p.pinion).member, input_speeds_rad_s) -
                     gt::speed_value(speeds, mesh.carrier, input_speeds_rad_s);
    if (auto m = rate_mesh(model, d, k, std::fabs(T_pinion), std::fabs(w) * 30.0 / std::numbers::pi, report.warnings)) {
      rated.push_back(std::move(*m));
    }
  }
  report_meshes(report, rated);
  report_scuffing(report, rated);
  note_helix_hands(report, rated);
}

}  // namespace gearkit::plugins::train
