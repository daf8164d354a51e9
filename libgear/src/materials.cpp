#include <gearkit/gear/materials.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace gearkit::gear {

namespace {

// One row of ISO 6336-5:2016 Table 1: sigma = A x + B for grades ML, MQ, ME, x the hardness.
struct Line {
  double A, B;
};
struct ClassData {
  MaterialClass kind;
  const char* name;
  const char* abbreviation;
  double x_min, x_max;          // hardness range of the figure (HV, HBW for the St/cast classes)
  std::array<Line, 3> H;        // sigma_Hlim, ML MQ ME
  std::array<Line, 3> F;        // sigma_Flim, ML MQ ME
  double E, nu;                 // ISO 6336-2:2019 Table 4
  double yield;                 // default core proof stress, MPa (ISO 6336-3 Table 2 rows)
};

// ISO 6336-5:2016 Table 1 (the straight lines of Figures 2 to 13). The ME lines agree with the
// public transcription in waa552/fyp-website (data.js); for nitrocarburized steel MQ is taken as
// ML (conservative) for want of a checked value.
constexpr std::array<ClassData, 11> kClasses = {{
    {MaterialClass::normalized_steel, "normalized-steel", "St", 110, 210,
     {{{1.000, 190}, {1.000, 190}, {1.520, 250}}}, {{{0.455, 69}, {0.455, 69}, {0.386, 147}}}, 206000, 0.3, 300},
    {MaterialClass::cast_steel, "cast-steel", "St", 140, 210,
     {{{0.986, 131}, {0.986, 131}, {1.143, 237}}}, {{{0.313, 62}, {0.313, 62}, {0.254, 137}}}, 202000, 0.3, 300},
    {MaterialClass::grey_cast_iron, "grey-cast-iron", "GG", 150, 240,
     {{{1.033, 132}, {1.033, 132}, {1.465, 122}}}, {{{0.256, 8}, {0.256, 8}, {0.200, 53}}}, 118000, 0.3, 0},
    {MaterialClass::nodular_cast_iron, "nodular-cast-iron", "GGG", 175, 300,
     {{{1.434, 211}, {1.434, 211}, {1.500, 250}}}, {{{0.350, 119}, {0.350, 119}, {0.380, 134}}}, 173000, 0.3, 500},
    {MaterialClass::through_hardened_carbon, "through-hardened-carbon", "V", 115, 215,
     {{{0.963, 283}, {0.925, 360}, {0.838, 432}}}, {{{0.250, 108}, {0.240, 163}, {0.283, 202}}}, 206000, 0.3, 500},
    {MaterialClass::through_hardened_alloy, "through-hardened-alloy", "V", 200, 390,
     {{{1.313, 188}, {1.313, 373}, {2.213, 260}}}, {{{0.423, 104}, {0.425, 187}, {0.358, 231}}}, 206000, 0.3, 800},
    {MaterialClass::case_carburized, "case-carburized", "Eh", 600, 800,
     {{{0, 1300}, {0, 1500}, {0, 1650}}}, {{{0, 312}, {0, 425}, {0, 525}}}, 206000, 0.3, 0},
    {MaterialClass::induction_hardened, "induction-hardened", "IF", 485, 615,
     {{{0.740, 602}, {0.541, 882}, {0.505, 1013}}}, {{{0.305, 76}, {0.138, 290}, {0.271, 237}}}, 206000, 0.3, 0},
    {MaterialClass::nitrided, "nitrided", "NT", 650, 900,
     {{{0, 1125}, {0, 1450}, {0, 1450}}}, {{{0, 270}, {0, 420}, {0, 468}}}, 206000, 0.3, 0},
    {MaterialClass::nitrided_through_hardened, "nitrided-through-hardened", "NV(nitr)", 450, 650,
     {{{0, 788}, {0, 998}, {0, 1217}}}, {{{0, 258}, {0, 363}, {0, 432}}}, 206000, 0.3, 0},
    {MaterialClass::nitrocarburized, "nitrocarburized", "NV(nitrocar)", 300, 650,
     {{{0, 650}, {0, 650}, {0, 950}}}, {{{0, 224}, {0, 224}, {0, 388}}}, 206000, 0.3, 0},
}};

const ClassData& data_of(MaterialClass kind) {
  for (const auto& c : kClasses) {
    if (c.kind == kind) return c;
  }
  return kClasses.back();
}

double clamp_hardness(const ClassData& c, double x) { return std::clamp(x, c.x_min, c.x_max); }

// Brinell from Vickers for steels (ISO 18265 table, fitted: HBW ~ 0.95 HV below 450 HV).
double brinell_of(const ClassData& c, double hardness) {
  const bool brinell_scale = c.kind == MaterialClass::normalized_steel || c.kind == MaterialClass::cast_steel ||
                             c.kind == MaterialClass::grey_cast_iron || c.kind == MaterialClass::nodular_cast_iron;
  return brinell_scale ? hardness : 0.95 * hardness;
}

struct Named {
  const char* name;
  MaterialClass kind;
  QualityGrade grade;
  double hardness;
  double yield;
};

constexpr std::array<Named, 12> kNamed = {{
    {"18CrNiMo7-6", MaterialClass::case_carburized, QualityGrade::MQ, 700, 0},
    {"16MnCr5", MaterialClass::case_carburized, QualityGrade::MQ, 700, 0},
    {"20MnCr5", MaterialClass::case_carburized, QualityGrade::MQ, 700, 0},
    {"42CrMo4", MaterialClass::through_hardened_alloy, QualityGrade::MQ, 300, 750},
    {"34CrNiMo6", MaterialClass::through_hardened_alloy, QualityGrade::MQ, 330, 900},
    {"C45", MaterialClass::through_hardened_carbon, QualityGrade::MQ, 200, 490},
    {"42CrMo4-induction", MaterialClass::induction_hardened, QualityGrade::MQ, 560, 0},
    {"31CrMoV9-nitrided", MaterialClass::nitrided, QualityGrade::MQ, 700, 0},
    {"42CrMo4-nitrided", MaterialClass::nitrided_through_hardened, QualityGrade::MQ, 550, 0},
    {"S355", MaterialClass::normalized_steel, QualityGrade::MQ, 160, 355},
    {"GJL-250", MaterialClass::grey_cast_iron, QualityGrade::MQ, 200, 0},
    {"GJS-700", MaterialClass::nodular_cast_iron, QualityGrade::MQ, 260, 420},
}};

std::string known_names() {
  std::string s;
  for (const auto& n : kNamed) s += fmt::format("{}{}", s.empty() ? "" : ", ", n.name);
  return s + ", or CLASS:GRADE:HARDNESS";
}

Material parse_class_form(std::string_view name) {
  const auto c1 = name.find(':');
  const auto c2 = c1 == std::string_view::npos ? c1 : name.find(':', c1 + 1);
  if (c2 == std::string_view::npos) {
    throw std::invalid_argument(fmt::format("unknown material '{}'; expected one of {}", name.substr(0, 60), known_names()));
  }
  const std::string_view cls = name.substr(0, c1), grade = name.substr(c1 + 1, c2 - c1 - 1), hard = name.substr(c2 + 1);
  const ClassData* c = nullptr;
  for (const auto& d : kClasses) {
    if (cls == d.name) c = &d;
  }
  if (!c) {
    std::string classes;
    for (const auto& d : kClasses) classes += fmt::format("{}{}", classes.empty() ? "" : ", ", d.name);
    throw std::invalid_argument(fmt::format("unknown material class '{}'; expected one of {}", cls.substr(0, 60), classes));
  }
  QualityGrade g{};
  if (grade == "ML") g = QualityGrade::ML;
  else if (grade == "MQ") g = QualityGrade::MQ;
  else if (grade == "ME") g = QualityGrade::ME;
  else throw std::invalid_argument(fmt::format("unknown quality grade '{}'; expected ML, MQ or ME", grade.substr(0, 60)));
  double x = 0;
  const auto [end, ec] = std::from_chars(hard.data(), hard.data() + hard.size(), x);
  if (hard.empty() || ec != std::errc() || end != hard.data() + hard.size() || !std::isfinite(x)) {
    throw std::invalid_argument(fmt::format("expected a hardness number after '{}:{}:', found '{}'", cls, grade, hard.substr(0, 60)));
  }
  if (x < c->x_min || x > c->x_max) {
    throw std::invalid_argument(fmt::format("hardness {} outside the range {}..{} of class {} (ISO 6336-5)", x, c->x_min,
                                            c->x_max, c->name));
  }
  return material_of_class(c->kind, g, x, std::string(name));
}

}  // namespace

