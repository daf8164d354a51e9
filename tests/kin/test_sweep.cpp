// Sweeps: branch continuity, limit positions of outputs, dead points.
#include <gearkit/kin/sweep.hpp>

#include <gtest/gtest.h>

#include "mechanisms.hpp"

namespace gearkit::kin {
namespace {

using testing::kDeg;

Output slider_s(const Model& m) {
  Output s;
  s.name = "s";
  s.kind = OutputKind::slider_displacement;
  s.constraint = *m.constraint_index("guide");
  return s;
}

// Seed 004, exam 2020-21 exercise 1 (pantograph): the dead point of maximum s is at
// phi1 = -60 deg, phi2 = 60 deg with s_max = sqrt((l1 + l3)^2 - d^2) = 346.4 mm, and there
// phi2'/phi1' = l1/l3 = 0.6. The seed's phi2 is measured clockwise (Q = P + l3 (cos phi2,
// -sin phi2)) and our coupler's x axis runs from Q to P, so phi2 = 180 deg - theta_coupler.
TEST(Sweep, PantographMaximumOfS) {
  Model m = testing::pantograph(-80 * kDeg);
  Data data(m);
  SweepOptions o;
  o.start = -80 * kDeg;
  o.end = -40 * kDeg;
  o.step = 1 * kDeg;
  o.outputs = {slider_s(m)};
  const SweepResult r = sweep(m, data, o);
  ASSERT_TRUE(r.complete) << r.message;
  EXPECT_EQ(r.samples.size(), 41u);
  ASSERT_EQ(r.extremes.size(), 1u);
  const OutputExtreme& e = r.extremes[0];
  EXPECT_TRUE(e.maximum);
  EXPECT_NEAR(e.input / kDeg, -60.0, 1e-6);
  EXPECT_NEAR(e.value * 1000, 346.4, 0.05);
  EXPECT_NEAR(e.value, std::sqrt(0.4 * 0.4 - 0.2 * 0.2), 1e-9);
  EXPECT_NEAR(180.0 - e.q(5) / kDeg, 60.0, 1e-5);  // phi2
  EXPECT_NEAR(-e.dq(5) / e.dq(2), 0.6, 1e-6);       // phi2'/phi1'
}

// Driving the same pantograph by the slider: s cannot exceed s_max. The sweep stops there,
// reports the dead point located to min_step, and never jumps to another branch.
TEST(Sweep, PantographDrivenBySliderStopsAtTheDeadPoint) {
  Model m = testing::pantograph(-75 * kDeg, true, 0.30);
  Data data(m);
  SweepOptions o;
  o.start = 0.30;
  o.end = 0.36;
  o.step = 0.002;
  o.min_step = 1e-9;
  const SweepResult r = sweep(m, data, o);
  EXPECT_TRUE(r.assembled);
  EXPECT_FALSE(r.complete);
  ASSERT_EQ(r.dead_points.size(), 1u);
  EXPECT_NEAR(r.dead_points[0].input, std::sqrt(0.4 * 0.4 - 0.2 * 0.2), 1e-6);
  EXPECT_NEAR(r.dead_points[0].q(2) / kDeg, -60.0, 0.5);  // near the toggle
  for (std::size_t k = 1; k < r.samples.size(); ++k) {
    EXPECT_GT(r.samples[k].input, r.samples[k - 1].input);
    EXPECT_LT(std::abs(r.samples[k].q(2) - r.samples[k - 1].q(2)), 0.2);  // continuous branch
  }
}

// A Grashof crank-rocker turns fully: 360 samples, no dead point, and the branch is the drawn
// one all the way round (the rocker angle comes back to its start).
TEST(Sweep, CrankRockerFullTurnKeepsItsBranch) {
  const testing::FourBarDims f{0.040, 0.120, 0.080, 0.100};
  Model m = testing::four_bar(f, 0.0);
  Data data(m);
  SweepOptions o;
  o.start = 0.0;
  o.end = 2 * M_PI;
  o.step = 1 * kDeg;
  const SweepResult r = sweep(m, data, o);
  ASSERT_TRUE(r.complete) << r.message;
  ASSERT_EQ(r.samples.size(), 361u);
  EXPECT_NEAR(r.samples.front().q(8), r.samples.back().q(8), 1e-9);
  for (const SweepSample& s : r.samples) {
    const auto [theta3, theta4] = testing::four_bar_closed_form(f, s.input);
    EXPECT_NEAR(std::remainder(s.q(8) - theta4, 2 * M_PI), 0.0, 1e-8);
    EXPECT_NEAR(std::remainder(s.q(5) - theta3, 2 * M_PI), 0.0, 1e-8);
  }
}

// A triple rocker driven on its input link reaches a toggle; the sweep must stop there.
TEST(Sweep, TripleRockerStopsAtToggle) {
  const testing::FourBarDims f{0.080, 0.090, 0.100, 0.120};  // s + l = 0.2 > p + q = 0.19
  Model m = testing::four_bar(f, 60 * kDeg);
  Data data(m);
  SweepOptions o;
  o.start = 60 * kDeg;
  o.end = 180 * kDeg;
  o.step = 2 * kDeg;
  const SweepResult r = sweep(m, data, o);
  EXPECT_FALSE(r.complete);
  ASSERT_EQ(r.dead_points.size(), 1u);
  // Toggle where coupler and rocker are aligned: |A O4| = b + c.
  const double a = f.a, d = f.d, bc = f.b + f.c;
  const double theta_toggle = std::acos((a * a + d * d - bc * bc) / (2 * a * d));
  EXPECT_NEAR(r.dead_points[0].input, theta_toggle, 1e-6);
}

TEST(Sweep, RejectsBadOptions) {
  Model m = testing::four_bar({0.04, 0.12, 0.08, 0.1}, 0.0);
  Data data(m);
  SweepOptions o;
  o.end = 1.0;
  o.step = 0.0;
  EXPECT_THROW(sweep(m, data, o), std::invalid_argument);
  o.step = 0.1;
  o.driver = 3;
  EXPECT_THROW(sweep(m, data, o), std::invalid_argument);
}

// A fine sweep (0.1 deg, the benchmark's) against the closed form: positions, and velocities
// and accelerations against central differences of the closed form in the input (unit input
// speed, so d/dt = d/d theta2). Most samples converge from the predictor alone; none may lose
// accuracy for it.
TEST(Sweep, FineSweepMatchesTheClosedFormAndItsDerivatives) {
  const testing::FourBarDims f{0.040, 0.120, 0.080, 0.100};
  Model m = testing::four_bar(f, 0.0);
  Data data(m);
  SweepOptions o;
  o.start = 0.0;
  o.step = 0.1 * kDeg;
  o.end = 359.9 * kDeg;
  o.solver.tolerance = 1e-11;
  const SweepResult r = sweep(m, data, o);
  ASSERT_TRUE(r.complete) << r.message;
  ASSERT_EQ(r.samples.size(), 3600u);
  const double e = 1e-4;
  for (std::size_t k = 0; k < r.samples.size(); k += 7) {
    const SweepSample& s = r.samples[k];
    const auto [t3, t4] = testing::four_bar_closed_form(f, s.input);
    const auto [t3p, t4p] = testing::four_bar_closed_form(f, s.input + e);
    const auto [t3m, t4m] = testing::four_bar_closed_form(f, s.input - e);
    EXPECT_NEAR(std::remainder(s.q(5) - t3, 2 * M_PI), 0.0, 1e-9) << k;
    EXPECT_NEAR(std::remainder(s.q(8) - t4, 2 * M_PI), 0.0, 1e-9) << k;
    const auto d1 = [&](double p, double mi) { return std::remainder(p - mi, 2 * M_PI) / (2 * e); };
    const auto d2 = [&](double p, double c, double mi) {
      return (std::remainder(p - c, 2 * M_PI) - std::remainder(c - mi, 2 * M_PI)) / (e * e);
    };
    EXPECT_NEAR(s.qd(5), d1(t3p, t3m), 1e-7) << k;
    EXPECT_NEAR(s.qd(8), d1(t4p, t4m), 1e-7) << k;
    EXPECT_NEAR(s.qdd(5), d2(t3p, t3, t3m), 1e-5) << k;
    EXPECT_NEAR(s.qdd(8), d2(t4p, t4, t4m), 1e-5) << k;
  }
}

// A chain of 200 four-bars (1203 coordinates, the sparse path): every loop's rocker angle
// follows from the previous one by the closed form, at every sample of the sweep.
TEST(Sweep, ChainOfFourBarsFollowsTheClosedFormLoopByLoop) {
  const testing::FourBarDims f{0.040, 0.120, 0.080, 0.100};
  const int loops = 200;
  Model m = testing::four_bar_chain(f, loops);
  Data data(m);
  ASSERT_TRUE(data.sparse);
  SweepOptions o;
  o.start = 0.0;
  o.step = 2 * kDeg;
  o.end = 30 * kDeg;
  const SweepResult r = sweep(m, data, o);
  ASSERT_TRUE(r.complete) << r.message;
  ASSERT_EQ(r.samples.size(), 16u);
  for (const SweepSample& s : r.samples) {
    double crank = s.input;
    for (int k = 0; k < loops; ++k) {
      const auto [theta3, theta4] = testing::four_bar_closed_form(f, crank);
      // Bodies: crank 0, then coupler 1 + 2k and rocker 2 + 2k.
      ASSERT_NEAR(std::remainder(s.q(3 * (1 + 2 * k) + 2) - theta3, 2 * M_PI), 0.0, 1e-8) << "loop " << k;
      ASSERT_NEAR(std::remainder(s.q(3 * (2 + 2 * k) + 2) - theta4, 2 * M_PI), 0.0, 1e-8) << "loop " << k;
      crank = theta4;
    }
  }
}

// Sweeping into a kept result overwrites it exactly: a longer sweep, then a shorter one that
// stops at a dead point, give the same samples as fresh sweeps.
TEST(Sweep, IntoAKeptResultEqualsAFreshSweep) {
  const testing::FourBarDims crank_rocker{0.040, 0.120, 0.080, 0.100}, triple{0.080, 0.090, 0.100, 0.120};
  Model m1 = testing::four_bar(crank_rocker, 0.0), m2 = testing::four_bar(triple, 60 * kDeg);
  SweepOptions o1, o2;
  o1.end = 90 * kDeg;
  o1.step = 1 * kDeg;
  o2.start = 60 * kDeg;
  o2.end = 180 * kDeg;
  o2.step = 2 * kDeg;
  SweepResult kept;
  for (int pass = 0; pass < 2; ++pass) {
    const Model& m = pass == 0 ? m1 : m2;
    const SweepOptions& o = pass == 0 ? o1 : o2;
    Data fresh_data(m), kept_data(m);
    const SweepResult fresh = sweep(m, fresh_data, o);
    sweep(m, kept_data, o, kept);
    ASSERT_EQ(kept.samples.size(), fresh.samples.size()) << pass;
    EXPECT_EQ(kept.complete, fresh.complete);
    EXPECT_EQ(kept.dead_points.size(), fresh.dead_points.size());
    EXPECT_EQ(kept.message, fresh.message);
    for (std::size_t k = 0; k < fresh.samples.size(); ++k) {
      EXPECT_EQ(kept.samples[k].input, fresh.samples[k].input);
      EXPECT_EQ(kept.samples[k].q, fresh.samples[k].q);
      EXPECT_EQ(kept.samples[k].qd, fresh.samples[k].qd);
      EXPECT_EQ(kept.samples[k].qdd, fresh.samples[k].qdd);
    }
  }
  EXPECT_FALSE(kept.complete);  // the triple rocker stops at its toggle
}

}  // namespace
}  // namespace gearkit::kin
