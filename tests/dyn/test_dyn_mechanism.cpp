// `gearkit dyn` with a linkage given as a `gearkit kin` mechanism file (plugins/dyn/
// dyn_mechanism.hpp): the reduced inertia comes from the solver's velocity coefficients.
// Reference: the slider-crank's closed-form velocity coefficient of the slider (Norton,
// "Design of Machinery", the exact piston velocity of chapter 13 divided by the crank speed)
//   k(theta) = -r sin(theta) - r^2 sin(theta) cos(theta) / sqrt(l^2 - r^2 sin^2(theta)),
// and I(theta) = I_crank + m_slider k^2 for a massless rod.
#include <run_gearkit.hpp>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

using gearkit::testing::run_gearkit;
using gearkit::testing::shell_quote;

namespace {

constexpr double pi = std::numbers::pi;

// The crank press of examples/dynamics/crank_press_mechanism.yaml.
double press_inertia(double theta) {
  const double r = 0.1, l = 0.4, m = 10, I_crank = 0.05;
  const double s = std::sin(theta), c = std::cos(theta);
  const double k = -r * s - r * r * s * c / std::sqrt(l * l - r * r * s * s);
  return I_crank + m * k * k;
}

std::string example(const std::string& name) {
  return shell_quote(std::string(GEARKIT_SOURCE_DIR) + "/examples/dynamics/" + name);
}

}  // namespace