const char* abbreviation(MaterialClass kind) { return data_of(kind).abbreviation; }
const char* to_string(MaterialClass kind) { return data_of(kind).name; }

const char* to_string(QualityGrade grade) {
  switch (grade) {
    case QualityGrade::ML: return "ML";
    case QualityGrade::MQ: return "MQ";
    case QualityGrade::ME: return "ME";
  }
  return "MQ";
}

double sigma_Hlim_of(MaterialClass kind, QualityGrade grade, double hardness) {
  const ClassData& c = data_of(kind);
  const Line& l = c.H[static_cast<int>(grade)];
  return l.A * clamp_hardness(c, hardness) + l.B;
}

double sigma_Flim_of(MaterialClass kind, QualityGrade grade, double hardness) {
  const ClassData& c = data_of(kind);
  const Line& l = c.F[static_cast<int>(grade)];
  return l.A * clamp_hardness(c, hardness) + l.B;
}

std::pair<double, double> hardness_range(MaterialClass kind) {
  const ClassData& c = data_of(kind);
  return {c.x_min, c.x_max};
}

Material material_of_class(MaterialClass kind, QualityGrade grade, double hardness, std::string name) {
  const ClassData& c = data_of(kind);
  Material m;
  m.name = name.empty() ? fmt::format("{}:{}:{:g}", c.name, to_string(grade), hardness) : std::move(name);
  m.kind = kind;
  m.grade = grade;
  m.hardness = hardness;
  m.HB = brinell_of(c, hardness);
  m.sigma_Hlim = sigma_Hlim_of(kind, grade, hardness);
  m.sigma_Flim = sigma_Flim_of(kind, grade, hardness);
  m.E = c.E;
  m.nu = c.nu;
  m.yield = c.yield;
  return m;
}

