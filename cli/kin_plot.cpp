#include "kin_plot.hpp"
#include "kin_units.hpp"

#include <gearkit/io/plot.hpp>

#include <fmt/format.h>

#include <limits>

namespace gearkit::cli {

namespace {

// About the plot's width in pixels: more points per column could not be seen.
constexpr int kColumns = 1000;

}  // namespace

KinPlot::KinPlot(const mechanism::Mechanism& mech, int driver, double x_first, double x_last, long expected)
    : mech_(mech), driver_(driver), x_first_(x_first), x_last_(x_last), expected_(expected) {
  const auto make = [&] { return io::SeriesReducer(x_first_, x_last_, kColumns, expected_); };
  for (std::size_t k = 0; k < mech.outputs.size(); ++k) outputs_.push_back(make());
  if (mech.outputs.empty())
    for (std::size_t b = 0; b < mech.model.bodies().size(); ++b) angles_.push_back(make());
}

void KinPlot::add(const KinPosition& p) {
  const double x = shown_input(mech_, driver_, p.input);
  for (std::size_t k = 0; k < outputs_.size(); ++k) outputs_[k].add(x, shown_output(mech_.outputs[k], p.outputs[k].value));
  for (std::size_t b = 0; b < angles_.size(); ++b) angles_[b].add(x, p.q(3 * static_cast<int>(b) + 2) * kRadToDeg);
  const auto reducer = [&](std::vector<io::SeriesReducer>& r) -> io::SeriesReducer& {
    if (r.empty()) r.emplace_back(x_first_, x_last_, kColumns, expected_);
    return r.front();
  };
  if (p.transmission_angle) reducer(mu_).add(x, *p.transmission_angle * kRadToDeg);
  // At a dead point the effort is unbounded: a gap (NaN) ends the curve before it instead of a
  // spike of 1e15 that flattens the rest of the panel; the plot's mark shows where.
  if (p.forces)
    reducer(effort_).add(x, p.at_dead_point ? std::numeric_limits<double>::quiet_NaN()
                                            : p.forces->effort_virtual_power[static_cast<std::size_t>(driver_)]);
}

std::string KinPlot::svg(std::vector<io::PlotMark> marks) const {
  io::Plot plot;
  plot.marks = std::move(marks);
  plot.x_reversed = x_last_ < x_first_;  // a clockwise sweep reads left to right as swept
  plot.title = mech_.title;
  plot.x_label = fmt::format("{} [{}]", mech_.drivers[static_cast<std::size_t>(driver_)].name, input_unit(mech_, driver_));
  for (std::size_t k = 0; k < outputs_.size(); ++k) {
    const kin::Output& o = mech_.outputs[k];
    plot.panels.push_back({fmt::format("{} [{}]", o.name, output_unit(o)), {outputs_[k].series(o.name)}, {}});
  }
  if (!angles_.empty()) {
    io::PlotPanel panel;
    panel.y_label = "link angles [deg]";
    for (std::size_t b = 0; b < angles_.size(); ++b) panel.series.push_back(angles_[b].series(mech_.model.bodies()[b].name));
    plot.panels.push_back(panel);
  }
  if (!mu_.empty()) plot.panels.push_back({"transmission angle [deg]", {mu_.front().series("mu")}, {}});
  if (!effort_.empty()) {
    const bool ang = angular(mech_, driver_);
    plot.panels.push_back({ang ? "driving torque [N m]" : "driving force [N]", {effort_.front().series(ang ? "T" : "F")}, {}});
  }
  return io::to_svg(plot);
}

}  // namespace gearkit::cli
