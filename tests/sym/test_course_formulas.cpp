// Formulas gearkit writes outside the constraint equations, compared with the ones the course
// writes (sym::equivalent: equal after trigonometric expansion and rational normalisation): the
// cam motion laws (libcam law_formula, gearkit cam's "Motion formulas") and seed 000 problem 2 a.
#include <gearkit/cam/motion_law.hpp>
#include <gearkit/sym/expression.hpp>

#include <run_gearkit.hpp>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

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

namespace {

// `text` with every "u" (the only letter u in these formulas) replaced by `value`.
std::string at(const std::string& text, const std::string& value) {
  std::string out;
  for (char c : text) out += c == 'u' ? "(" + value + ")" : std::string(1, c);
  return out;
}

}  // namespace

// Issue 25: the laws pieced together had no formulas, so "Motion formulas" listed only the dwells
// of a modified-sine program. Each piece against Norton (Design of Machinery, sec. 8.4), his
// decimals written exactly: modified sine 0.43990085 = pi/(4 + pi), 0.0350062 =
// 1/(4 (4 + pi)), 0.31505577 = 9/(4 (4 + pi)), 0.28004957 = 2/(4 + pi), 0.56009915 = 4/(4 + pi);
// modified trapezoid 0.38898448 = 2/(pi + 2), 0.0309544 = 1/(2 pi (pi + 2)), 2.44406184 =
// 4 pi/(pi + 2), 1.6110154 = (2 + 2 pi)/(pi + 2), 4.6660917 = (7 pi + 2)/(pi + 2); parabolic
// 2u^2 and 1 - 2(1 - u)^2. Then, independently of the book: y(0) = 0, y(1) = 1, y and y' continuous
// at every join, y' = 0 at both ends.
TEST(CourseFormulas, PiecedCamLawsPieceByPiece) {
  const std::string ms = "(4+Pi)", mt = "(Pi+2)";
  const std::vector<std::string> sine = {"Pi/" + ms + "*u-1/(4*" + ms + ")*sin(4*Pi*u)",
                                         "2/" + ms + "+Pi/" + ms + "*u-9/(4*" + ms + ")*cos(4*Pi/3*u-Pi/6)",
                                         "4/" + ms + "+Pi/" + ms + "*u-1/(4*" + ms + ")*sin(4*Pi*u-2*Pi)"};
  const std::vector<std::string> trapezoid = {
      "2/" + mt + "*u-1/(2*Pi*" + mt + ")*sin(4*Pi*u)",
      "4*Pi/" + mt + "*u^2+(2-Pi)/" + mt + "*u+(Pi/16-1/(2*Pi))/" + mt,
      "(2+2*Pi)/" + mt + "*u-1/(2*Pi*" + mt + ")*sin(4*Pi*u-Pi)-Pi/(2*" + mt + ")",
      "-4*Pi/" + mt + "*u^2+(7*Pi+2)/" + mt + "*u-(2*Pi+Pi/16-1/(2*Pi))/" + mt,
      "Pi/" + mt + "+2/" + mt + "*u+1/(2*Pi*" + mt + ")*sin(4*Pi*u-3*Pi)"};
  const std::vector<std::string> parabolic = {"2*u^2", "1-2*(1-u)^2"};
  const std::pair<gc::Law, const std::vector<std::string>*> laws[] = {
      {gc::Law::modified_sine, &sine}, {gc::Law::modified_trapezoid, &trapezoid}, {gc::Law::parabolic, &parabolic}};
  for (const auto& [law, book] : laws) {
    const auto pieces = gc::law_pieces(law, "u");
    ASSERT_EQ(pieces.size(), book->size()) << gc::name_of(law);
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      EXPECT_TRUE(equivalent(pieces[k].formula.y, (*book)[k])) << gc::name_of(law) << " " << k << ": " << pieces[k].formula.y;
      if (k == 0) continue;
      // Every join is a multiple of 1/8, written as a fraction: GiNaC keeps it exact.
      const std::string join = fmt::format("{}/8", std::lround(pieces[k].u0 * 8));
      EXPECT_EQ(pieces[k].u0 * 8, std::round(pieces[k].u0 * 8));
      EXPECT_EQ(pieces[k].u0, pieces[k - 1].u1);
      EXPECT_TRUE(equivalent(at(pieces[k].formula.y, join), at(pieces[k - 1].formula.y, join))) << gc::name_of(law) << k;
      EXPECT_TRUE(equivalent(at(pieces[k].formula.dy, join), at(pieces[k - 1].formula.dy, join))) << gc::name_of(law) << k;
    }
    EXPECT_TRUE(equivalent(at(pieces.front().formula.y, "0"), "0"));
    EXPECT_TRUE(equivalent(at(pieces.back().formula.y, "1"), "1")) << gc::name_of(law);
    EXPECT_TRUE(equivalent(at(pieces.front().formula.dy, "0"), "0"));
    EXPECT_TRUE(equivalent(at(pieces.back().formula.dy, "1"), "0"));
  }
  // A single-expression law is one piece over [0, 1], the formula law_formula gives.
  const auto one = gc::law_pieces(gc::Law::cycloidal, "u");
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].formula.y, gc::law_formula(gc::Law::cycloidal, "u")->y);
}

