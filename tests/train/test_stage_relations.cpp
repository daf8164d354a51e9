// Tests for gearkit/train/stage_relations.hpp: Willis' equation per stage in the members the
// exam names, against seed 004 (004_b4a8ce5a956e12a3.txt).
#include "train_fixtures.hpp"

#include <gearkit/train/stage_relations.hpp>

#include <gtest/gtest.h>

namespace gearkit::train {
namespace {

using namespace testing;

MemberId id(const TrainModel& m, const std::string& name) { return *m.find_member(name); }

// Exam A, exercise 2 b): tau_2 = (w5 - wb)/(w3 - wb) = -z3 z4/(z4 z5) = -1/3, so
// tau_2 w3 + (1 - tau_2) wb - w5 = 0; a) tau_1 = -35/90 on fixed axes. (Wheel 3 is member 23.)
TEST(StageRelations, CvtTrainAsTheExamWritesIt) {
  const TrainModel m = make_train_model(seed_cvt_train());
  const auto r = stage_relations(m, {id(m, "1"), id(m, "23"), id(m, "5"), id(m, "b")});
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0].input, id(m, "1"));
  EXPECT_EQ(r[0].output, id(m, "23"));
  EXPECT_EQ(r[0].arm, ground);
  EXPECT_EQ(r[0].tau, Rational(-7, 18));  // -35/90
  EXPECT_EQ(stage_relation_text(m, r[0]), "-7/18 w_1 - w_23 = 0");
  EXPECT_EQ(r[1].input, id(m, "23"));
  EXPECT_EQ(r[1].output, id(m, "5"));
  EXPECT_EQ(r[1].arm, id(m, "b"));
  EXPECT_EQ(r[1].tau, Rational(-1, 3));
  EXPECT_EQ(stage_relation_text(m, r[1]), "-1/3 w_23 + 4/3 w_b - w_5 = 0");
  // Without member 1 in the vector the fixed-axis pair reads from 23: tau = -90/35.
  const auto s = stage_relations(m, {id(m, "23"), id(m, "5"), id(m, "b")});
  EXPECT_EQ(s[0].input, id(m, "23"));
  EXPECT_EQ(s[0].tau, Rational(-18, 7));
}

// Exam C, exercise 1 a), u = {w1, wb, w45, w7}: [1] tau_1 w1 + (1 - tau_1) wb - w45 = 0 with
// tau_1 = -2/5; [2] tau_2 w45 + (1 - tau_2) wb - w7 = 0 with tau_2 = -7/2.
TEST(StageRelations, TwoEpicyclicStagesInTheUsersVector) {
  const TrainModel m = make_train_model(seed_two_epicyclic_stages());
  const auto r = stage_relations(m, {id(m, "1"), id(m, "b"), id(m, "45"), id(m, "7")});
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0].tau, Rational(-2, 5));
  EXPECT_EQ(stage_relation_text(m, r[0]), "-2/5 w_1 + 7/5 w_b - w_45 = 0");
  EXPECT_EQ(r[1].tau, Rational(-7, 2));
  EXPECT_EQ(stage_relation_text(m, r[1]), "-7/2 w_45 + 9/2 w_b - w_7 = 0");
  // The order of the vector picks the input: with w7 first the second stage reads the other way.
  const auto rev = stage_relations(m, {id(m, "7"), id(m, "45"), id(m, "b"), id(m, "1")});
  EXPECT_EQ(rev[1].input, id(m, "7"));
  EXPECT_EQ(rev[1].tau, Rational(-2, 7));
}

}  // namespace
}  // namespace gearkit::train
