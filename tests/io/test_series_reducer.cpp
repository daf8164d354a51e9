// Tests for gearkit/io/series_reducer.hpp: a plot of any number of samples in constant memory
// keeps what a plot of that width can show.
#include <gearkit/io/series_reducer.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace gearkit::io;

TEST(SeriesReducer, ShortSeriesAreKeptWhole) {
  SeriesReducer r(0, 10, 100, 11);
  for (int i = 0; i <= 10; ++i) r.add(i, i * i);
  const Series s = r.series("y");
  ASSERT_EQ(s.x.size(), 11u);
  EXPECT_EQ(s.y[7], 49);
}

// A million samples of sin(x) with a spike: at most four points per column survive, every
// column's extremes among them, and the spike too.
TEST(SeriesReducer, LongSeriesKeepEachColumnsExtremes) {
  const long n = 1'000'000;
  const int columns = 500;
  SeriesReducer r(0, 2 * M_PI, columns, n);
  std::vector<double> low(columns, INFINITY), high(columns, -INFINITY);
  for (long i = 0; i < n; ++i) {
    const double x = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n - 1);
    const double y = i == 123456 ? 5.0 : std::sin(x);
    r.add(x, y);
    const int c = std::min(columns - 1, static_cast<int>(x / (2 * M_PI) * columns));
    low[c] = std::min(low[c], y);
    high[c] = std::max(high[c], y);
  }
  const Series s = r.series("sin");
  EXPECT_LE(s.x.size(), 4u * columns);
  EXPECT_TRUE(std::is_sorted(s.x.begin(), s.x.end()));
  EXPECT_EQ(*std::max_element(s.y.begin(), s.y.end()), 5.0);
  for (int c = 0; c < columns; ++c) {
    bool has_low = false, has_high = false;
    for (std::size_t k = 0; k < s.x.size(); ++k) {
      const int kc = std::min(columns - 1, static_cast<int>(s.x[k] / (2 * M_PI) * columns));
      if (kc != c) continue;
      has_low = has_low || s.y[k] == low[c];
      has_high = has_high || s.y[k] == high[c];
    }
    EXPECT_TRUE(has_low && has_high) << "column " << c;
  }
}

TEST(SeriesReducer, NonFiniteValuesBreakTheLine) {
  SeriesReducer r(0, 100, 10, 1000);
  for (int i = 0; i < 1000; ++i) r.add(i * 0.1, i == 500 ? NAN : 1.0);
  const Series s = r.series("y");
  EXPECT_EQ(std::count_if(s.y.begin(), s.y.end(), [](double y) { return std::isnan(y); }), 1);
}
