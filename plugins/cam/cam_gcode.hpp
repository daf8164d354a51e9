#pragma once
// G-code (RS-274/NGC) of a cam's cutter-centre path (docs/cam.md, "Machining").
#include "cam_model.hpp"
#include "cam_report.hpp"

#include <string>

namespace gearkit::plugins::cam {

struct GcodeOptions {
  bool polar = false;        ///< rotary table (X radius, C angle) instead of a 2-axis mill (X, Y, G2/G3)
  double feed_mm_min = 200;  ///< feed rate [mm/min]
};

/// The program: a documented header (units, plane, arc mode, what the coordinates mean), then
/// every tool-path loop (both walls of a groove; the conjugate cam after an M0), M2. Requires a
/// cutter radius (the tool paths).
std::string cam_gcode(const CamModel& model, const CamResult& result, const GcodeOptions& options,
                      const std::string& file);

}  // namespace gearkit::plugins::cam
