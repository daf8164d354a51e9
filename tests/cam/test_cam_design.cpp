// Tests of gearkit/cam/cam_design.hpp: contact geometry against textbook formulas, finite
// differences and geometric identities; validation of impossible designs.
#include <gearkit/cam/cam_design.hpp>

#include "cam_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using namespace gearkit::cam;
using gearkit::cam::testing::oscillating;
using gearkit::cam::testing::rad;
using gearkit::cam::testing::translating;

double dist(Vec2 a, Vec2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

/// Signed curvature of the circle through three points (positive counter-clockwise).
double three_point_curvature(Vec2 a, Vec2 b, Vec2 c) {
  const double cross = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  return 2 * cross / (dist(a, b) * dist(b, c) * dist(a, c));
}

TEST(CamDesign, TranslatingRollerPressureAngleMatchesTheTextbookFormula) {
  // Norton, Design of Machinery, eq. 8.31 (offset roller follower):
  // phi = atan((v - epsilon) / (s + sqrt(Rp^2 - epsilon^2))), v = ds/dtheta, epsilon the offset
  // on the side where the cam surface moves towards the follower (minus sigma e in our frame).
  for (Rotation rot : {Rotation::ccw, Rotation::cw}) {
    const CamDesign d{gearkit::cam::testing::rise_dwell_return(20), translating(Contact::roller, 10, 6), 40, rot};
    validate(d);
    const double sigma = rotation_sign(rot);
    for (double deg = 3; deg < 360; deg += 11) {
      const ContactState c = contact_at(d, rad(deg));
      const double Rp = 50;
      const double expected = std::atan((c.motion.ds - sigma * 6) / (c.motion.s + std::sqrt(Rp * Rp - 36)));
      EXPECT_NEAR(c.pressure_angle, expected, 1e-12) << deg;
    }
  }
}

TEST(CamDesign, PitchPointsAndTangentsAgreeWithFiniteDifferences) {
  const std::vector<CamDesign> designs{
      {gearkit::cam::testing::rise_dwell_return(20), translating(Contact::roller, 10, 5), 40, Rotation::ccw},
      {gearkit::cam::testing::otm2015_program(), oscillating(Contact::roller, 120, 100, 10), 40, Rotation::cw},
      {gearkit::cam::testing::rise_dwell_return(10, Law::polynomial_345), translating(Contact::flat_face), 40,
       Rotation::ccw},
      {gearkit::cam::testing::rise_dwell_return(0.2, Law::polynomial_345), oscillating(Contact::flat_face, 120, 0, 0, 5),
       45, Rotation::cw}};
  const double h = 1e-6;
  for (const CamDesign& d : designs) {
    validate(d);
    for (double deg = 7; deg < 360; deg += 13) {
      const ContactState a = contact_at(d, rad(deg) - h), b = contact_at(d, rad(deg) + h), c = contact_at(d, rad(deg));
      EXPECT_NEAR((b.pitch.x - a.pitch.x) / (2 * h), c.pitch_tangent.x, 1e-4) << deg;
      EXPECT_NEAR((b.pitch.y - a.pitch.y) / (2 * h), c.pitch_tangent.y, 1e-4) << deg;
      // Curvature from three nearby pitch points (sign: convex = turning the way the curve closes).
      const double k = 1e-3;
      const ContactState p0 = contact_at(d, rad(deg) - k), p2 = contact_at(d, rad(deg) + k);
      const double fd = -rotation_sign(d.rotation) * three_point_curvature(p0.pitch, c.pitch, p2.pitch);
      EXPECT_NEAR(fd, c.curvature_pitch, 1e-5 * (1 + std::abs(c.curvature_pitch)) + 2e-6) << deg;
    }
  }
}

TEST(CamDesign, RollerContactIsOneRollerRadiusFromThePitchAlongTheNormal) {
  const CamDesign d{gearkit::cam::testing::otm2015_program(), oscillating(Contact::roller, 120, 100, 10), 40,
                    Rotation::ccw};
  validate(d);
  for (double deg = 0; deg < 360; deg += 10) {
    const ContactState c = contact_at(d, rad(deg));
    EXPECT_NEAR(dist(c.contact, c.pitch), 10, 1e-12);
    const double along = (c.contact.x - c.pitch.x) * c.pitch_tangent.x + (c.contact.y - c.pitch.y) * c.pitch_tangent.y;
    EXPECT_NEAR(along, 0, 1e-9);
    // The contact is on the cam's side: closer to the centre than the roller centre while convex.
    if (c.curvature_pitch > 0) {
      EXPECT_LT(std::hypot(c.contact.x, c.contact.y), std::hypot(c.pitch.x, c.pitch.y));
    }
    // Oscillating: the roller centre stays one arm length from the pivot; fixed frame distance.
    EXPECT_NEAR(dist(c.follower_point, Vec2{120, 0}), 100, 1e-9);
    // Cam frame vs fixed frame: the same distance from the cam centre.
    EXPECT_NEAR(std::hypot(c.pitch.x, c.pitch.y), std::hypot(c.follower_point.x, c.follower_point.y), 1e-9);
  }
  // On the dwell at the base: the roller centre on the prime circle, 50 mm from the centre.
  EXPECT_NEAR(std::hypot(contact_at(d, rad(60)).pitch.x, contact_at(d, rad(60)).pitch.y), 50, 1e-12);
  EXPECT_NEAR(contact_at(d, rad(60)).curvature_pitch, 1.0 / 50, 1e-12);
  EXPECT_NEAR(contact_at(d, rad(60)).curvature_profile, 1.0 / 40, 1e-12);
}

TEST(CamDesign, TranslatingFlatFaceEnvelope) {
  // Textbook results for a translating flat-faced follower (Norton sec. 8.8): the contact lies at
  // x = ds/dtheta from the follower axis (on the side the cam surface comes from) and the
  // profile's radius of curvature is rho = Rb + s + s''.
  for (Rotation rot : {Rotation::ccw, Rotation::cw}) {
    const CamDesign d{gearkit::cam::testing::rise_dwell_return(15, Law::polynomial_345), translating(Contact::flat_face),
                      30, rot};
    validate(d);
    for (double deg = 5; deg < 360; deg += 10) {
      const ContactState c = contact_at(d, rad(deg));
      EXPECT_NEAR(c.face_position, rotation_sign(rot) * c.motion.ds, 1e-12);
      EXPECT_NEAR(1 / c.curvature_profile, 30 + c.motion.s + c.motion.d2s, 1e-9);
      EXPECT_NEAR(c.follower_point.y, 30 + c.motion.s, 1e-12);  // the face height
      EXPECT_EQ(c.pressure_angle, 0);
    }
  }
}

TEST(CamDesign, OscillatingFlatFaceTouchesItsFaceLine) {
  const double a = 120, f = 5;
  const CamDesign d{gearkit::cam::testing::rise_dwell_return(0.2, Law::polynomial_345),
                    oscillating(Contact::flat_face, a, 0, 0, f), 45, Rotation::ccw};
  validate(d);
  const double beta0 = std::asin((f - 45) / a);
  for (double deg = 0; deg < 360; deg += 15) {
    const ContactState c = contact_at(d, rad(deg));
    const double beta = beta0 - c.motion.s;
    // The contact (fixed frame) lies on the face line N.X = f - a sin(beta), N = (-sin, cos).
    const double on_line = -std::sin(beta) * c.follower_point.x + std::cos(beta) * c.follower_point.y;
    EXPECT_NEAR(on_line, f - a * std::sin(beta), 1e-9);
  }
  // At the base dwell the face is tangent to the base circle at the contact.
  const ContactState base = contact_at(d, rad(330));  // inside the last dwell, at the base
  EXPECT_NEAR(std::hypot(base.contact.x, base.contact.y), 45, 1e-9);
  EXPECT_NEAR(1 / base.curvature_profile, 45, 1e-9);
}

std::string design_error_field(const CamDesign& d) {
  try {
    validate(d);
  } catch (const DesignError& e) {
    return e.field();
  }
  return "";
}

TEST(CamDesign, RejectsImpossibleDesigns) {
  const auto p = gearkit::cam::testing::rise_dwell_return(20);
  EXPECT_EQ(design_error_field({p, translating(Contact::roller, 10), 8, Rotation::ccw}), "base_radius");
  EXPECT_EQ(design_error_field({p, translating(Contact::roller, -1), 40, Rotation::ccw}), "roller_radius");
  EXPECT_EQ(design_error_field({p, translating(Contact::roller, 0), 40, Rotation::ccw}), "roller_radius");
  EXPECT_EQ(design_error_field({p, translating(Contact::knife_edge), -5, Rotation::ccw}), "base_radius");
  EXPECT_EQ(design_error_field({p, translating(Contact::knife_edge, 0, 40), 40, Rotation::ccw}), "offset");
  const auto otm = gearkit::cam::testing::otm2015_program();
  // Prime circle 50 mm: a pivot 200 mm away with a 100 mm arm cannot reach it.
  EXPECT_EQ(design_error_field({otm, oscillating(Contact::roller, 200, 100, 10), 40, Rotation::ccw}),
            "pivot_distance");
  EXPECT_EQ(design_error_field({otm, oscillating(Contact::roller, -120, 100, 10), 40, Rotation::ccw}),
            "pivot_distance");
  EXPECT_EQ(design_error_field({otm, oscillating(Contact::roller, 120, 100, 10), 40, Rotation::ccw}), "");
  // An oscillating follower's lift is an angle: 20 (taken as rad) is not a swing.
  EXPECT_EQ(design_error_field({p, oscillating(Contact::roller, 120, 100, 10), 40, Rotation::ccw}), "motion");
}

}  // namespace
