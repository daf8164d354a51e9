// The mechanism summary of a synthesised four-bar over the motion it really makes: the full turn
// when the crank turns fully (a motor drives it on past the task's travel), else the travel.
#include "synth_output.hpp"

#include <gearkit/kin/sweep_statistics.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace gearkit::plugins::synth {

namespace {

constexpr double pi = std::numbers::pi;
constexpr double kStep = pi / 1800;  // 0.1 deg of crank between samples

double wrapped_deg(double theta2) { return gs::wrap_two_pi(theta2) * 180 / pi; }

struct RockerLimit {
  double theta2 = 0, theta4 = 0;
  bool maximum = false;
};

// The vertex of the parabola through three equally spaced samples (h apart) around a sampled
// extreme: the rocker's limit position to O(h^3).
RockerLimit vertex(double theta2, double h, double y0, double y1, double y2) {
  const double curvature = y0 - 2 * y1 + y2;
  const double p = curvature != 0 ? (y0 - y2) / (2 * curvature) : 0.0;
  return {theta2 + p * h, y1 - (y0 - y2) * p / 4, curvature < 0};
}

struct MotionSamples {
  kin::SweepStatistics mu;
  std::vector<RockerLimit> limits;
};

// Samples the motion every 0.1 deg. Over a full turn the rocker's samples run one step past each
// end, so that a limit position at the start (the crank-rocker is drawn at one) is found once:
// each middle sample of a turn is the centre of one triple.
MotionSamples sample_motion(const gs::FourBar& f, double start, double travel, int direction, bool full) {
  MotionSamples m;
  const int n = std::max(2, static_cast<int>(std::ceil(travel / kStep)));
  const double h = direction * travel / n;
  double y[3] = {0, 0, 0};  // the last three unwrapped rocker angles
  int have = 0;             // consecutive closed positions in y
  for (int k = full ? -1 : 0; k <= n; ++k) {
    const double theta2 = start + h * k;
    const auto pose = gs::pose_at(f, theta2);
    if (k >= 0) m.mu.add(theta2, pose ? gs::transmission_angle(*pose, f) : std::numeric_limits<double>::quiet_NaN());
    if (!pose) {
      have = 0;
      continue;
    }
    const double t4 = have == 0 ? pose->theta4 : y[2] + std::remainder(pose->theta4 - y[2], 2 * pi);
    y[0] = y[1], y[1] = y[2], y[2] = t4;
    if (++have >= 3 && (y[1] - y[0]) * (y[2] - y[1]) < 0) m.limits.push_back(vertex(theta2 - h, h, y[0], y[1], y[2]));
  }
  return m;
}

}  // namespace

void add_four_bar_summary(const gs::FourBar& f, double start, double travel, int direction, double limit, bool warn,
                          io::Report& report) {
  const bool full = gs::crank_turns_fully(f);
  if (full) travel = 2 * pi;
  const MotionSamples m = sample_motion(f, start, travel, direction, full);
  const std::string over = full ? "the full turn of the crank" : "the crank's travel (it does not turn fully)";
  io::Table t{"Mechanism summary", {"quantity", "value", "at theta2 [deg]"}, {}};
  nlohmann::json j = {{"motion", full ? "full turn" : "travel"},
                      {"theta2_from_deg", start * 180 / pi},
                      {"theta2_to_deg", (start + direction * travel) * 180 / pi},
                      {"min_transmission_angle_limit_deg", limit * 180 / pi}};
  t.add_row({"motion", full ? "crank turns fully" : "crank's travel",
             fmt::format("{} .. {}", deg(start), deg(start + direction * travel))});
  if (m.mu.count() > 0) {
    t.add_row({"least transmission angle mu [deg]", deg(m.mu.min().value), io::fixed(wrapped_deg(m.mu.min().input), 3)});
    t.add_row({"largest transmission angle mu [deg]", deg(m.mu.max().value), io::fixed(wrapped_deg(m.mu.max().input), 3)});
    j["transmission_angle_min_deg"] = m.mu.min().value * 180 / pi;
    j["transmission_angle_min_at_theta2_deg"] = wrapped_deg(m.mu.min().input);
    j["transmission_angle_max_deg"] = m.mu.max().value * 180 / pi;
    j["transmission_angle_max_at_theta2_deg"] = wrapped_deg(m.mu.max().input);
  }
  nlohmann::json limits = nlohmann::json::array();
  for (const RockerLimit& l : m.limits) {
    t.add_row({fmt::format("limit position: rocker theta4 {} [deg]", l.maximum ? "max" : "min"), io::fixed(wrapped_deg(l.theta4), 3),
               io::fixed(wrapped_deg(l.theta2), 3)});
    limits.push_back({{"kind", l.maximum ? "rocker max" : "rocker min"}, {"theta4_deg", wrapped_deg(l.theta4)},
                      {"theta2_deg", wrapped_deg(l.theta2)}});
  }
  if (!full)
    for (const gs::AngleInterval& r : gs::crank_range(f))
      for (const double end : {r.start, r.start + r.length}) {
        t.add_row({"dead point of the crank (coupler and rocker in line)", "-", io::fixed(wrapped_deg(end), 3)});
        limits.push_back({{"kind", "dead point"}, {"theta2_deg", wrapped_deg(end)}});
      }
  j["limit_positions"] = limits;
  report.tables.push_back(std::move(t));
  report.json["summary"] = std::move(j);
  if (warn && m.mu.count() > 0 && m.mu.min().value < limit)
    report.warnings.push_back(fmt::format("transmission angle down to {} deg at theta2 = {} deg over {}, below the {} deg "
                                          "limit (--min-transmission-angle): it transmits force poorly there",
                                          deg(m.mu.min().value), io::fixed(wrapped_deg(m.mu.min().input), 3), over, deg(limit)));
}

}  // namespace gearkit::plugins::synth
