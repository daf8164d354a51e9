// Tests for gearkit/elements/cam_follower.hpp: a cam-rocker built and solved from C++ with no
// YAML, against the closed form of its motion program, and the follower's forces against hand
// calculations.
#include "element_fixtures.hpp"

#include <gearkit/elements/cam_follower.hpp>
#include <gearkit/kin/kinetostatics.hpp>

#include <limits>

namespace gearkit::elements {
namespace {

using namespace testing;

// The cam-rocker of examples/mechanisms/cam_rocker.yaml: a plate cam on O_c turning clockwise
// lifts a rocker pivoted at O_r = (120, 0) mm by 20 deg (cycloidal rise over 120 deg, dwell
// 60 deg, 3-4-5 return over 120 deg, dwell 60 deg); the rocker drives a slider on y = 150 mm
// through a rod EF = 80 mm (rocker arm O_rE = 100 mm).
std::vector<cam::Segment> rocker_program() {
  auto segment = [](cam::SegmentKind kind, double from, double to, cam::Law law, double lift) {
    cam::Segment s;
    s.kind = kind;
    s.start = from * kDeg;
    s.end = to * kDeg;
    s.law = law;
    s.lift = lift * kDeg;
    return s;
  };
  return {segment(cam::SegmentKind::rise, 0, 120, cam::Law::cycloidal, 20),
          segment(cam::SegmentKind::dwell, 120, 180, cam::Law::cycloidal, 0),
          segment(cam::SegmentKind::fall, 180, 300, cam::Law::polynomial_345, 20),
          segment(cam::SegmentKind::dwell, 300, 360, cam::Law::cycloidal, 0)};
}

struct CamRocker {
  kin::Model model;
  int cam, rocker, rod, slider;
};

CamRocker cam_rocker(double cam_angle) {
  CamRocker m;
  kin::Model& model = m.model;
  model.ground().points = {{"Oc", {0, 0}}, {"Or", {0.120, 0}}, {"G", {0.120, 0.150}}};
  m.cam = add_body(model, "cam", {0, 0}, 0.0, {{"Oc", {0, 0}}});
  m.rocker = add_body(model, "rocker", {0.120, 0}, 100 * kDeg, {{"Or", {0, 0}}, {"E", {0.100, 0}}});
  const Eigen::Vector2d E = Eigen::Vector2d(0.120, 0) + 0.100 * Eigen::Vector2d(std::cos(100 * kDeg), std::sin(100 * kDeg));
  m.rod = add_body(model, "rod", E, 40 * kDeg, {{"E", {0, 0}}, {"F", {0.080, 0}}});
  m.slider = add_body(model, "slider", E + 0.080 * Eigen::Vector2d(std::cos(40 * kDeg), std::sin(40 * kDeg)), 0.0,
                      {{"F", {0, 0}}});
  revolute(model, "cam shaft", m.cam, "Oc", kin::kGround, "Oc");
  revolute(model, "rocker pivot", m.rocker, "Or", kin::kGround, "Or");
  revolute(model, "E", m.rocker, "E", m.rod, "E");
  revolute(model, "F", m.rod, "F", m.slider, "F");
  model.add_constraint("guide", std::make_shared<kin::Prismatic>(point(model, m.slider, "F"), point(model, kin::kGround, "G"),
                                                                 Eigen::Vector2d(1, 0), 0.0));
  CamFollowerParameters p;
  p.cam = m.cam;
  p.path = FollowerPath::oscillating;
  p.follower = m.rocker;
  p.base = 100 * kDeg;
  p.clockwise = true;
  p.motion = rocker_program();
  add_cam_follower(model, "cam contact", p);
  drive_angle(model, m.cam, cam_angle, -10.0);
  return m;
}

// Cycloidal rise (Norton, Design of Machinery, eq. 8.12): psi = h (x/beta - sin(2 pi x/beta)/(2 pi)),
// psi' = h/beta (1 - cos(2 pi x/beta)), with x the program angle = sigma theta_cam = -theta_cam.
TEST(CamFollower, CamRockerFromCppMatchesTheMotionProgram) {
  const double h = 20 * kDeg, beta = 120 * kDeg;
  for (const double x_deg : {0.0, 30.0, 60.0, 100.0}) {
    const double x = x_deg * kDeg;
    CamRocker m = cam_rocker(-x);
    kin::Data data(m.model);
    solve_all(m.model, data);
    const double psi = h * (x / beta - std::sin(2 * std::numbers::pi * x / beta) / (2 * std::numbers::pi));
    const double dpsi = h / beta * (1 - std::cos(2 * std::numbers::pi * x / beta));
    const double theta_r = 100 * kDeg + psi;
    EXPECT_NEAR(data.q(3 * m.rocker + 2), theta_r, 1e-10) << x_deg;
    // The cam turns at -10 rad/s: omega_r = psi' dx/dt = psi' * 10 rad/s.
    EXPECT_NEAR(data.qd(3 * m.rocker + 2), 10.0 * dpsi, 1e-9) << x_deg;
    // The slider on y = 150 mm, 80 mm from E, right of it (the drawn branch).
    const Eigen::Vector2d E = Eigen::Vector2d(0.120, 0) + 0.100 * Eigen::Vector2d(std::cos(theta_r), std::sin(theta_r));
    const double x_F = E.x() + std::sqrt(0.080 * 0.080 - (0.150 - E.y()) * (0.150 - E.y()));
    EXPECT_NEAR(data.q(3 * m.slider), x_F, 1e-10) << x_deg;
  }
}

// A torque of 3 N m on the rocker, no masses, at mid-rise (x = 60 deg, psi' = 2 h/beta = 1/3):
// the cam holds the rocker, T_f = -3 N m; the cam shaft needs T = 3 psi' = 1 N m by virtual
// power (T omega_c + T_L omega_r = 0 with omega_r = -psi' omega_c), and T_cam = -1 N m.
TEST(CamFollower, RockerTorqueAndCamTorqueMatchTheHandCalculation) {
  CamRocker m = cam_rocker(-60 * kDeg);
  m.model.add_torque({m.rocker, 3.0, "load"});
  kin::Data data(m.model);
  solve_all(m.model, data);
  const kin::ForceAnalysis f = kin::solve_forces(m.model, data);
  const kin::ConstraintReaction* contact = nullptr;
  for (const auto& r : f.reactions)
    if (r.kind == "cam_follower") contact = &r;
  ASSERT_NE(contact, nullptr);
  EXPECT_NEAR(value_of(contact->values, "T_f"), -3.0, 1e-9);
  EXPECT_NEAR(value_of(contact->values, "T_cam"), -1.0, 1e-9);
  EXPECT_NEAR(f.effort_virtual_power[0], 1.0, 1e-9);
  EXPECT_NEAR(f.effort_lagrange[0], 1.0, 1e-9);
}

// A translating follower of 2 kg pushed up a vertical guide by a cam turning at 10 rad/s with a
// simple harmonic rise of 20 mm over 180 deg, under gravity and a 100 N load pushing it down.
// At 60 deg: s'' = (h/2)(pi/beta)^2 cos(pi theta/beta) = 5 mm/rad^2, a = s'' omega^2 = 0.5 m/s^2,
// s' = (h/2)(pi/beta) sin 60 deg = 8.6603 mm/rad. Contact force along the guide:
// F = m (a + g) + 100 N = 2 (0.5 + 9.81) + 100 = 120.62 N; cam shaft torque F s' = 1.04460 N m.
TEST(CamFollower, TranslatingContactForceMatchesTheHandCalculation) {
  kin::Model model;
  model.ground().points = {{"O", {0, 0}}, {"G", {0, 0}}};
  const int cam_body = add_body(model, "cam", {0, 0}, 0.0, {{"O", {0, 0}}});
  kin::Body follower_body;
  follower_body.name = "follower";
  follower_body.points = {{"P", {0, 0}}};
  follower_body.mass = 2.0;
  follower_body.position_guess = {0, 0.055};
  const int follower = model.add_body(follower_body);
  revolute(model, "cam shaft", cam_body, "O", kin::kGround, "O");
  model.add_constraint("guide", std::make_shared<kin::Prismatic>(point(model, follower, "P"), point(model, kin::kGround, "G"),
                                                                 Eigen::Vector2d(0, 1), 0.0));
  CamFollowerParameters p;
  p.cam = cam_body;
  p.point = point(model, follower, "P");
  p.guide = point(model, kin::kGround, "G");
  p.axis = 90 * kDeg;
  p.base = 0.050;
  cam::Segment rise;
  rise.kind = cam::SegmentKind::rise;
  rise.end = 180 * kDeg;
  rise.law = cam::Law::simple_harmonic;
  rise.lift = 0.020;
  cam::Segment fall = rise;
  fall.kind = cam::SegmentKind::fall;
  fall.start = 180 * kDeg;
  fall.end = 360 * kDeg;
  p.motion = {rise, fall};
  add_cam_follower(model, "cam contact", p);
  drive_angle(model, cam_body, 60 * kDeg, 10.0);
  model.add_force({point(model, follower, "P"), {0, -100.0}, "load"});
  model.set_gravity({0, -9.81});
  kin::Data data(model);
  solve_all(model, data);
  EXPECT_NEAR(data.q(3 * follower + 1), 0.050 + 0.005, 1e-12);  // s = (h/2)(1 - cos 60 deg) = 5 mm
  const kin::ForceAnalysis f = kin::solve_forces(model, data);
  for (const auto& r : f.reactions)
    if (r.kind == "cam_follower") {
      EXPECT_NEAR(value_of(r.values, "F"), 120.62, 1e-9);
      EXPECT_NEAR(value_of(r.values, "T_cam"), -120.62 * 0.01 * std::sin(60 * kDeg), 1e-9);
      EXPECT_NEAR(r.force.y(), 120.62, 1e-9);  // on the follower, along the guide
    }
  EXPECT_NEAR(f.effort_virtual_power[0], 120.62 * 0.01 * std::sin(60 * kDeg), 1e-9);
}

// The field a builder's kin::ElementError names, or "" when it builds.
std::string field_of(const kin::Model& model, const CamFollowerParameters& q) {
  try {
    make_cam_follower(model, q);
  } catch (const kin::ElementError& e) {
    return e.field();
  }
  return "";
}

// The cam-rocker's follower as the drawing tests start from: the program only.
CamFollowerParameters rocker_parameters(const CamRocker& m) {
  CamFollowerParameters p;
  p.cam = m.cam;
  p.path = FollowerPath::oscillating;
  p.follower = m.rocker;
  p.motion = rocker_program();
  return p;
}

TEST(CamFollower, ImpossibleParametersNameTheirField) {
  CamRocker m = cam_rocker(0.0);
  CamFollowerParameters p;
  p.cam = m.cam;
  p.path = FollowerPath::oscillating;
  p.follower = m.cam;
  p.motion = rocker_program();
  EXPECT_EQ(field_of(m.model, p), "follower");
  p.follower = m.rocker;
  EXPECT_EQ(field_of(m.model, p), "");
  p.relative_to = m.rocker;
  EXPECT_EQ(field_of(m.model, p), "relative_to");
  p.relative_to = kin::kGround;
  p.motion.pop_back();  // the program no longer covers the turn
  EXPECT_EQ(field_of(m.model, p), "motion");
  p.cam = 42;
  EXPECT_EQ(field_of(m.model, p), "cam");
  p.cam = m.cam;
  p.motion = rocker_program();
  p.roller_radius = -0.001;
  EXPECT_EQ(field_of(m.model, p), "roller_radius");
  p.roller_radius = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(field_of(m.model, p), "roller_radius");
  p.roller_radius = 0.010;
  p.roller = point(m.model, m.cam, "Oc");  // the roller centre on the cam, not on the rocker
  EXPECT_EQ(field_of(m.model, p), "roller");
  p.roller = point(m.model, m.rocker, "E");
  EXPECT_EQ(field_of(m.model, p), "");
}

// What drawings read: the cam, the roller centre (the rocker's point for an oscillating
// follower, `point` for a translating one) and the roller radius, as given.
TEST(CamFollower, DrawingGivesTheCamAndTheRoller) {
  CamRocker m = cam_rocker(0.0);
  CamFollowerParameters p = rocker_parameters(m);
  EXPECT_FALSE(make_cam_follower(m.model, p)->drawing().cam);  // no roller point: nothing to draw
  p.roller = point(m.model, m.rocker, "E");
  p.roller_radius = 0.012;
  const auto cam = make_cam_follower(m.model, p)->drawing().cam;
  ASSERT_TRUE(cam);
  EXPECT_EQ(cam->cam, m.cam);
  EXPECT_EQ(cam->contact.body, m.rocker);
  EXPECT_EQ(cam->contact.local, Eigen::Vector2d(0.100, 0));
  EXPECT_EQ(cam->roller_radius, 0.012);
  p.path = FollowerPath::translating;
  p.point = point(m.model, m.slider, "F");
  p.guide = point(m.model, kin::kGround, "G");
  p.roller.reset();
  const auto translating = make_cam_follower(m.model, p)->drawing().cam;
  ASSERT_TRUE(translating);
  EXPECT_EQ(translating->contact.body, m.slider);
  EXPECT_EQ(translating->roller_radius, 0.012);
}

// A flat face (docs/kin.md): translating, the line through `point` across the guide, its
// direction axis + 90 deg in the guide's frame; oscillating, through `face_point` at
// `face_angle` in the follower's frame. No roller with it, and the face keys only with face: flat
// on an oscillating follower.
TEST(CamFollower, DrawingGivesTheFlatFace) {
  CamRocker m = cam_rocker(0.0);
  CamFollowerParameters p = rocker_parameters(m);
  p.flat_face = true;
  EXPECT_EQ(field_of(m.model, p), "face_point");
  p.face_point = point(m.model, m.rocker, "E");
  EXPECT_EQ(field_of(m.model, p), "face_angle");
  p.face_angle = 30 * kDeg;
  const auto rocker = make_cam_follower(m.model, p)->drawing().cam;
  ASSERT_TRUE(rocker && rocker->face);
  EXPECT_EQ(rocker->contact.body, m.rocker);
  EXPECT_EQ(rocker->contact.local, Eigen::Vector2d(0.100, 0));
  EXPECT_EQ(rocker->face->frame, m.rocker);
  EXPECT_NEAR(rocker->face->direction.x(), std::cos(30 * kDeg), 1e-15);
  EXPECT_NEAR(rocker->face->direction.y(), std::sin(30 * kDeg), 1e-15);
  p.face_point = point(m.model, m.cam, "Oc");
  EXPECT_EQ(field_of(m.model, p), "face_point");
  p.face_point = point(m.model, m.rocker, "E");
  p.roller_radius = 0.005;
  EXPECT_EQ(field_of(m.model, p), "roller_radius");
  p.roller_radius = 0.0;
  p.roller = point(m.model, m.rocker, "E");
  EXPECT_EQ(field_of(m.model, p), "roller");
  p.roller.reset();
  p.flat_face = false;
  EXPECT_EQ(field_of(m.model, p), "face_point");  // a roller follower has no face
  p.face_point.reset();
  EXPECT_EQ(field_of(m.model, p), "face_angle");
  p.face_angle.reset();
  EXPECT_EQ(field_of(m.model, p), "");
  p.path = FollowerPath::translating;
  p.point = point(m.model, m.slider, "F");
  p.guide = point(m.model, kin::kGround, "G");
  p.axis = 20 * kDeg;
  p.flat_face = true;
  const auto translating = make_cam_follower(m.model, p)->drawing().cam;
  ASSERT_TRUE(translating && translating->face);
  EXPECT_EQ(translating->contact.body, m.slider);
  EXPECT_EQ(translating->face->frame, kin::kGround);
  EXPECT_NEAR(translating->face->direction.x(), std::cos(110 * kDeg), 1e-15);
  EXPECT_NEAR(translating->face->direction.y(), std::sin(110 * kDeg), 1e-15);
  p.face_angle = 0.0;
  EXPECT_EQ(field_of(m.model, p), "face_angle");  // the face of a translating follower is across its guide
}

}  // namespace
}  // namespace gearkit::elements

