#pragma once
// Coupler curves of `gearkit kin`: the path of any link point over the sweep, for a designer to
// reuse: --coupler LINK.POINT[,...] with --coupler-svg (Py against Px, equal scales, the ground
// pivots, the start and the direction of travel), --coupler-csv (one table) and --coupler-dxf (a
// polyline per point, mm).
#include "kin_analysis.hpp"

#include <gearkit/io/command_line.hpp>
#include <gearkit/io/drawing.hpp>
#include <gearkit/io/output.hpp>

#include <optional>
#include <string>
#include <vector>

namespace gearkit::cli {

/// Registers --coupler, --coupler-svg, --coupler-csv, --coupler-dxf.
void add_coupler_options(io::po::options_description& desc);

/// A coupler point: the body and its local point, named "LINK.POINT".
struct CouplerPoint {
  std::string name;
  int body = 0;
  Eigen::Vector2d local = Eigen::Vector2d::Zero();  ///< [m]
};

/// Parses "LINK.POINT,LINK.POINT..." against the model's moving links.
/// @throws io::InputError naming --coupler and listing the link points for an unknown one.
std::vector<CouplerPoint> parse_coupler_points(const kin::Model& model, const std::string& text);

/// The paths of the points as a sweep runs, [mm]: at most kCouplerPoints points each (a longer
/// sweep keeps every stride-th position, and the last).
class CouplerPaths {
 public:
  static constexpr long kCouplerPoints = 100'000;
  CouplerPaths(std::vector<CouplerPoint> points, long expected_positions);
  void add(const KinPosition& p);
  /// Keeps the last position added if the stride skipped it. Call once, after the last add().
  void finish();
  const std::vector<CouplerPoint>& points() const { return points_; }
  const std::vector<double>& inputs() const { return inputs_; }  ///< the driver's input of each point [rad or m]
  const std::vector<std::vector<Eigen::Vector2d>>& paths() const { return paths_; }
  bool empty() const { return inputs_.empty(); }

 private:
  void keep(double input, const Eigen::VectorXd& q);
  std::vector<CouplerPoint> points_;
  std::vector<double> inputs_;
  std::vector<std::vector<Eigen::Vector2d>> paths_;
  long stride_ = 1, seen_ = 0;
  bool skipped_last_ = false;
  double last_input_ = 0;
  Eigen::VectorXd last_q_;
};

/// Drawing of the paths (layers coupler_1, coupler_2..., ground, labels), in mm, y up.
io::Drawing coupler_drawing(const mechanism::Mechanism& mech, const std::vector<CouplerPoint>& points,
                            const std::vector<std::vector<Eigen::Vector2d>>& paths);

/// What --coupler and its files ask for, checked before the analysis: the points parsed and every
/// destination reserved in `outputs` (so a bad one is refused before the report is printed).
/// @throws io::InputError for --coupler-* without --coupler, or a bad --coupler.
std::optional<std::vector<CouplerPoint>> reserve_coupler_outputs(const io::po::variables_map& vm, const kin::Model& model,
                                                                 io::OutputSet& outputs);

/// Fills the reserved files from the paths; a warning in `report` when there are no positions.
void fill_coupler_outputs(const io::po::variables_map& vm, const mechanism::Mechanism& mech, int driver,
                          const CouplerPaths& paths, io::Report& report, io::OutputSet& outputs);

}  // namespace gearkit::cli
