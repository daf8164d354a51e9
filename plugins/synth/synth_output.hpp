#pragma once
// What a synthesis task produces, and the pieces every task shares: the linkage's tables, the
// drawing of its positions, the solver check of the written mechanism file.
#include <gearkit/io/drawing.hpp>
#include <gearkit/io/plot.hpp>
#include <gearkit/io/report.hpp>
#include <gearkit/io/yaml_model.hpp>
#include <gearkit/synth/linkage.hpp>
#include <gearkit/synth/mechanism_writer.hpp>

#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace gearkit::plugins::synth {

namespace gs = gearkit::synth;

/// Command-line settings that override the task file (optimiser budget, seed).
struct Overrides {
  std::optional<long> evaluations;
  std::optional<int> restarts;
  std::optional<unsigned> seed;
  double min_transmission_angle = 40 * std::numbers::pi / 180;  ///< --min-transmission-angle [rad]
};

struct Output {
  io::Report report;
  std::string mechanism_yaml;      ///< the `gearkit kin` file of the result
  io::Drawing drawing;             ///< the linkage at its positions, curves and targets (mm)
  std::optional<io::Plot> plot;    ///< the task's chart
};

/// A precision position the written mechanism must reach: crank angle and where its tracked
/// point (the coupler point P, or the slider) must be.
struct Checkpoint {
  double theta2 = 0;               ///< [rad]
  gs::Vec2 point{0, 0};            ///< expected P [m] (four-bar) ...
  std::optional<double> output;    ///< ... or expected output value (rad or m) of output `output_name`
  std::string output_name;
  bool angular = false;            ///< compare the output modulo 2 pi
};

/// Loads the mechanism text through the `gearkit kin` reader, drives the solver from the drawn
/// position through each checkpoint in turn (continuation, so the branch is kept) and returns
/// the largest miss [m or rad]; adds the misses (JSON solver_check_max_miss_mm/_deg) and a note,
/// or a warning above 1e-8 m or rad, to the report. Closing the loop between synthesis and analysis.
double verify_with_solver(const std::string& yaml, const std::vector<Checkpoint>& checkpoints, io::Report& report);

/// Crank angle t2 as reached from `start` turning in `direction` (the driver's continuous value).
double unwrapped(double start, double t2, int direction);

/// Tables "Linkage" (pivots and lengths) and "Checks" (Grashof class, defects, transmission
/// angle range) of a four-bar, with their JSON keys under `key`; defects become warnings.
void add_four_bar_tables(const gs::FourBar& linkage, const gs::DefectReport& defects,
                         const gs::TransmissionRange& transmission, io::Report& report);

/// Table "Mechanism summary" and JSON "summary" (synth_summary.cpp) over the motion the four-bar
/// really makes: the full turn when its crank turns fully, else `travel` [rad] from `theta2_start`
/// in `direction`. The least and largest transmission angle and where, the rocker's limit
/// positions (located to O(h^3) by a parabola through 0.1 deg samples), the crank's dead points
/// when it does not turn fully; a warning below `limit` [rad] when `warn` (a defective linkage
/// has its own warnings).
void add_four_bar_summary(const gs::FourBar& linkage, double theta2_start, double travel, int direction, double limit,
                          bool warn, io::Report& report);

/// Draws the four-bar at each crank angle (the first solid, the others on layer "positions")
/// and its coupler curve over `travel` from theta2[0] in `direction`.
void draw_four_bar(const gs::FourBar& linkage, const std::vector<double>& theta2, double travel, int direction,
                   io::Drawing& drawing);

/// Small circles at target points on layer "targets".
void draw_targets(const std::vector<gs::Vec2>& points, double radius, io::Drawing& drawing);

/// The transmission-angle chart over the crank's travel.
io::Plot transmission_plot(const gs::FourBar& linkage, double theta2_start, double travel, int direction,
                           const std::string& title);

/// Task readers (synth_read.cpp): a point [x, y] (mm by default) and an angle list.
gs::Vec2 read_point(const YAML::Node& node, const std::string& file);
std::vector<double> read_angles(const YAML::Node& node, const std::string& file);

/// Each task: reads its file, synthesises, fills the output.
Output run_function_task(const io::YamlDocument& doc, const Overrides& overrides);
Output run_motion_task(const io::YamlDocument& doc, const Overrides& overrides);
Output run_path_task(const io::YamlDocument& doc, const Overrides& overrides);
Output run_crank_rocker_task(const io::YamlDocument& doc, const Overrides& overrides);
Output run_dwell_task(const io::YamlDocument& doc, const Overrides& overrides);

/// "12.345" mm of a length in m; degrees of an angle in rad.
std::string mm(double metres);
std::string deg(double radians);

}  // namespace gearkit::plugins::synth
