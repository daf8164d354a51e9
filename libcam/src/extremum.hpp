#pragma once
// Largest value of a piecewise smooth function on an interval, found rather than sampled: the
// function is sampled to bracket its local maxima, and every bracket is then narrowed by
// golden-section search until the abscissa is known to `x_tolerance`. Used wherever gearkit states
// a bound (the arc fit's tolerance, the smallest base circle, the jump speed): a sampled maximum
// is always an underestimate, and by a margin nobody controls.
#include <algorithm>
#include <cmath>
#include <limits>

namespace gearkit::cam::detail {

struct Peak {
  double x = 0;
  double value = -std::numeric_limits<double>::infinity();
};

/// Narrows the bracket [a, b] around a local maximum of f (f(mid) >= f(a), f(b) assumed) by
/// golden-section search; returns the best point seen.
template <class F>
Peak golden_maximum(F&& f, double a, double b, double x_tolerance, Peak best) {
  constexpr double r = 0.6180339887498949;  // (sqrt(5) - 1) / 2
  double x1 = b - r * (b - a), x2 = a + r * (b - a);
  double f1 = f(x1), f2 = f(x2);
  for (int i = 0; i < 200 && b - a > x_tolerance; ++i) {
    if (f1 >= f2) {
      b = x2, x2 = x1, f2 = f1;
      x1 = b - r * (b - a), f1 = f(x1);
    } else {
      a = x1, x1 = x2, f1 = f2;
      x2 = a + r * (b - a), f2 = f(x2);
    }
  }
  if (f1 > best.value) best = {x1, f1};
  if (f2 > best.value) best = {x2, f2};
  return best;
}

/// The largest value of f on [a, b] (both ends included) and where it occurs. f is sampled at
/// `samples` + 1 evenly spaced points; each sampled local maximum is refined by golden-section
/// search over its two neighbouring intervals. A maximum narrower than the sampling step and
/// lower than its neighbours can be missed, so `samples` must resolve the function's shape
/// (a few per oscillation); non-finite values of f count as +infinity and stop the search.
template <class F>
Peak find_maximum(F&& f, double a, double b, int samples, double x_tolerance) {
  samples = std::max(samples, 2);
  const double h = (b - a) / samples;
  Peak best;
  double prev2 = 0, prev = 0;
  for (int i = 0; i <= samples; ++i) {
    const double x = i == samples ? b : a + h * i;
    double v = f(x);
    if (std::isnan(v)) v = std::numeric_limits<double>::infinity();
    if (v > best.value) best = {x, v};
    if (std::isinf(v) && v > 0) return best;
    // A local maximum of the samples (plateaus, as in a dwell, are flat: nothing to refine).
    if (i >= 2 && prev >= prev2 && prev >= v && (prev > prev2 || prev > v)) {
      best = golden_maximum(f, a + h * (i - 2), x, x_tolerance, best);
    }
    // A maximum between an end and its neighbour, the end itself being the larger sample.
    if ((i == 1 && prev > v) || (i == samples && v > prev)) {
      best = golden_maximum(f, a + h * (i - 1), x, x_tolerance, best);
    }
    prev2 = prev, prev = v;
  }
  return best;
}

}  // namespace gearkit::cam::detail
