#pragma once
// Plots of long sweeps in constant memory: a plot a thousand pixels wide cannot show more than
// a few points per pixel column, so each series keeps, per column of x, the points that shape
// what is drawn there (first, lowest, highest, last), whatever the number of samples.
#include <gearkit/io/plot.hpp>

#include <string>
#include <vector>

namespace gearkit::io {

class SeriesReducer {
 public:
  /// @param x_first, x_last the range of x the samples will cover (either order).
  /// @param columns intervals of x kept apart (about the plot's width in pixels).
  /// @param expected_samples when it is at most 4 * columns every sample is kept as it is.
  SeriesReducer(double x_first, double x_last, int columns, long expected_samples);

  /// Adds a sample; a non-finite y breaks the line there (kept as a gap).
  void add(double x, double y);

  /// The kept points in order of x (as plotted) as a Series named `name`.
  Series series(std::string name) const;

 private:
  struct Point {
    double x = 0, y = 0;
  };
  struct Column {
    bool used = false;
    Point first, low, high, last;
    bool gap = false;
    double gap_x = 0;
  };
  int column_of(double x) const;

  double x_min_, x_max_;
  bool keep_all_;
  std::vector<Point> all_;        // keep_all_: every sample
  std::vector<Column> columns_;   // otherwise: four points per column
};

}  // namespace gearkit::io
