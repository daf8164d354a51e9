#pragma once
// `gearkit kin --plot`: the outputs (or the link angles), the transmission angle and the driving
// effort against the input, gathered position by position in constant memory.
#include "kin_analysis.hpp"

#include <gearkit/io/plot.hpp>
#include <gearkit/io/series_reducer.hpp>

#include <string>
#include <vector>

namespace gearkit::cli {

class KinPlot {
 public:
  /// @param x_first, x_last the sweep's input range as shown (deg or mm); `expected` positions.
  KinPlot(const mechanism::Mechanism& mech, int driver, double x_first, double x_last, long expected);
  void add(const KinPosition& p);
  /// The SVG document. @param marks where the sweep stopped (dead points), inputs as shown.
  std::string svg(std::vector<io::PlotMark> marks = {}) const;

 private:
  const mechanism::Mechanism& mech_;
  int driver_;
  double x_first_, x_last_;
  long expected_;
  std::vector<io::SeriesReducer> outputs_, angles_;
  std::vector<io::SeriesReducer> mu_, effort_;  // empty, or one series when positions have them
};

}  // namespace gearkit::cli
