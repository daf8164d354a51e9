#pragma once
// Extremes over a cam's turn of a quantity computed from the motion: the turn is cut at the
// program's breaks (joins, law blends, table knots), where the quantity may jump, and each
// smooth piece is searched on its own (extremum.hpp), with the one-sided values at its ends.
#include <gearkit/cam/motion_program.hpp>

#include "extremum.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace gearkit::cam::detail {

/// The cam angles [start, start + 2 pi] where the program's pieces begin and end, sorted.
inline std::vector<double> piece_bounds(const MotionProgram& program) {
  std::vector<double> bounds{program.start()};
  for (const MotionProgram::Break& b : program.breaks()) bounds.push_back(b.theta);
  std::sort(bounds.begin(), bounds.end());
  bounds.erase(std::unique(bounds.begin(), bounds.end()), bounds.end());
  return bounds;
}

/// The largest value of f(theta) over the turn, where f may be evaluated anywhere in a piece:
/// at a piece's end f sees the piece's own side (theta is moved inwards by one ulp).
/// `samples_per_turn` sets the sampling that brackets the maxima (at least 8 per piece).
template <class F>
Peak maximum_over_turn(const MotionProgram& program, F&& f, int samples_per_turn) {
  const std::vector<double> bounds = piece_bounds(program);
  const double turn = bounds.back() - bounds.front();
  Peak best;
  for (std::size_t k = 0; k + 1 < bounds.size(); ++k) {
    const double a = bounds[k], b = bounds[k + 1];
    if (b - a <= 0) continue;
    const double b_in = std::nextafter(b, a);
    auto g = [&](double t) { return f(std::min(t, b_in)); };
    const int n = std::max(8, static_cast<int>(std::ceil(samples_per_turn * (b - a) / turn)));
    const Peak p = find_maximum(g, a, b, n, 1e-12 * turn);
    if (p.value > best.value) best = {std::min(p.x, b_in), p.value};
  }
  return best;
}

}  // namespace gearkit::cam::detail