TEST(DynMechanism, ReducedInertiaOfTheSliderCrankMatchesTheClosedForm) {
  const auto r = run_gearkit("dyn " + example("crank_press_from_mechanism.yaml") + " --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  // Nodes every degree: the table's extremes are the closed form's extremes on that grid.
  double lo = 1e9, hi = 0, mean = 0;
  const int n = 360, fine = 36000;
  for (int i = 0; i < n; ++i) {
    lo = std::min(lo, press_inertia(2 * pi * i / n));
    hi = std::max(hi, press_inertia(2 * pi * i / n));
  }
  for (int i = 0; i < fine; ++i) mean += press_inertia(2 * pi * i / fine) / fine;
  EXPECT_NEAR(j["linkage_inertia_min_kgm2"].get<double>(), lo, 1e-9);
  EXPECT_NEAR(j["linkage_inertia_max_kgm2"].get<double>(), hi, 1e-9);
  EXPECT_NEAR(j["linkage_inertia_mean_kgm2"].get<double>(), mean, 1e-7);
}

TEST(DynMechanism, SameFlywheelAsTheHandTabulatedModel) {
  // crank_press_linkage.yaml types the same I(theta) every 5 deg: the flywheel sized from the
  // mean inertia must agree to the interpolation error of that coarser table.
  const auto a = run_gearkit("dyn " + example("crank_press_from_mechanism.yaml") + " --format json");
  const auto b = run_gearkit("dyn " + example("crank_press_linkage.yaml") + " --format json");
  ASSERT_EQ(a.status, 0) << a.err;
  ASSERT_EQ(b.status, 0) << b.err;
  const auto ja = nlohmann::json::parse(a.out), jb = nlohmann::json::parse(b.out);
  EXPECT_NEAR(ja["inertia_flywheel_kgm2"].get<double>(), jb["inertia_flywheel_kgm2"].get<double>(), 1e-3);
  EXPECT_NEAR(ja["energy_excursion_J"].get<double>(), jb["energy_excursion_J"].get<double>(), 1e-6);
}

// The dyn plugin reads mechanisms with element types of other plugins through the host (issue
// 12): a cam follower. examples/dynamics/cam_rocker_mechanism.yaml reduces to
// I(theta) = I_cam + I_rocker psi'^2 with I_cam = 0.002, I_rocker = 0.05 kg m^2 and the rocker's
// program (cycloidal rise and 3-4-5 return of h = 20 deg over beta = 120 deg each): minimum
// I_cam in the dwells, maximum I_cam + I_rocker (2 h/beta)^2 = I_cam + I_rocker/9 at mid-rise, mean
// I_cam + I_rocker (h^2/beta)(3/2 + 10/7)/(2 pi) (integrals of psi'^2: 3/2 h^2/beta for the
// cycloid, 900 B(5,5) h^2/beta = 10/7 h^2/beta for the 3-4-5 polynomial).
TEST(DynMechanism, CamFollowerMechanismThroughTheHost) {
  const auto r = run_gearkit("dyn " + example("cam_rocker_machine.yaml") + " --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const double h = 20 * pi / 180, beta = 120 * pi / 180, I_cam = 0.002, I_rocker = 0.05;
  EXPECT_NEAR(j["linkage_inertia_min_kgm2"].get<double>(), I_cam, 1e-12);
  EXPECT_NEAR(j["linkage_inertia_max_kgm2"].get<double>(), I_cam + I_rocker / 9, 1e-12);
  EXPECT_NEAR(j["linkage_inertia_mean_kgm2"].get<double>(),
              I_cam + I_rocker * h * h / beta * (1.5 + 10.0 / 7.0) / (2 * pi), 1e-9);
}

// And a gear mesh: pinion 0.01 kg m^2 (z = 20) and gear 0.2 kg m^2 (z = 40) reduce to
// I = 0.01 + 0.2 (20/40)^2 = 0.06 kg m^2 at every angle.
TEST(DynMechanism, GearMeshMechanismThroughTheHost) {
  const auto r = run_gearkit("dyn " + example("geared_drive_machine.yaml") + " --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["linkage_inertia_min_kgm2"].get<double>(), 0.06, 1e-12);
  EXPECT_NEAR(j["linkage_inertia_max_kgm2"].get<double>(), 0.06, 1e-12);
}

TEST(DynMechanism, BadMechanismReferencesAreInputErrors) {
  const auto dir = gearkit::testing::scratch_dir("dyn_mechanism");
  const std::string model = "motor: {speed: 1450 rpm}\nstages:\n  - {ratio: 1/10}\nload:\n  mechanism: MECH\n"
                            "flywheel:\n  fluctuation: 2 %\n  resisting: {constant: 10 N*m}\n  drive: {constant: 10 N*m}\n";
  auto with = [&](const std::string& mech) {
    std::string text = model;
    text.replace(text.find("MECH"), 4, mech);
    std::ofstream(dir / "m.yaml") << text;
    return run_gearkit("dyn " + shell_quote((dir / "m.yaml").string()));
  };
  const auto missing = with("no_such_mechanism.yaml");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("no_such_mechanism.yaml"), std::string::npos) << missing.err;
  EXPECT_NE(missing.err.find("no such file"), std::string::npos) << missing.err;
  // Issue 26, section 3: where the dyn model names it, line 5 "  mechanism: " + the value at column 14.
  EXPECT_NE(missing.err.find("m.yaml:5:14: 'mechanism': cannot read"), std::string::npos) << missing.err;
  const auto folder = with(dir.string());
  EXPECT_EQ(folder.status, 2);
  EXPECT_NE(folder.err.find("m.yaml:5:14: 'mechanism': expected a mechanism file, found the folder"), std::string::npos)
      << folder.err;
  // A mechanism whose links carry no mass has nothing to reduce.
  std::ofstream(dir / "massless.yaml") << "mechanism: bare crank\nground: {O: [0, 0]}\n"
                                          "links:\n  crank: {points: {O: [0, 0], A: [50, 0]}}\n"
                                          "joints:\n  - {name: O, type: revolute, at: [crank.O, ground.O]}\n"
                                          "drivers:\n  - {name: a, type: angle, link: crank}\n";
  const auto massless = with("massless.yaml");
  EXPECT_EQ(massless.status, 2);
  EXPECT_NE(massless.err.find("expected links with 'mass' or 'inertia'"), std::string::npos) << massless.err;
  EXPECT_NE(massless.err.find("m.yaml:5:"), std::string::npos) << massless.err;  // where it was named
}
