#include <gearkit/kin/sweep_statistics.hpp>

#include <cmath>

namespace gearkit::kin {

void SweepStatistics::add(double input, double value) {
  if (!std::isfinite(value) || !std::isfinite(input)) {
    has_previous_ = false;
    return;
  }
  if (count_ == 0 || value < min_.value) min_ = {value, input};
  if (count_ == 0 || value > max_.value) max_ = {value, input};
  if (count_ == 0 || std::abs(value) > std::abs(peak_.value)) peak_ = {value, input};
  ++count_;
  const double square = value * value;
  if (has_previous_) {
    const double width = std::abs(input - previous_input_);
    integral_ += 0.5 * (square + previous_square_) * width;
    covered_ += width;
  }
  has_previous_ = true;
  previous_input_ = input;
  previous_square_ = square;
}

double SweepStatistics::rms() const {
  if (count_ == 0) return std::numeric_limits<double>::quiet_NaN();
  if (covered_ <= 0) return std::abs(peak_.value);
  return std::sqrt(integral_ / covered_);
}

}  // namespace gearkit::kin
