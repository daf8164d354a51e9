// Tests for gearkit/mechanism/sweep_start.hpp: the sweep's options and the way from the drawing to
// the sweep's start, which must keep the drawing's assembly branch.
#include <gearkit/io/yaml_model.hpp>
#include <gearkit/mechanism/reader.hpp>
#include <gearkit/mechanism/sweep_start.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace gearkit::mechanism {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// The crank-rocker of examples/mechanisms/four_bar.yaml (O2A 40, AB 120, O4B 80, O2O4 100 mm),
// drawn with the rocker at `rocker_deg`: 75 deg draws B above the line A-O4, -75 deg below it.
Mechanism four_bar(double rocker_deg) {
  const std::string text =
      "ground: {O2: [0, 0], O4: [100, 0]}\n"
      "links:\n"
      "  crank: {points: {O2: [0, 0], A: [40, 0]}, angle: 40 deg}\n"
      "  coupler: {points: {A: [0, 0], B: [120, 0]}, angle: " + std::to_string(rocker_deg > 0 ? 20 : -20) + " deg}\n"
      "  rocker: {points: {O4: [0, 0], B: [80, 0]}, angle: " + std::to_string(rocker_deg) + " deg}\n"
      "joints:\n"
      "  - {type: revolute, at: [crank.O2, ground.O2]}\n"
      "  - {type: revolute, at: [crank.A, coupler.A]}\n"
      "  - {type: revolute, at: [coupler.B, rocker.B]}\n"
      "  - {type: revolute, at: [rocker.O4, ground.O4]}\n"
      "drivers:\n"
      "  - {name: theta2, type: angle, link: crank}\n";
  return read_mechanism(io::load_yaml_text(text, "four_bar.yaml"), nullptr);
}

// The rocker angle by hand: B where the circle of 120 mm about A = 40 (cos, sin theta2) meets the
// circle of 80 mm about O4 = (100, 0), left of the line from A to O4 (above it) for `above` = +1.
double rocker_angle(double theta2, double above) {
  const double ax = 40 * std::cos(theta2), ay = 40 * std::sin(theta2);
  const double ex = 100 - ax, ey = -ay, f = std::hypot(ex, ey);
  const double along = (120.0 * 120.0 - 80.0 * 80.0 + f * f) / (2 * f), h = above * std::sqrt(120.0 * 120.0 - along * along);
  const double bx = ax + (along * ex - h * ey) / f, by = ay + (along * ey + h * ex) / f;  // h > 0: left of A->O4
  return std::atan2(by, bx - 100);
}

TEST(SweepStart, OptionsLocateDeadPointsToABillionthOfTheSpan) {
  const kin::SweepOptions o = sweep_options(0, 0.0, 2 * std::numbers::pi, 0.01, true, false);
  EXPECT_DOUBLE_EQ(o.min_step, 2e-9 * std::numbers::pi);
  EXPECT_DOUBLE_EQ(sweep_options(0, 0.0, 0.5, 0.01, false, true).min_step, 1e-9);  // at least 1e-9 of a unit
  EXPECT_TRUE(sweep_options(0, 0.0, 0.5, 0.01, false, true).switch_branch);
  EXPECT_FALSE(sweep_options(0, 0.0, 0.5, 0.01, false, true).velocities);
}

TEST(SweepStart, ReachesTheStartOnTheDrawingsBranch) {
  for (const double above : {1.0, -1.0}) {
    const Mechanism m = four_bar(75.0 * above);
    kin::Data data(m.model);
    const kin::SweepOptions o = sweep_options(0, 200 * kDeg, 300 * kDeg, kDeg, true, false);
    approach_start(m, data, 0, o);
    const double near = 200 * kDeg + 2 * kin::change_point_offset(o);
    EXPECT_NEAR(data.inputs(0), near, 1e-15);
    const int rocker = *m.model.body_index("rocker");
    const double theta4 = data.q(3 * rocker + 2), expected = rocker_angle(near, above);
    // data.q is the approach's last sample, up to one 2 deg step short of `near` (the sweep's first
    // Newton solve starts from it), so it is on the branch but not exactly at the start: within
    // 0.05 rad of the hand value there (2 deg of crank times a rocker ratio below 1.5), where the
    // other branch is over 2 rad away.
    EXPECT_NEAR(std::remainder(theta4 - expected, 2 * std::numbers::pi), 0.0, 0.05) << "above " << above;
    EXPECT_GT(std::abs(std::remainder(theta4 - rocker_angle(near, -above), 2 * std::numbers::pi)), 1.0) << "above " << above;
  }
}

TEST(SweepStart, RefusesADriverItDoesNotHave) {
  const Mechanism m = four_bar(75.0);
  kin::Data data(m.model);
  EXPECT_THROW(approach_start(m, data, 1, sweep_options(1, 0.0, 1.0, 0.1, true, false)), std::invalid_argument);
}

}  // namespace
}  // namespace gearkit::mechanism
