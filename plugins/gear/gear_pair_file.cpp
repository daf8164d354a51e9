#include "gear_pair_file.hpp"

#include "gear_rating_yaml.hpp"
#include "gear_rating_options.hpp"

#include <gearkit/gear/accuracy.hpp>
#include <gearkit/io/yaml_model.hpp>

#include <fmt/format.h>

#include <cmath>
#include <tuple>
#include <numbers>

namespace gearkit::plugins::gear {

namespace gg = gearkit::gear;

namespace {

constexpr double kRpm = 30.0 / std::numbers::pi;
constexpr std::size_t kMaxSpectrumRows = 10000;  // each row is a full rating (about 3 us): well under a second

using io::MapReader;
using io::Quantity;

double mm(MapReader& r, const char* key, double default_mm) { return r.quantity_or(key, Quantity::length, "mm", default_mm / 1000.0) * 1000.0; }

// Per-gear tools (rack1:, rack2: as rack:) and the tip and root diameters as made.
void read_tools_and_tips(MapReader& r, PairFile& f) {
  gg::GearPairInput& g = f.geometry;
  for (int i = 0; i < 2; ++i) {
    if (auto tool = read_tool(r, i, g, f.marks)) g.tool[i] = *tool;
    const std::string n = std::to_string(i + 1);
    for (const auto& [name, field, target] : {std::tuple{"tip_diameter" + n, "d_a" + n, &g.d_a}, std::tuple{"root_diameter" + n, "d_f" + n, &g.d_f}}) {
      if (auto d = r.optional_quantity(name.c_str(), Quantity::length, "mm")) (*target)[i] = *d * 1000.0;
      f.marks[field] = r.mark(name.c_str());
    }
  }
}

void read_geometry(MapReader& r, PairFile& f) {
  gg::GearPairInput& g = f.geometry;
  auto teeth = [&](const char* key) {
    const long long z = r.integer(key);
    if (z < 1 || z > 100000) io::fail_at(r.mark(key), fmt::format("expected a number of teeth 1..100000, found {}", z));
    f.marks[key] = r.mark(key);
    return static_cast<int>(z);
  };
  g.z1 = teeth("z1");
  g.z2 = teeth("z2");
  g.module = r.quantity("module", Quantity::length, "mm") * 1000.0;
  g.pressure_angle = r.quantity_or("pressure_angle", Quantity::angle, "deg", g.pressure_angle);
  g.helix_angle = r.quantity_or("helix_angle", Quantity::angle, "deg", 0.0);
  g.internal = r.boolean_or("internal", false);
  g.system = r.boolean_or("transverse", false) ? gg::ModuleSystem::transverse : gg::ModuleSystem::normal;
  g.apply_tip_shortening = r.boolean_or("tip_shortening", true);
  if (auto c = r.optional_quantity("centre_distance", Quantity::length, "mm")) g.centre_distance = *c * 1000.0;
  g.x1 = r.optional_number("x1").value_or(0.0);
  g.x2 = r.optional_number("x2").value_or(0.0);
  if (g.centre_distance && r.has("x2")) io::fail_at(r.mark("x2"), "x2 follows from centre_distance (give x1 to fix the split)");
  const std::string split = r.choice("split", {"balanced", "proportional", "user"}, r.has("x1") ? "user" : "balanced");
  g.split = split == "user" ? gg::ShiftSplit::user_x1 : split == "proportional" ? gg::ShiftSplit::proportional : gg::ShiftSplit::balanced_sliding;
  g.face_width = mm(r, "face_width", 0.0);
  for (int i = 0; i < 2; ++i) {
    const char* key = i == 0 ? "face_width1" : "face_width2";
    if (r.has(key)) g.face_widths[i] = mm(r, key, 0.0);
    f.marks[key] = r.mark(key);
  }
  g.face_offset = mm(r, "face_offset", 0.0);
  f.marks["face_offset"] = r.mark("face_offset");
  g.A_sn1 = mm(r, "allowance1", 0.0);
  g.A_sn2 = mm(r, "allowance2", 0.0);
  if (auto rack = r.optional_node("rack")) {
    MapReader k(*rack, r.file(), "rack");
    g.h_aP = k.optional_number("addendum").value_or(g.h_aP);
    g.h_fP = k.optional_number("dedendum").value_or(g.h_fP);
    g.rho_fP = k.optional_number("root_radius").value_or(g.rho_fP);
    f.marks["rack"] = k.mark();
    k.finish();
  }
  read_tools_and_tips(r, f);
  for (const char* key : {"module", "pressure_angle", "helix_angle", "centre_distance", "x1", "x2", "face_width"}) f.marks[key] = r.mark(key);
  f.marks["A_sn1"] = r.mark("allowance1");
  f.marks["A_sn2"] = r.mark("allowance2");
}

// The required life, checked where it is written: the spectrum's shares are fractions of it.
double read_life(MapReader& load, double default_h) {
  const double life_h = load.quantity_or("life", Quantity::time, "h", default_h * 3600.0) / 3600.0;
  if (!(std::isfinite(life_h) && life_h > 0.0)) io::fail_at(load.mark("life"), fmt::format("expected a life > 0 h, found {:g} h", life_h));
  return life_h;
}

void read_spectrum(MapReader& load, gg::RatingInput& r) {
  if (!load.has("spectrum")) return;
  const auto rows = load.sequence("spectrum", kMaxSpectrumRows, "rows");
  double share_sum = 0.0;
  bool shares = false;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    MapReader row(rows[k], load.file(), fmt::format("spectrum row {}", k + 1));
    gg::iso6336::LoadBin bin;
    bin.T_1 = row.quantity("torque1", Quantity::torque, "N*m");
    bin.n_1 = row.quantity("speed1", Quantity::angular_velocity, "rpm") * kRpm;
    if (row.has("share") == row.has("hours")) io::fail_at(row.mark(), "expected exactly one of 'hours' and 'share' in a spectrum row");
    shares = row.has("share");
    bin.hours = shares ? row.number("share") * r.life_h : row.quantity("hours", Quantity::time, "h") / 3600.0;
    if (shares) share_sum += row.number("share");
    if (!(bin.T_1 > 0.0 && bin.n_1 > 0.0 && bin.hours > 0.0)) {
      io::fail_at(row.mark(), "expected torque1 > 0, speed1 > 0 and a positive share or hours");
    }
    row.finish();
    r.spectrum.push_back(bin);
  }
  if (shares && std::fabs(share_sum - 1.0) > 1e-6) {
    io::fail_at(load.mark("spectrum"), fmt::format("the shares of the spectrum rows add up to {:.6g}, expected 1", share_sum));
  }
}

void read_load(MapReader& load, gg::RatingInput& r, PairFile& f) {
  const std::string method = load.choice("method", {"iso6336", "agma", "lewis-hertz"}, "iso6336");
  r.method = method == "agma" ? gg::RatingMethod::agma : method == "lewis-hertz" ? gg::RatingMethod::lewis_hertz : gg::RatingMethod::iso6336;
  r.n_1 = load.quantity("speed1", Quantity::angular_velocity, "rpm") * kRpm;
  if (int(load.has("torque1")) + int(load.has("torque2")) + int(load.has("power")) != 1) {
    io::fail_at(load.mark(), "expected exactly one of 'torque1', 'torque2' and 'power' in load");
  }
  if (load.has("torque2")) {
    r.T_2 = load.quantity("torque2", Quantity::torque, "N*m");
  } else {
    r.T_1 = load.has("torque1") ? load.quantity("torque1", Quantity::torque, "N*m")
                                : load.quantity("power", Quantity::power, "kW") / (r.n_1 / kRpm);
  }
  r.K_A = load.optional_number("application_factor").value_or(1.0);
  r.life_h = read_life(load, r.life_h);
  if (load.has("life_cycles")) {
    if (load.has("life")) io::fail_at(load.mark("life_cycles"), "give 'life' (hours) or 'life_cycles', not both");
    r.N_L1 = load.number("life_cycles");
  }
  f.marks["N_L1"] = load.mark("life_cycles");
  f.marks["T_2"] = load.mark("torque2");
  f.marks["T_1"] = load.mark(load.has("torque1") ? "torque1" : "power");
  f.marks["n_1"] = load.mark("speed1");
  f.marks["K_A"] = load.mark("application_factor");
  f.marks["life_h"] = load.mark("life");
  f.marks["spectrum"] = load.mark("spectrum");
  read_spectrum(load, r);
  load.finish();
}

}  // namespace

