// CLI tests of the accuracy and inspection options of `gearkit gear`
// (plugins/gear/gear_tolerance_options.cpp, gear_tolerance_report.cpp), run through GEARKIT_EXE.
#include "run_gearkit.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

using gearkit::testing::run_gearkit;

namespace {

constexpr const char* kPair = "gear --z1 20 --z2 40 --module 3 --face-width 30 ";

nlohmann::json json_of(const std::string& options) {
  const auto r = run_gearkit(std::string(kPair) + options + " --format json");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  return nlohmann::json::parse(r.out);
}

}  // namespace

// z = 20/40, m = 3, class 7 of ISO 1328-1:2013, by hand (see test_inspection.cpp): gear 1 f_pT =
// (0.06 + 1.2 + 5) 2 = 12.52 -> 13 um, F_pT = 36.96 -> 37 um; j_bn,min = 0.13 mm (ISO/TR 10064-2).
TEST(GearToleranceCommand, JsonFieldsAsTheIssueNamesThem) {
  const auto j = json_of("--quality 7");
  for (const auto& g : j["gears"]) {
    for (const char* key : {"f_pT_um", "F_pT_um", "F_alphaT_um", "f_falphaT_um", "f_HalphaT_um", "F_betaT_um",
                            "f_fbetaT_um", "f_HbetaT_um", "F_rT_um", "F_id_um", "f_id_um", "edition", "grade"}) {
      EXPECT_TRUE(g["tolerances"].contains(key)) << key;
    }
    for (const char* key : {"W_k_max_mm", "W_k_min_mm", "M_d_max_mm", "M_d_min_mm", "A_sne_mm", "A_sni_mm", "T_sn_mm"}) {
      EXPECT_TRUE(g.contains(key)) << key;
    }
    EXPECT_GT(g["W_k_max_mm"].get<double>(), g["W_k_min_mm"].get<double>());
    EXPECT_GT(g["M_d_max_mm"].get<double>(), g["M_d_min_mm"].get<double>());
  }
  EXPECT_EQ(j["gears"][0]["tolerances"]["f_pT_um"], 13.0);
  EXPECT_EQ(j["gears"][0]["tolerances"]["F_pT_um"], 37.0);
  const auto& b = j["pair"]["backlash"];
  for (const char* key : {"j_n_min_mm", "j_n_max_mm", "j_t_min_mm", "j_t_max_mm"}) EXPECT_TRUE(b.contains(key)) << key;
  EXPECT_NEAR(b["j_n_min_mm"].get<double>(), 0.13, 1e-9);
  EXPECT_TRUE(b["operating"].is_null());
  EXPECT_EQ(j["pair"]["centre_distance_allowances"]["field"], "js8");
}

TEST(GearToleranceCommand, QualityPerGearAndThe1995Edition) {
  const auto j = json_of("--quality 6,8");
  EXPECT_EQ(j["gears"][0]["tolerances"]["grade"], 6);
  EXPECT_EQ(j["gears"][1]["tolerances"]["grade"], 8);
  // 1995, grade 6, gear 2 (d = 120 mm, m_n = 3 mm, b = 30 mm): f_pt 8.5, F_p 27 um (test_accuracy.cpp).
  const auto k = json_of("--quality 6 --iso1328-edition 1995");
  EXPECT_EQ(k["gears"][1]["tolerances"]["edition"], "ISO 1328-1:1995");
  EXPECT_EQ(k["gears"][1]["tolerances"]["f_pT_um"], 8.5);
  EXPECT_EQ(k["gears"][1]["tolerances"]["F_pT_um"], 27.0);
}

TEST(GearToleranceCommand, GivenAllowancesAndTemperatures) {
  const auto j = json_of("--thickness-allowances1 -0.05,-0.1 --thickness-allowances2 '-60 um,-0.12 mm' "
                         "--centre-distance-allowances 0.02,-0.01");
  EXPECT_TRUE(j["gears"][0]["tolerances"].is_null());
  EXPECT_NEAR(j["gears"][1]["A_sne_mm"].get<double>(), -0.06, 1e-12);
  EXPECT_EQ(j["gears"][0]["thickness_allowances_from"], "given");
  // Gears 80 deg C, housing 40 deg C (steel): the warm state is the tighter one and gets j_bn,min.
  const auto w = json_of("--quality 7 --temperature 80,40");
  EXPECT_NEAR(w["pair"]["backlash"]["operating"]["j_n_min_mm"].get<double>(), 0.13, 1e-9);
  EXPECT_GT(w["pair"]["backlash"]["j_n_min_mm"].get<double>(), 0.13);
}

