// libsynth mechanism_writer.hpp: the written text goes through the real `gearkit kin` reader, and
// the drawn configuration it describes already satisfies every joint (the solver's residual at
// the drawn q is at rounding level), so the solver starts on the synthesised branch.
#include "synth_test_support.hpp"

#include <gearkit/kin/dof.hpp>
#include <gearkit/synth/mechanism_writer.hpp>

#include <gtest/gtest.h>

using namespace gearkit::synth;
using namespace gearkit::synth::testing;

TEST(MechanismWriter, FourBarFileIsReadAndItsDrawingIsAssembled) {
  const FourBar f = reference_four_bar();
  const std::string yaml = to_mechanism_yaml(four_bar_sketch(f, 40 * deg, 90 * deg, 1, "reference"));
  Driven d = Driven::from_text(yaml);
  EXPECT_EQ(d.mech.title, "reference");
  EXPECT_EQ(d.mech.model.bodies().size(), 3u);
  gearkit::kin::evaluate_constraints(d.mech.model, *d.data, 0);
  EXPECT_LT(gearkit::kin::residual(*d.data), 1e-10);  // 10 significant digits in mm
  EXPECT_EQ(gearkit::kin::dof(d.mech.model, *d.data).dof, 1);
  ASSERT_TRUE(d.drive_to(40 * deg));
  const auto pose = pose_at(f, 40 * deg);
  EXPECT_NEAR(d.output("Px"), pose->P.x(), 1e-10);
  EXPECT_NEAR(d.output("Py"), pose->P.y(), 1e-10);
  ASSERT_TRUE(d.drive_to(130 * deg));
  EXPECT_NEAR(d.output("Px"), pose_at(f, 130 * deg)->P.x(), 1e-10);
  // The default sweep is the synthesised travel.
  ASSERT_TRUE(d.mech.drivers[0].range);
  EXPECT_NEAR(d.mech.drivers[0].range->start, 40 * deg, 1e-10);
  EXPECT_NEAR(d.mech.drivers[0].range->end, 130 * deg, 1e-10);
}

TEST(MechanismWriter, SliderCrankFileIsRead) {
  SliderCrank k;
  k.crank = 0.05;
  k.rod = 0.2;
  k.offset = 0.02;
  Driven d = Driven::from_text(to_mechanism_yaml(slider_crank_sketch(k, 10 * deg, 300 * deg, -1, "slider")));
  for (double t : {10.0, -50.0, -200.0}) {
    ASSERT_TRUE(d.drive_to(t * deg));
    EXPECT_NEAR(d.output("s"), *slider_position(k, t * deg), 1e-10) << t;
  }
}

TEST(MechanismWriter, CommentsAndBadSketches) {
  MechanismSketch s = four_bar_sketch(reference_four_bar(), 0, pi, 1, "t");
  s.comments = {"first line", "second line"};
  const std::string yaml = to_mechanism_yaml(s);
  EXPECT_EQ(yaml.rfind("# first line\n# second line\n", 0), 0u);
  s.links[0].angle = std::nan("");
  EXPECT_THROW(to_mechanism_yaml(s), std::invalid_argument);
  s = four_bar_sketch(reference_four_bar(), 0, pi, 1, "t");
  s.links[0].name = "two words";
  EXPECT_THROW(to_mechanism_yaml(s), std::invalid_argument);
  FourBar apart = reference_four_bar();
  apart.O4 = Vec2(1, 0);  // the loop cannot close
  EXPECT_THROW(four_bar_sketch(apart, 0, pi, 1, "x"), std::invalid_argument);
}
