#include <gearkit/io/series_reducer.hpp>

#include <algorithm>
#include <cmath>

namespace gearkit::io {

SeriesReducer::SeriesReducer(double x_first, double x_last, int columns, long expected_samples)
    : x_min_(std::min(x_first, x_last)), x_max_(std::max(x_first, x_last)),
      keep_all_(expected_samples <= 4L * columns || !(x_max_ > x_min_)) {
  if (!keep_all_) columns_.resize(static_cast<std::size_t>(std::max(columns, 1)));
}

int SeriesReducer::column_of(double x) const {
  const double t = (x - x_min_) / (x_max_ - x_min_);
  const int n = static_cast<int>(columns_.size());
  return std::clamp(static_cast<int>(std::floor(t * n)), 0, n - 1);
}

void SeriesReducer::add(double x, double y) {
  if (keep_all_) {
    all_.push_back({x, y});
    return;
  }
  if (!std::isfinite(x)) return;
  Column& c = columns_[static_cast<std::size_t>(column_of(x))];
  if (!std::isfinite(y)) {
    c.gap = true;
    c.gap_x = x;
    return;
  }
  const Point p{x, y};
  if (!c.used) {
    c.used = true;
    c.first = c.low = c.high = c.last = p;
    return;
  }
  if (y < c.low.y) c.low = p;
  if (y > c.high.y) c.high = p;
  c.last = p;
}

Series SeriesReducer::series(std::string name) const {
  Series s;
  s.name = std::move(name);
  std::vector<Point> points;
  if (keep_all_) {
    points = all_;
  } else {
    for (const Column& c : columns_) {
      std::vector<Point> kept;
      if (c.used) kept = {c.first, c.low, c.high, c.last};
      if (c.gap) kept.push_back({c.gap_x, NAN});
      std::sort(kept.begin(), kept.end(), [](const Point& a, const Point& b) { return a.x < b.x; });
      for (const Point& p : kept)
        if (points.empty() || p.x != points.back().x || (std::isnan(p.y) != std::isnan(points.back().y))) points.push_back(p);
    }
  }
  for (const Point& p : points) {
    s.x.push_back(p.x);
    s.y.push_back(p.y);
  }
  return s;
}

}  // namespace gearkit::io