PairFile read_pair_file(const std::string& path) {
  const io::YamlDocument doc = io::load_yaml_file(path);
  MapReader r(doc.root, doc.file, "gear pair");
  PairFile f;
  f.file_mark = r.mark();
  read_geometry(r, f);
  if (auto load = r.optional_node("load")) {
    gg::RatingInput in;
    MapReader materials = r.map("materials");
    in.material[0] = read_material(materials.node("gear1"), doc.file, "gear1");
    in.material[1] = read_material(materials.node("gear2"), doc.file, "gear2");
    f.marks["material1"] = materials.mark("gear1");
    f.marks["material2"] = materials.mark("gear2");
    materials.finish();
    read_rating_keys(r, in, f.marks);
    MapReader lr(*load, doc.file, "load");
    in.life_h = read_life(lr, in.life_h);  // before the spectrum shares
    read_load(lr, in, f);
    f.rating = in;
  }
  r.finish();
  return f;
}

void grade_allowances(const PairFile& file, const gg::GearPairResult& table, gg::RatingInput& rating) {
  if (!rating.quality || file.geometry.A_sn1 != 0.0 || file.geometry.A_sn2 != 0.0) return;
  const int grade = *rating.quality;
  if (grade < gg::min_grade(rating.iso1328_edition) || grade > gg::max_grade(rating.iso1328_edition)) return;  // the rating names it
  try {
    const auto A_sne = upper_allowances_of_grade(file.geometry, table, grade, rating.iso1328_edition);
    for (int i = 0; i < 2; ++i) rating.A_sne[i] = A_sne[i];
  } catch (const gg::GeometryError& e) {
    io::fail_at(mark_for_field(file, "quality"), fmt::format("the tooth thickness allowances of the grade (ISO/TR 10064-2), which the "
                                                             "root rating uses, cannot be found: {}; give allowance1 and allowance2", e.what()));
  }
}

io::SourceMark mark_for_field(const PairFile& file, const std::string& field) {
  const auto it = file.marks.find(field);
  return it == file.marks.end() ? file.file_mark : it->second;
}

}  // namespace gearkit::plugins::gear