// Issue 25: `gearkit cam` with a modified-sine rise and return listed the two dwells only. Every
// piece is a row now, and the pieces join: the rise's s runs 0 -> 10 mm, the return's 10 -> 0, with
// the joins at 1/8 and 7/8 of each segment (11.25 and 78.75 deg of a 90 deg rise).
TEST(CourseFormulas, ModifiedSineProgramHasItsFormulas) {
  const std::string model =
      "name: modified sine\ncam: {base_radius: 40 mm}\nfollower: {type: translating, contact: roller, roller_radius: 10 mm}\n"
      "motion:\n  - {type: rise, from: 0 deg, to: 90 deg, law: modified_sine, lift: 10 mm}\n"
      "  - {type: dwell, from: 90 deg, to: 180 deg}\n  - {type: return, from: 180 deg, to: 270 deg, law: modified_sine}\n"
      "  - {type: dwell, from: 270 deg, to: 360 deg}\n";
  const std::string path = ::testing::TempDir() + "modified_sine_formulas.yaml";
  std::ofstream(path) << model;
  const auto r = gearkit::testing::run_gearkit("cam " + gearkit::testing::shell_quote(path) + " --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out)["motion_formulas"];
  ASSERT_EQ(j.size(), 8u) << j;  // 3 pieces, dwell, 3 pieces, dwell
  const double ends[] = {0, 11.25, 78.75, 90};
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(j[k]["kind"], "rise");
    EXPECT_EQ(j[k]["law"], "modified_sine");
    EXPECT_EQ(j[k]["piece"], fmt::format("{}/3", k + 1));
    EXPECT_NEAR(j[k]["from_deg"].get<double>(), ends[k], 1e-9);
    EXPECT_NEAR(j[k]["to_deg"].get<double>(), ends[k + 1], 1e-9);
    EXPECT_NEAR(j[k + 4]["from_deg"].get<double>(), 180 + ends[k], 1e-9);
    EXPECT_EQ(j[k + 4]["kind"], "return");
  }
  const auto s = [&](int row, const std::string& theta) {
    std::string text = j[row]["s"].get<std::string>(), out;
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text.compare(i, 5, "theta") == 0) out += "(" + theta + ")", i += 4;
      else out += text[i];
    return out;
  };
  EXPECT_TRUE(equivalent(s(0, "0"), "0")) << s(0, "0");
  EXPECT_TRUE(equivalent(s(0, "Pi/16"), s(1, "Pi/16")));
  EXPECT_TRUE(equivalent(s(1, "7*Pi/16"), s(2, "7*Pi/16")));
  EXPECT_TRUE(equivalent(s(2, "Pi/2"), "10"));
  EXPECT_EQ(j[3]["s"], "10");
  EXPECT_TRUE(equivalent(s(4, "Pi"), "10"));
  EXPECT_TRUE(equivalent(s(5, "Pi+7*Pi/16"), s(6, "Pi+7*Pi/16")));
  EXPECT_TRUE(equivalent(s(6, "3*Pi/2"), "0"));
  // Norton's modified sine at u = 1/2 is 1/2 (symmetric law): 5 mm at 45 deg.
  EXPECT_TRUE(equivalent(s(1, "Pi/4"), "5"));
}
