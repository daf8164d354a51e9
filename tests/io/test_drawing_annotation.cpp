// Layout helpers of io/drawing_annotation.hpp: text boxes, their tests against texts and curves,
// first-fit placement and the frame. Expected values are hand derivations on small drawings.
#include <gearkit/io/drawing_annotation.hpp>

#include <gtest/gtest.h>

using namespace gearkit::io;

TEST(DrawingAnnotation, TextBoxIsTheEstimatedWidthFromDescenderToCapHeight) {
  // 4 characters of height 10: 4 * 0.62 * 10 = 24.8 mm wide; 2.5 mm below the baseline, 10 above.
  const Box b = text_box({"t", 1.0, 2.0, 10.0, "abcd"});
  EXPECT_DOUBLE_EQ(b.xmin, 1.0);
  EXPECT_DOUBLE_EQ(b.xmax, 25.8);
  EXPECT_DOUBLE_EQ(b.ymin, -0.5);
  EXPECT_DOUBLE_EQ(b.ymax, 12.0);
}

TEST(DrawingAnnotation, CurvesCrossingABox) {
  const Box b{0, 0, 10, 5};
  Drawing d;
  d.lines.push_back({"l", -5, 10, 20, 10});  // above the box
  EXPECT_FALSE(crossed_by_curves(d, b));
  d.lines.push_back({"l", -5, -5, 20, 12});  // a diagonal through it, both ends outside
  EXPECT_TRUE(crossed_by_curves(d, b));
  // A circle about (5, 2.5) of radius 20 encloses the box (farthest corner 5.59 away): no crossing;
  // radius 4 runs through it (nearest point 0 < 4 < 5.59).
  Drawing c;
  c.circles.push_back({"c", 5, 2.5, 20});
  EXPECT_FALSE(crossed_by_curves(c, b));
  c.circles.push_back({"c", 5, 2.5, 4});
  EXPECT_TRUE(crossed_by_curves(c, b));
  // A half circle as one bulge (b = tan(180/4) = 1) from (-10, 2.5) to (20, 2.5), counter-
  // clockwise: below the chord, centre (5, 2.5), radius 15, lowest at y = -12.5, clear of the box;
  // with bulge -1 it bulges upward and also stays 15 away from (5, 2.5) - the chord itself is not
  // drawn, so no crossing either way; an arc of radius 5 about (5, -2) reaches y = 3 inside.
  Drawing p;
  p.polylines.push_back({"p", {{-10, 2.5, 1.0}, {20, 2.5, 0.0}}, false});
  EXPECT_FALSE(crossed_by_curves(p, b));
  p.arcs.push_back({"a", 5, -2, 5, 0, 180});
  EXPECT_TRUE(crossed_by_curves(p, b));
}

TEST(DrawingAnnotation, OverlapAndCrossingReportsNameTheTexts) {
  Drawing d;
  d.texts.push_back({"t", 0, 0, 2, "aaaa"});    // x 0 .. 4.96
  d.texts.push_back({"t", 4, 0, 2, "bbbb"});    // starts inside the first
  d.texts.push_back({"t", 20, 0, 2, "cccc"});   // alone
  d.lines.push_back({"l", 21, -5, 21, 5});      // through the third
  const auto pairs = overlapping_texts(d);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0], (std::pair<std::size_t, std::size_t>{0, 1}));
  EXPECT_EQ(texts_crossed_by_curves(d), std::vector<std::size_t>{2});
}

TEST(DrawingAnnotation, OwnLeaderDoesNotCountAsCrossingItsLabel) {
  Drawing d;
  add_label(d, 0, 0, 10, 10, "R = 5", 2.5, "l");
  EXPECT_TRUE(texts_crossed_by_curves(d).empty());
  EXPECT_TRUE(fits(Drawing{}, d));
}

TEST(DrawingAnnotation, PlaceFirstFittingSkipsCandidatesThatCollide) {
  Drawing d;
  d.texts.push_back({"t", 0, 0, 2, "taken"});
  d.lines.push_back({"l", 50, -10, 50, 10});
  Drawing on_text, on_line, free;
  on_text.texts.push_back({"t", 1, 0, 2, "x"});
  on_line.texts.push_back({"t", 49.5, 0, 2, "y"});
  free.texts.push_back({"t", 100, 0, 2, "z"});
  EXPECT_EQ(place_first_fitting(d, {on_text, on_line, free}), 2u);
  EXPECT_EQ(d.texts.back().text, "z");
  Drawing crowded = d;  // nothing fits: the first candidate is used
  EXPECT_EQ(place_first_fitting(crowded, {on_text, on_line}), 0u);
  EXPECT_EQ(crowded.texts.back().text, "x");
}

TEST(DrawingAnnotation, FrameEnclosesEverythingWithTheMargin) {
  Drawing d;
  d.circles.push_back({"c", 0, 0, 10});
  d.texts.push_back({"t", 20, 0, 2, "abc"});  // box x 20 .. 23.72, y -0.5 .. 2
  add_frame(d, 3, "frame");
  ASSERT_EQ(d.polylines.size(), 1u);
  const auto& v = d.polylines[0].vertices;
  EXPECT_DOUBLE_EQ(v[0].x, -13.0);
  EXPECT_DOUBLE_EQ(v[0].y, -13.0);
  EXPECT_NEAR(v[2].x, 23.72 + 3.0, 1e-12);
  EXPECT_DOUBLE_EQ(v[2].y, 13.0);
  EXPECT_TRUE(d.polylines[0].closed);
}
