#pragma once
// Helpers of the synthesis tests: the reference four-bar analysed by libkin (the truth the
// synthesis must recover), and the loop closed through the mechanism reader and the solver.
#include <gearkit/mechanism/reader.hpp>
#include <gearkit/kin/solve.hpp>
#include <gearkit/kin/sweep.hpp>
#include <gearkit/synth/function_generation.hpp>
#include <gearkit/synth/linkage.hpp>
#include <gearkit/synth/motion_generation.hpp>

#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace gearkit::synth::testing {

inline constexpr double pi = std::numbers::pi;
inline constexpr double deg = pi / 180;

/// The crank-rocker of examples/mechanisms/four_bar.yaml (Norton's four-bar dimensions):
/// O2 (0, 0), O4 (100, 0), crank 40, coupler 120, rocker 80 mm, coupler point C (60, 30) mm.
inline FourBar reference_four_bar() {
  FourBar f;
  f.O2 = Vec2(0, 0);
  f.O4 = Vec2(0.1, 0);
  f.crank = 0.04;
  f.coupler = 0.12;
  f.rocker = 0.08;
  f.coupler_point = Vec2(0.06, 0.03);
  f.branch = 1;
  return f;
}

/// A mechanism loaded through the `gearkit kin` reader with its solver workspace, driven by
/// continuation from the drawn position.
struct Driven {
  mechanism::Mechanism mech;
  std::unique_ptr<kin::Data> data;
  double input = 0;  ///< current driver value [rad]

  static Driven from_text(const std::string& yaml) {
    Driven d{mechanism::read_mechanism(io::load_yaml_text(yaml, "synthesised.yaml"), [](std::string_view) { return nullptr; }),
             nullptr, 0};
    d.data = std::make_unique<kin::Data>(d.mech.model);
    d.input = d.data->inputs(0);
    return d;
  }
  static Driven from_file(const std::string& path) {
    Driven d{mechanism::load_mechanism(path, [](std::string_view) { return nullptr; }), nullptr, 0};
    d.data = std::make_unique<kin::Data>(d.mech.model);
    d.input = d.data->inputs(0);
    return d;
  }

  /// Drives to `value` [rad] by a sweep in 1 deg steps then an exact solve; false at a dead point.
  bool drive_to(double value) {
    if (std::abs(value - input) > 1e-12) {
      kin::SweepOptions o;
      o.start = input;
      o.end = value;
      o.step = std::min(deg, std::abs(value - input) / 2);
      o.velocities = false;
      const kin::SweepResult s = kin::sweep(mech.model, *data, o);
      if (!s.complete) return false;
      data->q = s.samples.back().q;
    }
    input = value;
    return kin::solve_at(mech.model, *data, 0, value).converged;
  }

  double output(const std::string& name) const {
    for (const kin::Output& o : mech.outputs)
      if (o.name == name) return kin::evaluate_output(mech.model, *data, o).value;
    throw std::invalid_argument("no output " + name);
  }
};

/// Coupler poses (point C and coupler angle) of the reference four-bar at crank angles [rad],
/// computed by libkin from examples/mechanisms/four_bar.yaml: the independent truth.
inline std::vector<Pose> reference_poses(const std::vector<double>& theta2) {
  Driven d = Driven::from_file(std::string(GEARKIT_SOURCE_DIR) + "/examples/mechanisms/four_bar.yaml");
  std::vector<Pose> poses;
  for (double t : theta2) {
    if (!d.drive_to(t)) throw std::runtime_error("reference four-bar: dead point");
    poses.push_back({{d.output("Cx"), d.output("Cy")}, d.data->q[5]});  // coupler is body 1: q = (x, y, theta)
  }
  return poses;
}

/// y = log10(x) over [1, 2], crank 90 -> 150 deg, rocker 225 -> 285 deg, ground 100 mm
/// (examples/synthesis/function_log10.yaml).
inline FunctionTask log10_task() {
  FunctionTask t;
  t.f = [](double x) { return std::log10(x); };
  t.x_start = 1;
  t.x_end = 2;
  t.input_start = 90 * deg;
  t.input_range = 60 * deg;
  t.output_start = 225 * deg;
  t.output_range = 60 * deg;
  t.ground = 0.1;
  return t;
}

/// The ten-point elliptic path of the four-bar path-synthesis benchmark set (Acharyya & Mandal
/// 2009, Mechanism and Machine Theory 44; Yao et al. 2022, Mechanical Sciences 13: 79-87): points
/// every 40 deg on the ellipse of semi-axes 10 and 8 mm about (10, 10) mm, first and last the
/// same, no prescribed timing: the published coordinates, rounded as printed, as in
/// examples/synthesis/path_ellipse.yaml [m]. Converted as `gearkit synth` converts the file's mm
/// (x * 1e-3, io's unit factor), so that the library, the bench and the command start the
/// optimiser from bit-identical targets: its random search follows the last bits of its input,
/// and a seed only reproduces a run on the same bits (docs/synthesis.md, "Path generation").
inline std::vector<Vec2> published_ellipse_points() {
  const double xy[10][2] = {{20, 10},       {17.66, 15.142},   {11.736, 17.878}, {5, 16.928},      {0.60307, 12.736},
                            {0.60307, 7.2638}, {5, 3.0718},    {11.736, 2.1215}, {17.66, 4.8577}, {20, 10}};
  std::vector<Vec2> p;
  for (const auto& q : xy) p.push_back(Vec2(q[0] * 1e-3, q[1] * 1e-3));
  return p;
}

}  // namespace gearkit::synth::testing