namespace gearkit::elements {
namespace {

// Phi_q, Phi_t and gamma of both followers against finite differences of their Phi (issue 27,
// item 7). The oscillating follower's gamma, s'' omega_cam^2, was tested by nothing before.
TEST(CamFollower, OscillatingFollowerDerivativesMatchFiniteDifferences) {
  expect_derivatives(cam_rocker(0.0).model, "cam contact");  // clockwise, cycloidal and 3-4-5
  kin::Model model;
  const int cam_body = add_body(model, "cam", {0, 0}, 0.0, {});
  const int rocker = add_body(model, "rocker", {0.1, 0}, 0.0, {});
  const int frame = add_body(model, "frame", {0, 0}, 0.0, {});
  CamFollowerParameters p;
  p.cam = cam_body;
  p.path = FollowerPath::oscillating;
  p.follower = rocker;
  p.relative_to = frame;  // measured from a moving link, counter-clockwise cam
  p.base = 0.4;
  p.cam_zero = 0.3;
  p.motion = rocker_program();
  expect_derivatives(*make_cam_follower(model, p));
}

TEST(CamFollower, TranslatingFollowerDerivativesMatchFiniteDifferences) {
  kin::Model model;
  const int cam_body = add_body(model, "cam", {0, 0}, 0.0, {});
  const int follower = add_body(model, "follower", {0, 0.05}, 0.0, {});
  const int guide = add_body(model, "guide", {0, 0}, 0.0, {});
  CamFollowerParameters p;
  p.cam = cam_body;
  p.point = {follower, {0.01, -0.02}};
  p.guide = {guide, {0.03, 0.0}};  // a guide on a moving link: its rotation enters Phi_q
  p.axis = 80 * kDeg;
  p.base = 0.05;
  p.clockwise = true;
  p.motion = rocker_program();  // lifts read as metres: 20 deg = 0.35 m, large but smooth
  expect_derivatives(*make_cam_follower(model, p));
  p.guide = {kin::kGround, {0.0, 0.0}};
  p.clockwise = false;
  expect_derivatives(*make_cam_follower(model, p));
}

}  // namespace
}  // namespace gearkit::elements
