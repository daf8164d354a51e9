#pragma once
// Drawings, plots and tables of a synthesised cam: DXF/SVG through io::Drawing, s-v-a-j plots
// through io::Plot, CSV of the profile points and motion diagrams.
#include "cam_dynamics.hpp"
#include "cam_model.hpp"

#include <gearkit/cam/cam_checks.hpp>
#include <gearkit/cam/cam_profile.hpp>
#include <gearkit/io/drawing.hpp>
#include <gearkit/io/plot.hpp>

#include <string>

namespace gearkit::plugins::cam {

/// Layers: profile, pitch_curve, base_circle, tool_path (and centre marks on 'center'), in the
/// cam frame at cam angle 0. With `with_follower`, the cam turned to model.follower_at and the
/// follower drawn there (for the SVG).
/// Groove cams add the layers outer_wall and outer_tool_path; with `second` (a conjugate cam),
/// conjugate_profile, conjugate_pitch_curve and conjugate_tool_path.
io::Drawing cam_drawing(const CamModel& model, const gearkit::cam::CamProfile& profile, bool with_follower,
                        const gearkit::cam::CamProfile* second = nullptr);

/// A closed chain of pieces as a polyline with bulges (arcs on one circle merged first).
io::Polyline polyline_of(const std::vector<gearkit::cam::Piece>& loop, const std::string& layer);

/// s, v, a, j against cam angle (per second when the cam speed is known, else per radian).
io::Plot motion_plot(const CamModel& model, const std::vector<gearkit::cam::ContactState>& samples);

/// CSV: cam angle, motion and its derivatives, pressure angle, curvature, pitch and profile points;
/// with the dynamics, contact force, camshaft torque and power (and Hertz stress) at those angles.
std::string motion_csv(const CamModel& model, const std::vector<gearkit::cam::ContactState>& samples,
                       const CamDynamics* dynamics = nullptr);

/// Contact force (rigid and flexible), camshaft torque and Hertz stress against cam angle.
io::Plot dynamics_plot(const CamModel& model, const CamDynamics& dynamics);

/// A `gearkit dyn` model (docs/dyn.md) of the camshaft: its torque over the turn at the design
/// speed as the resisting torque table, the mean torque driving, and the flywheel question.
std::string dyn_model(const CamModel& model, const CamDynamics& dynamics, const std::string& file);

/// The contact at model.samples cam angles evenly over the turn.
std::vector<gearkit::cam::ContactState> sample_turn(const CamModel& model);

}  // namespace gearkit::plugins::cam
