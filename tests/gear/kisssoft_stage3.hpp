#pragma once
// The helical stage of a published KISSsoft 03/2017 report (ISO 6336:2006 method B), shared by
// test_rating.cpp (load capacity) and test_inspection.cpp (tolerances and measurements): file
// @NREL_5MW/stage_03.rtf of gfsReboucas/Drivetrain (commit 2a41bf1). m_n = 14 mm, z = 24/95,
// alpha_n = 20 deg, beta = 10 deg, a = 861 mm, x_1 = 0.48 (x_2 = 0.6691 follows), b = 360 mm,
// ISO 53 profile A (1 / 1.25 / 0.38).
#include <gearkit/gear/gear_pair.hpp>

#include <numbers>

namespace gearkit::testing {

inline gearkit::gear::GearPairInput kisssoft_stage3_geometry() {
  gearkit::gear::GearPairInput in;
  in.z1 = 24;
  in.z2 = 95;
  in.module = 14.0;
  in.helix_angle = 10.0 * std::numbers::pi / 180.0;
  in.centre_distance = 861.0;
  in.x1 = 0.48;
  in.split = gearkit::gear::ShiftSplit::user_x1;
  in.face_width = 360.0;
  return in;
}

}  // namespace gearkit::testing
