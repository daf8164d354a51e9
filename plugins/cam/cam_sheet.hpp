#pragma once
// The cam drawing as a sheet (`gearkit cam --dxf/--svg`): cam_drawing()'s geometry (profile, pitch
// curve, tool path, base circle, follower) plus what a workshop or a report needs to read it: a
// legend, the zero-angle mark and the cam angles of the segment joins, the direction of rotation,
// the key radii dimensioned (base, prime, largest, roller), the report's motion program and checks
// tables as printed, and a title block with the units. Annotation sits on layers of its own
// (dimensions, angle_marks, legend, tables, title_block, frame), so a CAM program can switch it off
// and the profile layers stay exactly what they were.
#include "cam_model.hpp"
#include "cam_report.hpp"

#include <gearkit/io/drawing.hpp>
#include <gearkit/io/report.hpp>

namespace gearkit::plugins::cam {

/// The annotated drawing. The follower is drawn at cam angle `follower_at` [rad] (the DXF uses 0,
/// so its profile layers keep the cam frame at cam angle 0; the SVG uses --follower-at).
/// `report` is cam_report()'s: its "Motion program" and "Checks" tables are copied cell for cell.
io::Drawing cam_sheet(const CamModel& model, const CamResult& result, const io::Report& report, double follower_at);

}  // namespace gearkit::plugins::cam
