#pragma once
// `gearkit kin`: the mechanism summary of a run, gathered position by position as the sweep
// streams (nothing is kept per position): the least and largest transmission angle and where,
// the peak and RMS driving effort, the peak reaction of each joint, the limit positions and dead
// points the sweep located, and a warning where the transmission angle falls below the limit
// (--min-transmission-angle, default 40 deg: the usual rule, Norton, Design of Machinery,
// sect. 3.3; Shigley and Uicker, Theory of Machines and Mechanisms, sect. 1.9).
#include "kin_analysis.hpp"

#include <gearkit/io/report.hpp>
#include <gearkit/kin/sweep_statistics.hpp>

#include <numbers>
#include <string>
#include <vector>

namespace gearkit::cli {

/// The default least transmission angle [rad] below which the summary warns.
inline constexpr double kDefaultMinTransmissionAngle = 40.0 * std::numbers::pi / 180.0;

class KinSummary {
 public:
  /// @param min_transmission_angle [rad] the warning limit.
  KinSummary(const mechanism::Mechanism& mech, int driver, double min_transmission_angle);

  /// One position, in the sweep's order.
  void add(const KinPosition& p);

  /// The table "Mechanism summary", JSON "summary" and the warnings, appended to `rep`. `a` gives
  /// the located dead points and output extremes (the limit positions).
  void write(const KinAnalysis& a, io::Report& rep) const;

 private:
  struct JointPeak {
    std::string name, kind;
    kin::Extreme force;  ///< largest |F| [N] and the input there
  };
  void add_reactions(const KinPosition& p);

  const mechanism::Mechanism& mech_;
  int driver_;
  double limit_;
  long positions_ = 0;
  double first_input_ = 0, last_input_ = 0;
  kin::SweepStatistics mu_, effort_;
  std::vector<JointPeak> joints_;
};

}  // namespace gearkit::cli
