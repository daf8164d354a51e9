#pragma once
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
  double deviation_mm = 0;  ///< fitted/offset profile vs the analytic profile
};

/// The report: design, motion program, checks, profile summary, warnings; JSON keys with units.
io::Report cam_report(const CamModel& model, const CamResult& result, const std::string& file);

}  // namespace gearkit::plugins::cam
