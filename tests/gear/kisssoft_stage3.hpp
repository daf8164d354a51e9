#pragma once
// The helical stage of a published KISSsoft 03/2017 report (ISO 6336:2006 method B), shared by
// test_rating.cpp (load capacity), test_inspection.cpp (tolerances and measurements) and
// test_iso6336_scuffing.cpp (scuffing): file
// @NREL_5MW/stage_03.rtf of gfsReboucas/Drivetrain (commit 2a41bf1). m_n = 14 mm, z = 24/95,
// alpha_n = 20 deg, beta = 10 deg, a = 861 mm, x_1 = 0.48 (x_2 = 0.6691 follows), b = 360 mm,
// ISO 53 profile A (1 / 1.25 / 0.38).
#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/gear/rating.hpp>

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

// The report's load (section 0, 2): case-carburized 18CrNiMo7-6 (sigma_Hlim 1500, sigma_Flim 430
// MPa), 5000 kW at 1165.9 1/min, K_A = 1.25, 175 200 h, VG 220, R_z 4.8 um flank / 20 um root,
// S_Hmin = 1.25, S_Fmin = 1.56. Y_F, Y_S "calculated with profile shift x" (the nominal one: no
// allowance here).
inline gearkit::gear::RatingInput kisssoft_stage3_load() {
  namespace gg = gearkit::gear;
  gg::RatingInput r;
  r.n_1 = 12255.788e6 / (60.0 * 175200.0);  // 1165.885 1/min: the report's N_L1 (it prints n rounded, 1165.9)
  r.T_1 = 5.0e6 / (r.n_1 * std::numbers::pi / 30.0);  // 5000 kW: T_1 = 40953.0 N m as printed
  r.K_A = 1.25;
  gg::Material m = gg::material_of_class(gg::MaterialClass::case_carburized, gg::QualityGrade::MQ, 700.0, "18CrNiMo7-6");
  m.sigma_Hlim = 1500.0;
  m.sigma_Flim = 430.0;
  r.material = {m, m};
  r.life_h = 175200.0;
  r.nu_40 = 220.0;
  r.R_z_flank = {4.8, 4.8};
  r.R_z_root = {20.0, 20.0};
  r.S_Hmin = 1.25;
  r.S_Fmin = 1.56;
  // The report's K factors: K_Hbeta user-specified 1.150; K_v = 1.092 and K_Halpha = K_Falpha =
  // 1.069 come from its web-blank factor C_R = 0.898, which gearkit does not model (solid blanks).
  r.factors.set(gg::Factor::K_v, 1.092);
  r.factors.set(gg::Factor::K_Hbeta, 1.150);
  r.factors.set(gg::Factor::K_Halpha, 1.069);
  r.factors.set(gg::Factor::K_Falpha, 1.069);
  return r;
}

}  // namespace gearkit::testing
