#pragma once
// `gearkit kin`: the analysis results of one run, independent of how they are printed.
#include <gearkit/mechanism/reader.hpp>
#include <gearkit/kin/dof.hpp>
#include <gearkit/kin/kinetostatics.hpp>
#include <gearkit/kin/sweep.hpp>
#include <optional>
#include <string>
#include <vector>

namespace gearkit::cli {

/// Everything computed at one input value.
struct KinPosition {
  double input = 0.0;  ///< [rad or m]
  Eigen::VectorXd q, qd, qdd;
  std::vector<kin::OutputValue> outputs;
  std::vector<double> output_ratios;       ///< d(output)/d(input)
  std::optional<double> transmission_angle;  ///< [rad], four-bars only
  std::optional<kin::ForceAnalysis> forces;  ///< when the model has loads
};

struct KinAnalysis {
  kin::DofReport dof;
  int driver = 0;
  std::vector<KinPosition> positions;
  std::vector<kin::DeadPoint> dead_points;
  std::vector<kin::OutputExtreme> extremes;
  std::vector<std::string> warnings;
  std::vector<std::optional<Eigen::Vector2d>> instant_centres;  ///< per body, single position only
  bool single = false;
};

/// Fills a KinPosition from a solved Data (positions, velocities, accelerations done).
KinPosition describe_position(const mechanism::Mechanism& mech, kin::Data& data, int driver, double input);

/// The SVG animation of the mechanism through the positions (SMIL, loops forever): links, joints,
/// ground, slider blocks on their guides, names, output point traces (kin_animation_elements.hpp).
/// One loop takes the sweep at `input_speed` (rad/s or m/s, from --speed), else a stated default.
std::string animation_svg(const mechanism::Mechanism& mech, const KinAnalysis& analysis,
                          std::optional<double> input_speed = std::nullopt);

}  // namespace gearkit::cli
