#pragma once
// Coupler curves of `gearkit kin`: the path of any link point over the sweep, for a designer to
// reuse: --coupler LINK.POINT[,...] with --coupler-svg (Py against Px, equal scales, the ground
// pivots, the start and the direction of travel), --coupler-csv (one table) and --coupler-dxf (a
// polyline per point, mm).
#include "kin_analysis.hpp"

#include <gearkit/io/command_line.hpp>
#include <gearkit/io/drawing.hpp>
#include <gearkit/io/output.hpp>

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

/// The points' paths over the analysis' positions, [mm]: one vector of (x, y) per point.
std::vector<std::vector<Eigen::Vector2d>> coupler_paths(const std::vector<CouplerPoint>& points, const KinAnalysis& analysis);

/// Drawing of the paths (layers coupler_1, coupler_2..., ground, labels), in mm, y up.
io::Drawing coupler_drawing(const mechanism::Mechanism& mech, const std::vector<CouplerPoint>& points,
                            const std::vector<std::vector<Eigen::Vector2d>>& paths);

/// Adds the files the options ask for to `outputs`; a warning when there are no positions.
/// @throws io::InputError for --coupler-* without --coupler, or a bad --coupler.
void add_coupler_outputs(const io::po::variables_map& vm, const mechanism::Mechanism& mech, const KinAnalysis& analysis,
                         io::Report& report, io::OutputSet& outputs);

}  // namespace gearkit::cli
