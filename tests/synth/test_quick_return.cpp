// libsynth quick_return.hpp: crank-rockers for a rocker swing and a time ratio (Norton, Design of
// Machinery, ch. 3), checked by driving the written mechanism through a full turn in the solver.
#include "synth_test_support.hpp"

#include <gearkit/synth/mechanism_writer.hpp>
#include <gearkit/synth/quick_return.hpp>

#include <gtest/gtest.h>

using namespace gearkit::synth;
using namespace gearkit::synth::testing;

namespace {

// The rocker's swing and the crank angles of its two limit positions, from a full solver sweep.
struct Measured {
  double swing = 0, crank_min = 0, crank_max = 0;
};

Measured sweep_rocker(const QuickReturnResult& r) {
  const auto yaml = to_mechanism_yaml(four_bar_sketch(r.linkage, r.theta2_extended, 2 * pi, 1, "q"));
  Driven d = Driven::from_text(yaml);
  Measured m{0, 0, 0};
  double lo = 1e9, hi = -1e9;
  for (int k = 0; k <= 7200; ++k) {
    const double t = r.theta2_extended + 2 * pi * k / 7200;
    EXPECT_TRUE(d.drive_to(t));
    const double t4 = d.output("theta4");
    if (t4 < lo) { lo = t4; m.crank_min = t; }
    if (t4 > hi) { hi = t4; m.crank_max = t; }
  }
  m.swing = hi - lo;
  return m;
}

}  // namespace

TEST(QuickReturn, NortonQuickReturnFortyFiveDegreesTimeRatioOnePointTwoFive) {
  // Norton's quick-return crank-rocker: 45 deg of rocker motion, time ratio 1:1.25, so
  // delta = 180 (1.25 - 1)/(1.25 + 1) = 20 deg and the strokes take 200 and 160 deg of crank.
  QuickReturnTask t;
  t.swing = 45 * deg;
  t.time_ratio = 1.25;
  t.rocker = 0.1;
  const QuickReturnResult r = synthesize_quick_return(t);
  EXPECT_NEAR(r.delta, 20 * deg, 1e-12);
  EXPECT_NEAR(std::max(r.ccw_stroke, 2 * pi - r.ccw_stroke), 200 * deg, 1e-9);
  EXPECT_TRUE(crank_turns_fully(r.linkage));
  const Measured m = sweep_rocker(r);
  EXPECT_NEAR(m.swing, 45 * deg, 1e-6);
  const double one = wrap_two_pi(m.crank_max - m.crank_min), other = 2 * pi - one;
  EXPECT_NEAR(std::max(one, other) / std::min(one, other), 1.25, 2e-3);  // 0.05 deg sampling
}

TEST(QuickReturn, EqualTimesPutO2OnTheLineB1B2) {
  // Norton Ex. 3-1 (rocker output, equal times): O2 on the extension of B1 B2, so the crank is
  // half the chord, a = c sin(psi/2), whatever the ground length.
  QuickReturnTask t;
  t.swing = 45 * deg;
  t.time_ratio = 1;
  t.rocker = 0.1;
  t.ground = 0.15;
  const QuickReturnResult r = synthesize_quick_return(t);
  EXPECT_NEAR(r.linkage.crank, 0.1 * std::sin(22.5 * deg), 1e-12);
  EXPECT_NEAR(r.linkage.ground(), 0.15, 1e-12);
  EXPECT_NEAR(r.ccw_stroke, pi, 1e-9);
  EXPECT_NEAR(sweep_rocker(r).swing, 45 * deg, 1e-6);
}

TEST(QuickReturn, BadTasksAreRejected) {
  QuickReturnTask t;
  t.swing = 200 * deg;
  EXPECT_THROW(synthesize_quick_return(t), std::invalid_argument);
  t.swing = 45 * deg;
  t.time_ratio = 0.5;
  EXPECT_THROW(synthesize_quick_return(t), std::invalid_argument);
  t.time_ratio = 1.25;
  t.ground = 0.001;  // O2 cannot be 1 mm from O4 on the locus
  EXPECT_THROW(synthesize_quick_return(t), NoSolution);
}
