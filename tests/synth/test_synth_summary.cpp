// `gearkit synth`'s mechanism summary (issue 32 item 1) over the motion the linkage really makes,
// against the closed-form four-bar transmission angle and the crank-rocker's limit positions.
#include <run_gearkit.hpp>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

using gearkit::testing::count_lines;
using gearkit::testing::run_gearkit;
using gearkit::testing::shell_quote;

namespace {

constexpr double pi = std::numbers::pi;

std::string example(const std::string& name) {
  return shell_quote(std::string(GEARKIT_SOURCE_DIR) + "/examples/synthesis/" + name);
}

nlohmann::json synth_json(const std::string& args) {
  const auto r = run_gearkit("synth " + args + " --format json");
  EXPECT_EQ(r.status, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

struct MuRange {
  double min = 0, max = 0;  // [deg]
};

// The acute transmission angle of a four-bar whose crank turns fully (Norton, Design of
// Machinery, eq. 4.32; Shigley and Uicker, sect. 1.9): as the crank turns the coupler-rocker
// angle runs monotonically between acos(c+) and acos(c-), c+- = (b^2 + c^2 - a^2 - d^2 +- 2 a d) /
// (2 b c), at theta2 along the ground line and opposite; the acute angle folds it at 90 deg.
MuRange closed_form_mu(const nlohmann::json& linkage) {
  const double a = linkage["crank_mm"], b = linkage["coupler_mm"], c = linkage["rocker_mm"], d = linkage["ground_mm"];
  const double lo = std::acos((b * b + c * c - a * a - d * d + 2 * a * d) / (2 * b * c)) * 180 / pi;
  const double hi = std::acos((b * b + c * c - a * a - d * d - 2 * a * d) / (2 * b * c)) * 180 / pi;
  const auto acute = [](double m) { return std::min(m, 180 - m); };
  return {std::min(acute(lo), acute(hi)), lo < 90 && hi > 90 ? 90.0 : std::max(acute(lo), acute(hi))};
}

// Norton's quick-return crank-rocker: the crank turns fully, so the summary covers the whole
// turn and finds the closed-form extremes; the rocker's limit positions are where crank and
// coupler lie in line, |O2 B| = b +- a, so at O4 cos(angle O2 O4 B) = (d^2 + c^2 - (b +- a)^2) /
// (2 d c), and the two differ by the task's 45 deg swing.
TEST(SynthSummary, CrankRockerOverTheFullTurnIsTheClosedForm) {
  const auto j = synth_json("crank-rocker " + example("crank_rocker.yaml"));
  const auto& s = j["summary"];
  EXPECT_EQ(s["motion"], "full turn");
  const MuRange mu = closed_form_mu(j["linkage"]);
  // 0.1 deg samples: near a smooth extreme mu is quadratic in theta2, so sampling misses it by far
  // less than 1e-3 deg; where the acute angle folds at 90 deg it has a corner, missed by up to the
  // step times the slope (below 0.1 deg).
  EXPECT_NEAR(s["transmission_angle_min_deg"].get<double>(), mu.min, 1e-3);
  EXPECT_NEAR(s["transmission_angle_max_deg"].get<double>(), mu.max, mu.max == 90 ? 0.1 : 1e-3);
  const auto& l = j["linkage"];
  const double a = l["crank_mm"], b = l["coupler_mm"], c = l["rocker_mm"], d = l["ground_mm"];
  const double extended = std::acos((d * d + c * c - (b + a) * (b + a)) / (2 * d * c));
  const double folded = std::acos((d * d + c * c - (b - a) * (b - a)) / (2 * d * c));
  EXPECT_NEAR(std::abs(extended - folded) * 180 / pi, 45.0, 1e-9);  // the task's swing
  std::vector<double> theta4;
  for (const auto& p : s["limit_positions"])
    if (p["kind"] == "rocker max" || p["kind"] == "rocker min") theta4.push_back(p["theta4_deg"]);
  ASSERT_EQ(theta4.size(), 2u);
  const double swing = std::abs(std::remainder(theta4[0] - theta4[1], 360.0));
  EXPECT_NEAR(swing, 45.0, 1e-6);  // the parabola through 0.1 deg samples: O(h^3)
}

// Every four-bar task: over the full turn when the crank turns fully (the closed form then), else
// over the travel; never a larger least angle than the task's travel alone shows.
TEST(SynthSummary, EveryTaskSummarisesTheMotionReallyMade) {
  for (const char* task : {"function function_log10.yaml", "motion two_positions.yaml", "motion three_positions.yaml",
                           "motion four_positions.yaml", "motion five_positions.yaml", "crank-rocker crank_rocker.yaml",
                           "dwell dwell.yaml"}) {
    const std::string t(task);
    const auto space = t.find(' ');
    const auto j = synth_json(t.substr(0, space) + " " + example(t.substr(space + 1)));
    ASSERT_TRUE(j.contains("summary")) << task;
    const auto& s = j["summary"];
    EXPECT_LE(s["transmission_angle_min_deg"].get<double>(), j["transmission_angle_min_deg"].get<double>() + 1e-9) << task;
    if (j["crank_turns_fully"].get<bool>()) {
      EXPECT_EQ(s["motion"], "full turn") << task;
      const MuRange mu = closed_form_mu(j["linkage"]);
      EXPECT_NEAR(s["transmission_angle_min_deg"].get<double>(), mu.min, 1e-3) << task;
      EXPECT_NEAR(s["transmission_angle_max_deg"].get<double>(), mu.max, mu.max == 90 ? 0.1 : 1e-3) << task;
    } else {
      EXPECT_EQ(s["motion"], "travel") << task;
    }
    const bool warned = std::any_of(j["warnings"].begin(), j["warnings"].end(), [](const auto& w) {
      return w.template get<std::string>().find("transmission angle down to") != std::string::npos;
    });
    const bool defective = !j["defects"].empty();
    EXPECT_EQ(warned, !defective && s["transmission_angle_min_deg"].get<double>() < 40) << task;
  }
}

TEST(SynthSummary, MinTransmissionAngleOption) {
  const auto j = synth_json("crank-rocker " + example("crank_rocker.yaml") + " --min-transmission-angle 89.9");
  EXPECT_EQ(j["summary"]["min_transmission_angle_limit_deg"].get<double>(), 89.9);
  const bool warned = std::any_of(j["warnings"].begin(), j["warnings"].end(), [](const auto& w) {
    return w.template get<std::string>().find("below the 89.900 deg limit") != std::string::npos;
  });
  EXPECT_TRUE(warned) << j["warnings"];
  for (const char* bad : {"91", "-5deg", "1mm"}) {
    const auto r = run_gearkit("synth crank-rocker " + example("crank_rocker.yaml") + " --min-transmission-angle " + bad);
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("--min-transmission-angle"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
  }
}

}  // namespace
