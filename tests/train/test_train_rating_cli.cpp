// CLI tests of `gearkit train FILE --torque ... --rate` (plugins/train/train_rating.cpp).
#include "run_gearkit.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace {

using CliRun = gearkit::testing::RunResult;

CliRun run(const std::string& args) { return gearkit::testing::run_gearkit("train " + args); }

const std::string kFile = std::string(GEARKIT_SOURCE_DIR) + "/examples/trains/rated_planetary.yaml";

}  // namespace

TEST(TrainRating, EveryMeshFromTheTrainsTorquesAndSpeeds) {
  const CliRun r = run("'" + kFile + "' --torque sun=40N*m --rate --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto meshes = nlohmann::json::parse(r.out)["rating"]["meshes"];
  ASSERT_EQ(meshes.size(), 2u);
  const auto& sun = meshes[0];
  const auto& ring = meshes[1];
  // Sun mesh: each of 3 planets carries 40/3 N m of the sun; the sun turns at 1000 - 1000/i
  // relative to the carrier, i = 1 + 108/21 (fixed ring).
  const double i = 1.0 + 108.0 / 21.0;
  EXPECT_NEAR(sun["T_1_Nm"].get<double>(), 40.0 / 3.0, 1e-9);
  EXPECT_NEAR(sun["n_1_rpm"].get<double>(), 1000.0 - 1000.0 / i, 1e-6);
  EXPECT_NEAR(sun["K_gamma"].get<double>(), 1.1, 1e-12);
  // The planet is balanced about its own axis: the ring pushes it with the same tangential force
  // as the sun (ideal train), so both meshes have the same F_t.
  EXPECT_NEAR(ring["F_t_N"].get<double>(), sun["F_t_N"].get<double>(), 1e-6 * sun["F_t_N"].get<double>());
  // The planet (pinion of the ring mesh) turns z_s/z_p times the sun's relative speed.
  EXPECT_NEAR(ring["n_1_rpm"].get<double>(), (1000.0 - 1000.0 / i) * 21.0 / 43.0, 1e-6);
  // Load cycles: the sun meets 3 planets per relative turn, a planet tooth one sun per turn.
  const double hours = 10000.0;
  EXPECT_NEAR(sun["gears"][0]["N_L"].get<double>(), 3.0 * 60.0 * hours * sun["n_1_rpm"].get<double>(), 1.0);
  EXPECT_NEAR(sun["gears"][1]["N_L"].get<double>(), 60.0 * hours * ring["n_1_rpm"].get<double>(), 1.0);
  // The planet is bent both ways (Y_M = 0.7), the sun one way.
  EXPECT_DOUBLE_EQ(sun["gears"][1]["Y_M"].get<double>(), 0.7);
  EXPECT_DOUBLE_EQ(sun["gears"][0]["Y_M"].get<double>(), 1.0);
  EXPECT_FALSE(nlohmann::json::parse(r.out)["rating"]["weakest"].get<std::string>().empty());
}

TEST(TrainRating, TorqueDoublesStresses) {
  const auto a = nlohmann::json::parse(run("'" + kFile + "' --torque sun=40N*m --rate --format json").out)["rating"]["meshes"];
  const auto b = nlohmann::json::parse(run("'" + kFile + "' --torque sun=80N*m --rate --format json").out)["rating"]["meshes"];
  EXPECT_NEAR(b[0]["F_t_N"].get<double>() / a[0]["F_t_N"].get<double>(), 2.0, 1e-9);
  EXPECT_LT(b[0]["gears"][0]["S_H"].get<double>(), a[0]["gears"][0]["S_H"].get<double>());
}

TEST(TrainRating, BadInput) {
  const CliRun no_load = run("'" + kFile + "' --rate");
  EXPECT_EQ(no_load.status, 2);
  EXPECT_NE(no_load.err.find("'--rate'"), std::string::npos) << no_load.err;
  const fs::path bad = fs::temp_directory_path() / ("gearkit-train-rating-bad-" + std::to_string(::getpid()) + ".yaml");
  std::ifstream in(kFile);
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  s.replace(s.find("material: 18CrNiMo7-6"), std::string("material: 18CrNiMo7-6").size(), "material: balsa");
  std::ofstream(bad) << s;
  const CliRun r = run("'" + bad.string() + "' --torque sun=40N*m --rate");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(bad.filename().string() + ":"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1);
}

namespace {

// rated_planetary.yaml with `from` replaced by `to`, written to a scratch file; `line` gets the
// line of the replacement.
std::string edited(const std::string& name, const std::string& from, const std::string& to, int* line = nullptr) {
  std::ifstream in(kFile);
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  const std::size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  s.replace(at, from.size(), to);
  if (line) *line = 1 + static_cast<int>(std::count(s.begin(), s.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
  const fs::path p = gearkit::testing::scratch_dir("train-rating") / name;
  std::ofstream(p) << s;
  return p.string();
}

void expect_error_at(const CliRun& r, const std::string& where) {
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_NE(r.err.find(where), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
}

}  // namespace

// A bad rating value is reported at its own key (not at `rating:`), without internal field names.
TEST(TrainRating, ErrorsNameTheOffendingKey) {
  int line = 0;
  const std::string quality = edited("quality13.yaml", "quality: 6", "quality: 13", &line);
  CliRun r = run("'" + quality + "' --torque sun=40N*m --rate");
  expect_error_at(r, "quality13.yaml:" + std::to_string(line) + ":12:");
  const std::string life = edited("life_negative.yaml", "life: 10000 h", "life: -2 h", &line);
  r = run("'" + life + "' --torque sun=40N*m --rate");
  expect_error_at(r, "life_negative.yaml:" + std::to_string(line) + ":9:");
  EXPECT_EQ(r.err.find("life_h"), std::string::npos) << r.err;
}

// The same material reader as gear-pair files: a user-defined material map is accepted.
TEST(TrainRating, UserDefinedMaterialMap) {
  const std::string file = edited("own_material.yaml", "material: 18CrNiMo7-6", "material: {name: mine, sigma_Hlim: 1200, sigma_Flim: 350}");
  const CliRun r = run("'" + file + "' --torque sun=40N*m --rate --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto sun = nlohmann::json::parse(r.out)["rating"]["meshes"][0];
  EXPECT_EQ(sun["materials"][0], "mine");
  // sigma_HP = sigma_Hlim Z_NT Z_L Z_v Z_R Z_W Z_X / S_Hmin with the user's sigma_Hlim = 1200 MPa.
  const auto& g = sun["gears"][0];
  const double product = g["Z_NT"].get<double>() * g["Z_L"].get<double>() * g["Z_v"].get<double>() * g["Z_R"].get<double>() *
                         g["Z_W"].get<double>() * g["Z_X"].get<double>();
  EXPECT_NEAR(g["sigma_HP_MPa"].get<double>(), 1200.0 * product, 1e-9 * 1200.0);
  const std::string bad = edited("bad_material.yaml", "material: 18CrNiMo7-6", "material: {name: mine, sigma_Hlim: -5, sigma_Flim: 350}");
  expect_error_at(run("'" + bad + "' --torque sun=40N*m --rate"), "bad_material.yaml:");
}

// The sun of the shipped planetary floats between 3 planets: its face load is not the pinion-on-
// shaft bending formula but the sun model of docs/rating.md: ISO 6336-1 Eq. 43 with no bending term
// (the planets' forces balance) and the sun body twisted by all 3 planets' torque, B* = 3:
// f_sh = F_m/b 0.023 * 3 (b/d_1)^2, b = 20 mm, d_1 = 21 * 1.75 = 36.75 mm.
TEST(TrainRating, SunFaceLoadFollowsTheSunModel) {
  const CliRun r = run("'" + kFile + "' --torque sun=40N*m --rate --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto sun = nlohmann::json::parse(r.out)["rating"]["meshes"][0];
  ASSERT_TRUE(sun.contains("face_load")) << sun.dump();
  EXPECT_EQ(sun["face_load"]["model"], "sun");
  EXPECT_DOUBLE_EQ(sun["face_load"]["B_star"].get<double>(), 3.0);
  const auto& f = sun["factors"];
  const double F_m_per_b = sun["F_t_N"].get<double>() * f["K_A"].get<double>() * f["K_gamma"].get<double>() * f["K_v"].get<double>() / 20.0;
  const double f_sh = F_m_per_b * 0.023 * 3.0 * std::pow(20.0 / 36.75, 2.0);
  EXPECT_NEAR(sun["face_load"]["f_sh_um"].get<double>(), f_sh, 1e-9);
  // F_betax = 1.33 f_sh + f_ma (Eq. 38); y_beta = 0.15 F_betax (case-carburized, Table 11);
  // K_Hbeta by Eq. 35/36.
  const double F_betax = sun["F_betax_um"].get<double>();
  const double F_betay = F_betax - std::min(0.15 * F_betax, 6.0);
  EXPECT_NEAR(sun["F_betay_um"].get<double>(), F_betay, 1e-9);
  const double c = sun["c_gamma_beta"].get<double>();
  const double K = 1.0 + c * F_betay / (2.0 * F_m_per_b);
  EXPECT_NEAR(f["K_Hbeta"].get<double>(), K <= 2.0 ? K : std::sqrt(2.0 * c * F_betay / F_m_per_b), 1e-9);
  const CliRun text = run("'" + kFile + "' --torque sun=40N*m --rate");
  EXPECT_NE(text.out.find("Mesh 's-p': face load by the sun model (3 planets, B* = 3"), std::string::npos) << text.out;
  // The planet-ring mesh keeps the pinion (planet) on its pin, centred: B* = 1, K' = 0, no face_load entry.
  EXPECT_FALSE(nlohmann::json::parse(r.out)["rating"]["meshes"][1].contains("face_load"));
}

// A mesh's own `rating:` takes the keys of a gear-pair file (factors, deviations, face_load, ...).
TEST(TrainRating, PerMeshRatingInputs) {
  const CliRun base = run("'" + kFile + "' --torque sun=40N*m --rate --format json");
  ASSERT_EQ(base.status, 0) << base.err;
  const auto b = nlohmann::json::parse(base.out)["rating"]["meshes"];
  const std::string file = edited("mesh_rating.yaml", "- {gears: [s, p], carrier: carrier}",
                                  "- {gears: [s, p], carrier: carrier, rating: {factors: {K_Hbeta: 1.3}, application_factor: 1.5}}");
  const CliRun r = run("'" + file + "' --torque sun=40N*m --rate --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto m = nlohmann::json::parse(r.out)["rating"]["meshes"];
  EXPECT_DOUBLE_EQ(m[0]["factors"]["K_Hbeta"].get<double>(), 1.3);
  EXPECT_DOUBLE_EQ(m[0]["factors"]["K_A"].get<double>(), 1.5);
  EXPECT_DOUBLE_EQ(m[1]["factors"]["K_Hbeta"].get<double>(), b[1]["factors"]["K_Hbeta"].get<double>());  // other mesh as before
  // Choosing the pinion-on-shaft model for the sun gives Eq. 43 with B* = 1 instead of 3: F_betax
  // (Eq. 38) drops by 1.33 F_m/b 0.023 (3 - 1) (b/d_1)^2.
  const std::string shaft = edited("sun_shaft.yaml", "- {gears: [s, p], carrier: carrier}",
                                   "- {gears: [s, p], carrier: carrier, rating: {face_load: {model: pinion-shaft}}}");
  const CliRun s = run("'" + shaft + "' --torque sun=40N*m --rate --format json");
  ASSERT_EQ(s.status, 0) << s.err;
  const auto sun = nlohmann::json::parse(s.out)["rating"]["meshes"][0];
  const auto& f = sun["factors"];
  const double F_m_per_b = sun["F_t_N"].get<double>() * f["K_A"].get<double>() * f["K_gamma"].get<double>() * f["K_v"].get<double>() / 20.0;
  EXPECT_NEAR(b[0]["F_betax_um"].get<double>() - sun["F_betax_um"].get<double>(), 1.33 * F_m_per_b * 0.023 * 2.0 * std::pow(20.0 / 36.75, 2.0),
              1e-9);
  EXPECT_FALSE(sun.contains("face_load"));  // the plain pinion on a centred shaft: reported as before
  // A bad value in a mesh's rating is reported at its key.
  int line = 0;
  const std::string bad = edited("mesh_quality.yaml", "- {gears: [s, p], carrier: carrier}",
                                 "- {gears: [s, p], carrier: carrier, rating: {face_load: {arrangement: z}}}", &line);
  expect_error_at(run("'" + bad + "' --torque sun=40N*m --rate"), "mesh_quality.yaml:" + std::to_string(line) + ":");
}

// Issue 25: a mesh's tools and thickness allowances, and one source of the allowances in both
// commands. The sun mesh s-p (z 21/43, m 1.75 mm, x 0.4380/0.0426, b 20 mm, grade 6) rated in the
// train and the same pair rated by `gearkit gear` with the same upper allowances give the same
// tooth-form factors Y_F, Y_S (they depend on the geometry and the generating shift only).
TEST(TrainRating, MeshToolsAndAllowancesAreThoseOfAGearPair) {
  const auto Y_of = [](const nlohmann::json& gear) { return std::pair{gear["Y_F"].get<double>(), gear["Y_S"].get<double>()}; };
  const std::string pair = "gear --z1 21 --z2 43 --module 1.75 --x1 0.4380 --x2 0.0426 --face-width 20 --torque1 10N*m "
                           "--speed1 800rpm --material1 18CrNiMo7-6 --material2 18CrNiMo7-6 --f-pb 8 --f-falpha 9 "
                           "--F-betax 10 --format json ";
  // Without allowance1/2 the mesh's grade 6 gives ISO/TR 10064-2's allowances, as --quality 6 does.
  const CliRun base = run("'" + kFile + "' --torque sun=40N*m --rate --format json");
  ASSERT_EQ(base.status, 0) << base.err;
  const auto by_grade = nlohmann::json::parse(base.out)["rating"]["meshes"][0]["gears"];
  const CliRun g6 = gearkit::testing::run_gearkit(pair + "--quality 6");
  ASSERT_EQ(g6.status, 0) << g6.err;
  const auto gear6 = nlohmann::json::parse(g6.out)["rating"]["gears"];
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(Y_of(by_grade[i]).first, Y_of(gear6[i]).first, 1e-12);
    EXPECT_NEAR(Y_of(by_grade[i]).second, Y_of(gear6[i]).second, 1e-12);
  }
  const CliRun note = run("'" + kFile + "' --torque sun=40N*m --rate");
  EXPECT_NE(note.out.find("Mesh 's-p': tooth root (Y_F, Y_S) at the generating shift"), std::string::npos) << note.out;
  EXPECT_NE(note.out.find("(ISO/TR 10064-2 for grade 6)"), std::string::npos);
  // Given allowances and a tool per gear: the same as the gear command with the same inputs.
  const std::string file = edited("mesh_tools.yaml", "- {gears: [s, p], carrier: carrier}",
                                  "- {gears: [s, p], carrier: carrier, rating: {allowance1: -0.06 mm, allowance2: -0.03 mm, "
                                  "rack2: {dedendum: 1.4, root_radius: 0.25}, reversed_bending2: false}}");
  const CliRun r = run("'" + file + "' --torque sun=40N*m --rate --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto mesh = nlohmann::json::parse(r.out)["rating"]["meshes"][0]["gears"];
  const CliRun g = gearkit::testing::run_gearkit(pair + "--thickness-allowances1 -0.06,-0.09 --thickness-allowances2 -0.03,-0.06 "
                                                        "--rack2 1,1.4,0.25");
  ASSERT_EQ(g.status, 0) << g.err;
  const auto gear = nlohmann::json::parse(g.out)["rating"]["gears"];
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(Y_of(mesh[i]).first, Y_of(gear[i]).first, 1e-12) << "gear " << i + 1;
    EXPECT_NEAR(Y_of(mesh[i]).second, Y_of(gear[i]).second, 1e-12) << "gear " << i + 1;
  }
  // The allowance thins the sun's root chord s_Fn, so Y_F rises above the nominal tooth's (x_E = x),
  // as ISO 6336-3's Y_F = 6 (h_Fe/m_n) cos(alpha_Fen) / ((s_Fn/m_n)^2 cos(alpha_n)) says.
  const CliRun nominal = gearkit::testing::run_gearkit(pair);
  ASSERT_EQ(nominal.status, 0) << nominal.err;
  EXPECT_GT(Y_of(mesh[0]).first, Y_of(nlohmann::json::parse(nominal.out)["rating"]["gears"][0]).first);
  // The planet's default reversed bending (Y_M = 0.7) is overridden by the mesh's key.
  EXPECT_DOUBLE_EQ(mesh[1]["Y_M"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(by_grade[1]["Y_M"].get<double>(), 0.7);
}

// Issue 25: the hand of every helical gear is printed, from each gear's own signed helix angle
// (docs/train.md: > 0 right hand); an external pair has opposite hands, an internal pair the same.
TEST(TrainRating, HelixHandOfEveryGearIsPrinted) {
  std::ifstream in(kFile);
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"x: 0.4380,", "x: 0.4380, helix_angle: 12 deg,"},
                                 {"x: 0.0426,", "x: 0.0426, helix_angle: -12 deg,"}, {"x: 0, face_width: 22 mm,", "x: 0, face_width: 22 mm, helix_angle: -12 deg,"}}) {
    const std::size_t at = s.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    s.replace(at, from.size(), to);
  }
  const fs::path p = gearkit::testing::scratch_dir("train-rating") / "helical.yaml";
  std::ofstream(p) << s;
  const CliRun r = run("'" + p.string() + "' --torque sun=40N*m --rate --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto meshes = nlohmann::json::parse(r.out)["rating"]["meshes"];
  EXPECT_EQ(meshes[0]["helix_hands"], nlohmann::json({"right", "left"}));  // sun +12, planet -12
  EXPECT_EQ(meshes[1]["helix_hands"], nlohmann::json({"left", "left"}));   // planet and ring: the same hand
  const CliRun t = run("'" + p.string() + "' --torque sun=40N*m --rate");
  EXPECT_NE(t.out.find("Helix hands: s right, p left, r left."), std::string::npos) << t.out;
  // A spur train says nothing of hands.
  EXPECT_EQ(run("'" + kFile + "' --torque sun=40N*m --rate").out.find("Helix hands"), std::string::npos);
}

// Issue 25 (face widths per gear): the ring (22 mm) is wider than its planet (20 mm). The mesh
// carries the common 20 mm, and the ring's root the common width plus what it extends beyond the
// planet, at most one module (1.75 mm) on each side: 20 + 2 x 1 = 22 mm (ISO 6336-3). Its root
// stress is then 20/22 of the stress of a 20 mm ring; the pitting stresses do not change.
TEST(TrainRating, AWiderGearCarriesItsRootOverItsOwnFace) {
  const auto meshes = [&](const std::string& file) {
    const CliRun r = run("'" + file + "' --torque sun=40N*m --rate --format json");
    EXPECT_EQ(r.status, 0) << r.err;
    return nlohmann::json::parse(r.out)["rating"]["meshes"];
  };
  const auto wide = meshes(kFile)[1]["gears"];
  const auto narrow = meshes(edited("ring20.yaml", "x: 0, face_width: 22 mm,", "x: 0, face_width: 20 mm,"))[1]["gears"];
  EXPECT_NEAR(wide[1]["sigma_F_MPa"].get<double>() / narrow[1]["sigma_F_MPa"].get<double>(), 20.0 / 22.0, 1e-12);
  EXPECT_NEAR(wide[0]["sigma_F_MPa"].get<double>(), narrow[0]["sigma_F_MPa"].get<double>(), 1e-9);  // the planet: its own 20 mm
  EXPECT_NEAR(wide[1]["sigma_H_MPa"].get<double>(), narrow[1]["sigma_H_MPa"].get<double>(), 1e-9);
}

// The oil's FZG stage in `rating:` rates every mesh for scuffing (ISO/TS 6336-21): a table and
// each mesh's JSON `scuffing`. The ring mesh (planet against a concave ring) runs cooler than the
// sun mesh at the same tangential force (larger relative radius, slower sliding); a missing oil
// temperature is an error.
TEST(TrainRating, ScuffingOfEveryMesh) {
  const std::string oil = "application_factor: 1.25\n  fzg_stage: 12\n  oil_temperature: 70\n  oil_viscosity_100: 19";
  const std::string file = edited("scuffing.yaml", "application_factor: 1.25", oil);
  const CliRun r = run("'" + file + "' --torque sun=40N*m --rate --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto meshes = nlohmann::json::parse(r.out)["rating"]["meshes"];
  ASSERT_EQ(meshes.size(), 2u);
  const auto& sun = meshes[0]["scuffing"];
  const auto& ring = meshes[1]["scuffing"];
  ASSERT_TRUE(sun.is_object() && ring.is_object());
  EXPECT_GT(ring["rho_redC_mm"].get<double>(), sun["rho_redC_mm"].get<double>());
  EXPECT_LT(ring["theta_flaE_K"].get<double>(), sun["theta_flaE_K"].get<double>());
  EXPECT_GT(sun["S_intS"].get<double>(), 1.0);
  const CliRun text = run("'" + file + "' --torque sun=40N*m --rate");
  EXPECT_NE(text.out.find("Scuffing of the meshes"), std::string::npos) << text.out;
  // Without the oil temperature: an error naming where the rating's oil is.
  int line = 0;
  const std::string no_temp = edited("scuffing_no_temp.yaml", "application_factor: 1.25",
                                     "application_factor: 1.25\n  fzg_stage: 12\n  oil_viscosity_100: 19", &line);
  const CliRun bad = run("'" + no_temp + "' --torque sun=40N*m --rate");
  EXPECT_EQ(bad.status, 2) << bad.err;
  EXPECT_NE(bad.err.find("oil temperature"), std::string::npos) << bad.err;
}
