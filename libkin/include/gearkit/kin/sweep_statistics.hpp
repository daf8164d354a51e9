#pragma once
// Running statistics of one quantity along a sweep of the input: its least and largest value and
// where they occur, the largest magnitude, and the root mean square over the input. Used by the
// mechanism summaries of `gearkit kin` and `gearkit synth`, which see the positions one by one.
#include <cstddef>
#include <limits>

namespace gearkit::kin {

/// A value and the input where it occurs (units of the caller: rad or m for the input).
struct Extreme {
  double value = std::numeric_limits<double>::quiet_NaN();
  double input = std::numeric_limits<double>::quiet_NaN();
};

/// Statistics of samples (input, value) given in the sweep's order. Non-finite values are not
/// counted (a wedged or dead-point position has no meaningful effort) and break the integral.
class SweepStatistics {
 public:
  /// Adds one sample; `input` must follow the previous one monotonically (either direction).
  void add(double input, double value);

  std::size_t count() const { return count_; }
  const Extreme& min() const { return min_; }
  const Extreme& max() const { return max_; }
  /// The sample of largest |value| (its value keeps its sign).
  const Extreme& peak() const { return peak_; }
  /// sqrt(integral of value^2 d(input) / covered input), by the trapezoidal rule between
  /// consecutive finite samples: the time RMS for an input turning at constant speed. With one
  /// sample (or none covering an input range) the |value| of that sample; NaN with none.
  double rms() const;

 private:
  std::size_t count_ = 0;
  Extreme min_, max_, peak_;
  bool has_previous_ = false;  // the previous sample was finite
  double previous_input_ = 0, previous_square_ = 0;
  double integral_ = 0, covered_ = 0;
};

}  // namespace gearkit::kin
