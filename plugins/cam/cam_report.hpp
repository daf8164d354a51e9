#pragma once
#include "cam_dynamics.hpp"
#include "cam_model.hpp"

#include <gearkit/cam/cam_checks.hpp>
#include <gearkit/cam/cam_profile.hpp>
#include <gearkit/io/report.hpp>

#include <vector>

namespace gearkit::plugins::cam {

/// Everything computed for one cam.
struct CamResult {
  gearkit::cam::CamChecks checks;
  gearkit::cam::CamProfile profile;
  std::vector<gearkit::cam::JoinJump> jumps;
  std::vector<gearkit::cam::ContactState> samples;  ///< model.samples cam angles
  double deviation_mm = 0;  ///< exported profile arcs vs the analytic profile (found during the fit)
  /// Groove: the outer wall's checks; conjugate: the second cam's checks and profile.
  std::optional<gearkit::cam::CamChecks> other_checks;
  std::optional<gearkit::cam::CamProfile> second_profile;
  std::optional<CamDynamics> dynamics;
};

/// The report: design, motion program, checks, profile summary, warnings; JSON keys with units.
io::Report cam_report(const CamModel& model, const CamResult& result, const std::string& file);

/// The dynamics sections (tables, warnings, notes and JSON "dynamics").
void dynamics_report(const CamModel& model, const CamDynamics& dynamics, io::Report& report);

/// Oscillating followers: the gap between the circle the cam sweeps and the pivot (less its
/// boss radius) [mm]; <= 0 means the cam strikes the pivot.
double pivot_clearance(const CamModel& model, const CamResult& result);

}  // namespace gearkit::plugins::cam
