// Tests for gearkit/gear/materials.hpp: ISO 6336-5:2016 endurance limits and the named materials.
#include <gearkit/gear/materials.hpp>

#include <gtest/gtest.h>

#include <stdexcept>

namespace gg = gearkit::gear;

TEST(Materials, CaseCarburizedLimitsOfIso6336_5) {
  // ISO 6336-5:2016 Figures 9 and 10 (case-carburized wrought steel): sigma_Hlim = 1300 / 1500 /
  // 1650 MPa for ML / MQ / ME; ISO/TR 6336-30 example 1 uses 1500 MPa for 18CrNiMo7-6 (MQ).
  EXPECT_DOUBLE_EQ(gg::sigma_Hlim_of(gg::MaterialClass::case_carburized, gg::QualityGrade::ML, 700), 1300.0);
  EXPECT_DOUBLE_EQ(gg::sigma_Hlim_of(gg::MaterialClass::case_carburized, gg::QualityGrade::MQ, 700), 1500.0);
  EXPECT_DOUBLE_EQ(gg::sigma_Hlim_of(gg::MaterialClass::case_carburized, gg::QualityGrade::ME, 700), 1650.0);
  const auto m = gg::material_by_name("18CrNiMo7-6");
  EXPECT_DOUBLE_EQ(m.sigma_Hlim, 1500.0);
  EXPECT_DOUBLE_EQ(m.E, 206000.0);
}

TEST(Materials, ThroughHardenedLineIsLinearInHardness) {
  // ISO 6336-5 Table 1, through-hardened alloy steel ME: sigma_Hlim = 2.213 HV + 260, sigma_Flim =
  // 0.358 HV + 231 (also transcribed in waa552/fyp-website data.js); MQ: 1.313 HV + 373.
  const double a = gg::sigma_Hlim_of(gg::MaterialClass::through_hardened_alloy, gg::QualityGrade::ME, 250);
  const double b = gg::sigma_Hlim_of(gg::MaterialClass::through_hardened_alloy, gg::QualityGrade::ME, 300);
  EXPECT_NEAR((b - a) / 50.0, 2.213, 1e-12);
  EXPECT_NEAR(b, 2.213 * 300 + 260, 1e-9);
  EXPECT_NEAR(gg::sigma_Flim_of(gg::MaterialClass::through_hardened_alloy, gg::QualityGrade::ME, 300), 0.358 * 300 + 231, 1e-9);
  EXPECT_NEAR(gg::sigma_Hlim_of(gg::MaterialClass::through_hardened_alloy, gg::QualityGrade::MQ, 300), 1.313 * 300 + 373, 1e-9);
  // Through-hardened carbon steel ME: 0.838 HV + 432 / 0.283 HV + 202.
  EXPECT_NEAR(gg::sigma_Hlim_of(gg::MaterialClass::through_hardened_carbon, gg::QualityGrade::ME, 200), 0.838 * 200 + 432, 1e-9);
  // Clamped to the figure's hardness range.
  EXPECT_DOUBLE_EQ(gg::sigma_Hlim_of(gg::MaterialClass::through_hardened_alloy, gg::QualityGrade::ME, 1000),
                   gg::sigma_Hlim_of(gg::MaterialClass::through_hardened_alloy, gg::QualityGrade::ME, 390));
}

TEST(Materials, ClassFormAndErrors) {
  const auto m = gg::material_by_name("through-hardened-alloy:MQ:300");
  EXPECT_EQ(m.kind, gg::MaterialClass::through_hardened_alloy);
  EXPECT_DOUBLE_EQ(m.sigma_Hlim, gg::sigma_Hlim_of(m.kind, m.grade, 300));
  EXPECT_THROW(gg::material_by_name("unobtainium"), std::invalid_argument);
  EXPECT_THROW(gg::material_by_name("case-carburized:MX:700"), std::invalid_argument);
  EXPECT_THROW(gg::material_by_name("case-carburized:MQ:200"), std::invalid_argument);  // below 600 HV
  EXPECT_THROW(gg::material_by_name("case-carburized:MQ:abc"), std::invalid_argument);
  gg::Material bad = m;
  bad.nu = 0.6;
  EXPECT_THROW(gg::validate(bad), std::invalid_argument);
  EXPECT_GE(gg::material_names().size(), 10u);
}
