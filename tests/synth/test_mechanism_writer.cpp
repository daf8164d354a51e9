// libsynth mechanism_writer.hpp: the written text goes through the real `gearkit kin` reader, and
// the drawn configuration it describes already satisfies every joint (the solver's residual at
// the drawn q is at rounding level), so the solver starts on the synthesised branch.
#include "synth_test_support.hpp"

#include <gearkit/kin/dof.hpp>
#include <gearkit/synth/mechanism_writer.hpp>

#include <gtest/gtest.h>

#include <string>
#include <vector>

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

// Issue 25: the title was written unquoted, so "Crank-rocker: 45 deg swing" (a ':' and a space)
// made the file unreadable. Every title and comment a task file can hold comes back as written,
// and the file still describes the same linkage: the coupler point and the slider position at
// the drawn crank angle from the solver equal the closed-form positions (pose_at, slider_position).
TEST(MechanismWriter, HostileTitlesAndCommentsReadBack) {
  const std::vector<std::string> titles = {"Crank-rocker: 45 deg swing, time ratio 1.3",
                                           "ratio # not a comment",
                                           "\"quoted\" and 'single'",
                                           "two\nlines",
                                           "Kurbelschwinge – Ü",
                                           "- [not, a list]: {nor: a map} & *alias !tag %x @y `z`",
                                           "null",
                                           "123",
                                           " padded "};
  const FourBar f = reference_four_bar();
  SliderCrank k;
  k.crank = 0.05;
  k.rod = 0.2;
  k.offset = 0.02;
  for (const std::string& title : titles) {
    MechanismSketch four = four_bar_sketch(f, 40 * deg, 90 * deg, 1, title);
    four.comments = {title, "from: a task # with a hash"};
    const std::string yaml = to_mechanism_yaml(four);
    Driven d = Driven::from_text(yaml);
    EXPECT_EQ(d.mech.title, title) << yaml;
    EXPECT_EQ(d.mech.model.bodies().size(), 3u) << title;
    ASSERT_TRUE(d.mech.drivers[0].range) << title;
    EXPECT_NEAR(d.mech.drivers[0].range->end, 130 * deg, 1e-10) << title;
    ASSERT_TRUE(d.drive_to(40 * deg)) << title;
    EXPECT_NEAR(d.output("Px"), pose_at(f, 40 * deg)->P.x(), 1e-10) << title;
    EXPECT_NEAR(d.output("Py"), pose_at(f, 40 * deg)->P.y(), 1e-10) << title;
    Driven s = Driven::from_text(to_mechanism_yaml(slider_crank_sketch(k, 10 * deg, 300 * deg, -1, title)));
    EXPECT_EQ(s.mech.title, title);
    ASSERT_TRUE(s.drive_to(10 * deg)) << title;
    EXPECT_NEAR(s.output("s"), *slider_position(k, 10 * deg), 1e-10) << title;
  }
}

// The emitter changes quoting only: a plain title keeps the layout a person would type (block
// maps, flow lists for coordinates and entries), as the files shipped before it.
TEST(MechanismWriter, LayoutOfAPlainFile) {
  MechanismSketch s = four_bar_sketch(reference_four_bar(), 0, pi, 1, "plain title");
  s.comments = {"made by a test"};
  const std::string yaml = to_mechanism_yaml(s);
  EXPECT_EQ(yaml.rfind("# made by a test\nmechanism: plain title\nground:\n  O2: [0, 0]\n  O4: [100, 0]\nlinks:\n  crank:\n"
                       "    points: {O2: [0, 0], A: [40, 0]}\n    angle: 0 deg\n    position: [0, 0]\n",
                       0),
            0u)
      << yaml;
  EXPECT_NE(yaml.find("\njoints:\n  - {name: O2, type: revolute, at: [crank.O2, ground.O2]}\n"), std::string::npos) << yaml;
  EXPECT_NE(yaml.find("\ndrivers:\n  - {name: theta2, type: angle, link: crank, range: [0 deg, 180 deg, 1 deg]}\n"),
            std::string::npos)
      << yaml;
  EXPECT_NE(yaml.find("\noutputs:\n  - {name: theta3, type: angle, link: coupler}\n"), std::string::npos) << yaml;
  EXPECT_EQ(yaml.back(), '\n');
  EXPECT_EQ(to_mechanism_yaml(four_bar_sketch(reference_four_bar(), 0, pi, 1, "a: b")).find("mechanism: \"a: b\"\n"),
            0u);
}
