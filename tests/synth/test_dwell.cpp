// libsynth dwell.hpp: the single-dwell six-bar built on a coupler curve's near-circular arc;
// the written six-bar is driven by the solver, and its output rocker must rest through the dwell.
#include "synth_test_support.hpp"

#include <gearkit/synth/dwell.hpp>

#include <gtest/gtest.h>

using namespace gearkit::synth;
using namespace gearkit::synth::testing;

namespace {

DwellTask task() {
  DwellTask t;  // examples/synthesis/dwell.yaml
  t.four_bar.O4 = Vec2(0.1, 0);
  t.four_bar.crank = 0.03;
  t.four_bar.coupler = 0.1;
  t.four_bar.rocker = 0.09;
  t.four_bar.coupler_point = Vec2(0.06, 0.045);
  t.dwell = 60 * deg;
  return t;
}

}  // namespace

TEST(Dwell, ArcCentreIsEquidistantFromTheCouplerPointThroughTheWindow) {
  const DwellResult r = synthesize_dwell(task());
  for (int k = 0; k <= 12; ++k) {
    const Vec2 P = pose_at(r.four_bar, r.window_start + 60 * deg * k / 12)->P;
    EXPECT_NEAR((P - r.D).norm(), r.radius, r.arc_deviation + 1e-12);
  }
  EXPECT_LT(r.arc_deviation, 0.001 * r.radius);
}

TEST(Dwell, SolverShowsTheOutputAtRestDuringTheDwell) {
  const DwellResult r = synthesize_dwell(task());
  Driven d = Driven::from_text(to_mechanism_yaml(dwell_sketch(r, "dwell")));
  double lo = 1e9, hi = -1e9, all_lo = 1e9, all_hi = -1e9;
  for (int k = 0; k <= 360; ++k) {
    const double t = r.window_start + 2 * pi * k / 360;
    ASSERT_TRUE(d.drive_to(t));
    const double a = d.output("theta6");
    EXPECT_NEAR(std::remainder(a - *output_angle(r, t), 2 * pi), 0, 1e-8);  // solver tolerance
    all_lo = std::min(all_lo, a);
    all_hi = std::max(all_hi, a);
    if (k <= 60) {
      lo = std::min(lo, a);
      hi = std::max(hi, a);
    }
  }
  EXPECT_GT(all_hi - all_lo, 20 * deg);            // the output swings ...
  EXPECT_LT(hi - lo, 0.01 * (all_hi - all_lo));    // ... and rests within 1 % during the dwell
}

TEST(Dwell, NeedsACrankThatTurnsFully) {
  DwellTask t = task();
  t.four_bar.crank = 0.095;  // no longer the shortest link: not a crank
  EXPECT_THROW(synthesize_dwell(t), NoSolution);
  t = task();
  t.dwell = 1 * deg;
  EXPECT_THROW(synthesize_dwell(t), std::invalid_argument);
}