TEST(GearToleranceCommand, BadInputExitsWithStatus2AndNamesTheOption) {
  const std::pair<const char*, const char*> cases[] = {
      {"--quality 12", "--quality"},
      {"--quality 0", "--quality"},
      {"--quality 7.5", "--quality"},
      {"--quality 6,7,8", "--quality"},
      {"--quality 13 --iso1328-edition 1995", "--quality"},
      {"--quality 7 --iso1328-edition 2000", "--iso1328-edition"},
      {"--thickness-allowances1 -0.1,-0.05 --quality 7", "--thickness-allowances1"},
      {"--thickness-allowances2 -0.1 --quality 7", "--thickness-allowances2"},
      {"--thickness-allowances1 -0.05,-0.1", "--quality"},
      {"--quality 7 --centre-distance-tolerance h7", "--centre-distance-tolerance"},
      {"--quality 7 --centre-distance-tolerance js13", "--centre-distance-tolerance"},
      {"--quality 7 --centre-distance-allowances -0.02,0.02", "--centre-distance-allowances"},
      {"--min-backlash 0.1", "--min-backlash"},
      {"--quality 7 --temperature 900", "--temperature"},
      {"--quality 7 --expansion 1e-5,1e-5,2e-5", "--expansion"},
      {"--din3967 27x", "--din3967"},   // a deviation series that does not exist
      {"--din3967 31cd", "--din3967"},  // nor a tolerance series
      {"--din3967 27cd --thickness-allowances1 -0.05,-0.1", "--din3967"},
  };
  for (const auto& [args, option] : cases) {
    const auto r = run_gearkit(std::string(kPair) + args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(r.out, "") << args;
    EXPECT_EQ(r.err.rfind("gearkit: ", 0), 0u) << args << ": " << r.err;
    EXPECT_NE(r.err.find(option), std::string::npos) << args << ": " << r.err;
    EXPECT_EQ(gearkit::testing::count_lines(r.err), 1) << args << ": " << r.err;
  }
}

// DIN 3967 clause 3.1 example: 27cd at d = 100 mm (z = 50, m = 2) -> A_sne = -70 um, A_sni = -170 um.
TEST(GearToleranceCommand, Din3967Designation) {
  const auto r = run_gearkit("gear --z1 20 --z2 50 --module 2 --din3967 25e,27cd --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["gears"][1]["din3967"], "27cd");
  EXPECT_NEAR(j["gears"][1]["A_sne_mm"].get<double>(), -0.070, 1e-12);
  EXPECT_NEAR(j["gears"][1]["A_sni_mm"].get<double>(), -0.170, 1e-12);
  EXPECT_EQ(j["gears"][0]["thickness_allowances_from"], "DIN 3967");
}

TEST(GearToleranceCommand, NoBacklashIsAWarning) {
  const std::string args = std::string(kPair) +
                           "--thickness-allowances1 0,-0.03 --thickness-allowances2 0,-0.03 --centre-distance-tolerance js8";
  const auto r = run_gearkit(args);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("minimum backlash"), std::string::npos);
  EXPECT_EQ(run_gearkit(args + " --strict").status, 3);
}

// ISO 1328-1:1995 grades run 0..12 (the help says so); grade 0 used to fail in the ISO/TR 10064-2
// allowances (no radial infeed tolerance below grade 1).
TEST(GearToleranceCommand, Iso1328_1995GradeZero) {
  const auto j = json_of("--quality 0 --iso1328-edition 1995");
  EXPECT_EQ(j["gears"][0]["tolerances"]["grade"], 0);
  EXPECT_EQ(j["gears"][0]["tolerances"]["edition"], "ISO 1328-1:1995");
  EXPECT_GT(j["gears"][0]["W_k_max_mm"].get<double>(), j["gears"][0]["W_k_min_mm"].get<double>());
}

// The audit's case: gear 1's tolerance (10 um) is narrower than its runout term (2 x 8.65 um): no
// acceptance band; W_k and M_d limits are both null (not one inverted and one re-sorted).
TEST(GearToleranceCommand, NoAcceptanceBandNullsSpanAndPinLimitsAlike) {
  const auto j = json_of("--thickness-allowances1 0.005,-0.005 --thickness-allowances2 0,-0.02 --quality 7");
  const auto& g1 = j["gears"][0];
  EXPECT_EQ(g1["acceptance_band"], false);
  for (const char* key : {"W_k_max_mm", "W_k_min_mm", "M_d_max_mm", "M_d_min_mm"}) EXPECT_TRUE(g1[key].is_null()) << key;
  EXPECT_EQ(j["gears"][1]["acceptance_band"], true);
  const auto r = run_gearkit(std::string(kPair) + "--thickness-allowances1 0.005,-0.005 --thickness-allowances2 0,-0.02 --quality 7");
  EXPECT_NE(r.out.find("gear 1: the thickness tolerance"), std::string::npos) << r.out;
}

// A narrow helical gear: one face-width warning per gear for the span, not one for the nominal
// W_k and another for W_k,max.
TEST(GearToleranceCommand, OneFaceWidthWarningPerGear) {
  const auto r = run_gearkit("gear --z1 20 --z2 40 --module 3 --helix-angle 30 --face-width 8 --quality 7");
  ASSERT_EQ(r.status, 0) << r.err;
  int narrow = 0;
  for (std::size_t at = r.out.find("too narrow"); at != std::string::npos; at = r.out.find("too narrow", at + 1)) ++narrow;
  EXPECT_EQ(narrow, 2) << r.out;
}
