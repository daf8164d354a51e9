// Formulas gearkit writes outside the constraint equations, compared with the ones the course
// writes (sym::equivalent: equal after trigonometric expansion and rational normalisation): the
// cam motion laws (libcam law_formula, gearkit cam's "Motion formulas") and seed 000 problem 2 a.
#include <gearkit/cam/motion_law.hpp>
#include <gearkit/sym/expression.hpp>

#include <run_gearkit.hpp>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

namespace gc = gearkit::cam;
using gearkit::sym::equivalent;

// Norton, Design of Machinery, ch. 8 (eqs. 8.6, 8.7, 8.11, 8.13, 8.24): the laws' displacement
// and velocity in the normalised u = theta/beta, typed from the book.
TEST(CourseFormulas, CamLawsAsTheTextbookWritesThem) {
  struct Case {
    gc::Law law;
    const char* y;
    const char* dy;
  };
  const Case cases[] = {
      {gc::Law::uniform_velocity, "u", "1"},
      {gc::Law::simple_harmonic, "1/2*(1-cos(Pi*u))", "Pi/2*sin(Pi*u)"},
      {gc::Law::cycloidal, "u-1/(2*Pi)*sin(2*Pi*u)", "1-cos(2*Pi*u)"},
      {gc::Law::polynomial_345, "10*u^3-15*u^4+6*u^5", "30*u^2-60*u^3+30*u^4"},
      {gc::Law::polynomial_4567, "35*u^4-84*u^5+70*u^6-20*u^7", "140*u^3-420*u^4+420*u^5-140*u^6"},
  };
  for (const Case& c : cases) {
    const auto f = gc::law_formula(c.law, "u");
    ASSERT_TRUE(f) << gc::name_of(c.law);
    EXPECT_TRUE(equivalent(f->y, c.y)) << f->y;
    EXPECT_TRUE(equivalent(f->dy, c.dy)) << f->dy;
  }
  EXPECT_FALSE(gc::law_formula(gc::Law::parabolic, "u"));
  EXPECT_FALSE(gc::law_formula(gc::Law::modified_sine, "u"));
}

// Seed 000 (OTM 2015) problem 2 a): the cycloidal rise over [120, 180] deg and return over
// [240, 360] deg of a lift of 1 rad, and their derivatives, as the solution prints them. Its
// return derivative is a slip (docs/seeds.md): differentiating its own Psi gives
// -3/(2 Pi) [1 - cos(3 (theta - 4 Pi/3))]; the printed -3/(2 Pi) [1 - 3/(2 Pi) cos(...)] is not it.
TEST(CourseFormulas, Otm2015Problem2CamFormulas) {
  const auto r = gearkit::testing::run_gearkit("cam examples/cams/otm2015_p2_oscillating_cycloidal.yaml --format json",
                                               "cd " + std::string(GEARKIT_SOURCE_DIR) + " &&");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out)["motion_formulas"];
  ASSERT_EQ(j.size(), 4u);
  const std::string rise = j[1]["s"], rise_d = j[1]["ds_dtheta"], ret = j[3]["s"], ret_d = j[3]["ds_dtheta"];
  EXPECT_TRUE(equivalent(rise, "3/Pi*(theta-2*Pi/3)-1/(2*Pi)*sin(6*(theta-2*Pi/3))")) << rise;
  EXPECT_TRUE(equivalent(rise_d, "3/Pi*(1-cos(6*(theta-2*Pi/3)))")) << rise_d;
  EXPECT_TRUE(equivalent(ret, "1-3/(2*Pi)*(theta-4*Pi/3)+1/(2*Pi)*sin(3*(theta-4*Pi/3))")) << ret;
  EXPECT_TRUE(equivalent(ret_d, "-3/(2*Pi)*(1-cos(3*(theta-4*Pi/3)))")) << ret_d;
  EXPECT_FALSE(equivalent(ret_d, "-3/(2*Pi)*(1-3/(2*Pi)*cos(3*(theta-4*Pi/3)))"));  // the seed's slip
  EXPECT_EQ(j[0]["s"], "0");
  EXPECT_EQ(j[2]["s"], "1");
  EXPECT_EQ(j[1]["unit"], "rad");
}