Material material_by_name(std::string_view name) {
  for (const auto& n : kNamed) {
    if (name == n.name) {
      Material m = material_of_class(n.kind, n.grade, n.hardness, n.name);
      if (n.yield > 0) m.yield = n.yield;
      return m;
    }
  }
  return parse_class_form(name);
}

std::vector<std::string> material_names() {
  std::vector<std::string> v;
  for (const auto& n : kNamed) v.emplace_back(n.name);
  return v;
}

void validate(const Material& m) {
  auto bad = [](const char* field, double v, const char* expected) {
    throw std::invalid_argument(fmt::format("material {}: expected {}, found {}", field, expected, v));
  };
  if (!(std::isfinite(m.sigma_Hlim) && m.sigma_Hlim > 0)) bad("sigma_Hlim", m.sigma_Hlim, "a stress > 0 MPa");
  if (!(std::isfinite(m.sigma_Flim) && m.sigma_Flim > 0)) bad("sigma_Flim", m.sigma_Flim, "a stress > 0 MPa");
  if (!(std::isfinite(m.E) && m.E > 0)) bad("E", m.E, "a modulus > 0 MPa");
  if (!(std::isfinite(m.nu) && m.nu >= 0 && m.nu < 0.5)) bad("nu", m.nu, "a Poisson ratio in [0, 0.5)");
  if (!(std::isfinite(m.density) && m.density > 0)) bad("density", m.density, "a density > 0");
  if (!(std::isfinite(m.HB) && m.HB >= 0)) bad("HB", m.HB, "a hardness >= 0");
}

}  // namespace gearkit::gear
