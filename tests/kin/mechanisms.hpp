#pragma once
// Mechanisms built in code for the solver tests. Each link is drawn in ground coordinates at
// an assembled configuration; its frame is put at its first point with the x axis along
// `angle`, so the local coordinates are exact.
#include <gearkit/kin/model.hpp>

#include <cmath>
#include <initializer_list>
#include <memory>
#include <string>
#include <utility>

namespace gearkit::kin::testing {

inline constexpr double kDeg = M_PI / 180.0;

inline Eigen::Vector2d polar(double length, double angle) { return {length * std::cos(angle), length * std::sin(angle)}; }

/// Adds a body whose points are given in ground coordinates; returns its index.
/// With `mass` > 0 the body's centre of mass is its point `com_point`.
inline int add_link(Model& model, const std::string& name, double angle,
                    std::initializer_list<std::pair<std::string, Eigen::Vector2d>> drawn, double mass = 0.0,
                    const std::string& com_point = "") {
  Body b;
  b.name = name;
  const Eigen::Vector2d origin = drawn.begin()->second;
  for (const auto& [point, at] : drawn) b.points.emplace_back(point, rotate(-angle, at - origin));
  if (mass > 0.0) {
    b.mass = mass;
    b.centre_of_mass = *b.point(com_point);
  }
  b.position_guess = origin;
  b.angle_guess = angle;
  return model.add_body(std::move(b));
}

inline BodyPoint at(const Model& model, int body, const std::string& point) {
  const Body& b = body == kGround ? model.ground() : model.bodies()[static_cast<std::size_t>(body)];
  return {body, *b.point(point)};
}

inline void pin(Model& model, const std::string& name, int a, const std::string& pa, int b, const std::string& pb) {
  model.add_constraint(name, std::make_shared<Revolute>(at(model, a, pa), at(model, b, pb)));
}

/// Four-bar O2 A B O4 with O2 at the origin and O4 at (d, 0), drawn at crank angle theta2 on
/// the open branch (B above the line O2 O4 for the test lengths). Driver: crank angle
/// relative to ground with speed omega2 and acceleration alpha2. Bodies: crank 0, coupler 1,
/// rocker 2.
struct FourBarDims {
  double a, b, c, d;  // crank, coupler, rocker, ground [m]
};

/// Freudenstein-style closed form (Norton, Design of Machinery, eqs. 4.10): the open-branch
/// theta4 and theta3 for crank angle theta2.
inline std::pair<double, double> four_bar_closed_form(const FourBarDims& f, double theta2) {
  const double K1 = f.d / f.a, K2 = f.d / f.c, K3 = (f.a * f.a - f.b * f.b + f.c * f.c + f.d * f.d) / (2 * f.a * f.c);
  const double K4 = f.d / f.b, K5 = (f.c * f.c - f.d * f.d - f.a * f.a - f.b * f.b) / (2 * f.a * f.b);
  const double A = std::cos(theta2) - K1 - K2 * std::cos(theta2) + K3;
  const double B = -2 * std::sin(theta2);
  const double C = K1 - (K2 + 1) * std::cos(theta2) + K3;
  const double D = std::cos(theta2) - K1 + K4 * std::cos(theta2) + K5;
  const double E = -2 * std::sin(theta2);
  const double F = K1 + (K4 - 1) * std::cos(theta2) + K5;
  const double theta4 = 2 * std::atan((-B - std::sqrt(B * B - 4 * A * C)) / (2 * A));
  const double theta3 = 2 * std::atan((-E - std::sqrt(E * E - 4 * D * F)) / (2 * D));
  return {theta3, theta4};
}

inline Model four_bar(const FourBarDims& f, double theta2, Motion motion = {1.0, 0.0}) {
  Model m;
  m.ground().points = {{"O2", {0, 0}}, {"O4", {f.d, 0}}};
  const auto [theta3, theta4] = four_bar_closed_form(f, theta2);
  const Eigen::Vector2d A = polar(f.a, theta2), B = A + polar(f.b, theta3);
  const int crank = add_link(m, "crank", theta2, {{"O2", {0, 0}}, {"A", A}});
  const int coupler = add_link(m, "coupler", theta3, {{"A", A}, {"B", B}});
  const int rocker = add_link(m, "rocker", theta4, {{"O4", {f.d, 0}}, {"B", B}});
  pin(m, "O2", crank, "O2", kGround, "O2");
  pin(m, "A", crank, "A", coupler, "A");
  pin(m, "B", coupler, "B", rocker, "B");
  pin(m, "O4", rocker, "O4", kGround, "O4");
  const int drv = m.add_constraint("input", std::make_shared<AngleDriver>(crank, kGround, motion));
  m.set_driver(drv, DriverQuantity::angle, theta2);
  return m;
}

/// A chain of n four-bars of dimensions f, each rocker driving the next loop as its crank:
/// loop k has its ground pivots at (k d, 0) and ((k + 1) d, 0); the rocker of loop k carries,
/// on its own axis, the crank end "A" (at distance a from its pivot) of loop k + 1. So the crank
/// angle of loop k + 1 is the rocker angle of loop k, and loop by loop the open-branch closed
/// form gives every angle. Drawn at input angle theta2 on the open branch; driver on the first
/// crank (unit speed). Bodies: crank 0, then (coupler, rocker) per loop; 3 (2n + 1) coordinates.
inline Model four_bar_chain(const FourBarDims& f, int n, double theta2 = 0.0) {
  Model m;
  int crank = -2;
  double crank_angle = theta2;
  for (int k = 0; k < n; ++k) {
    const std::string i = std::to_string(k), next = std::to_string(k + 1);
    const Eigen::Vector2d o2(k * f.d, 0.0), o4((k + 1) * f.d, 0.0);
    m.ground().points.emplace_back("O" + next, o4);
    const auto [theta3, theta4] = four_bar_closed_form(f, crank_angle);
    const Eigen::Vector2d A = o2 + polar(f.a, crank_angle), B = A + polar(f.b, theta3);
    if (k == 0) {
      m.ground().points.emplace_back("O0", o2);
      crank = add_link(m, "crank", crank_angle, {{"O0", o2}, {"A0", A}});
      pin(m, "O0", crank, "O0", kGround, "O0");
    }
    const int coupler = add_link(m, "coupler" + i, theta3, {{"A", A}, {"B", B}});
    const int rocker = add_link(m, "rocker" + i, theta4, {{"O", o4}, {"B", B}, {"A" + next, o4 + polar(f.a, theta4)}});
    pin(m, "A" + i, crank, "A" + i, coupler, "A");
    pin(m, "B" + i, coupler, "B", rocker, "B");
    pin(m, "O" + next, rocker, "O", kGround, "O" + next);
    crank = rocker;
    crank_angle = theta4;
  }
  const int drv = m.add_constraint("input", std::make_shared<AngleDriver>(0, kGround, Motion{1.0, 0.0}));
  m.set_driver(drv, DriverQuantity::angle, theta2);
  return m;
}

/// A chain of n parallelograms with a redundant middle link in each: loop k has ground pivots
/// O_k = (k d, 0) and O_{k+1}; crank O_k A_k and rocker O_{k+1} B_k of length a at angle theta,
/// coupler A_k B_k (length d, horizontal), and a middle link of length a from M_k = ((k + 1/2) d,
/// 0) to the coupler's midpoint C_k, parallel to the cranks. The rocker of loop k is the crank
/// of loop k + 1 (its end B_k is A_{k+1}). Drawn exactly assembled at theta. Each loop adds 3
/// bodies and 5 revolutes (9 - 10 = -1), the first crank 3 - 2: Gruebler 1 - n, yet the chain
/// moves with one freedom, so n constraint rows are redundant (one per middle link: the
/// textbook parallelogram with a third parallel link). Bodies: crank 0, then coupler, rocker,
/// middle per loop. Driver on the first crank.
inline Model parallelogram_chain(int n, double a, double d, double theta) {
  Model m;
  m.ground().points = {{"O0", {0, 0}}};
  const Eigen::Vector2d r = polar(a, theta);
  int crank = add_link(m, "crank", theta, {{"O", {0, 0}}, {"A", r}});
  pin(m, "O0", crank, "O", kGround, "O0");
  for (int k = 0; k < n; ++k) {
    const std::string i = std::to_string(k);
    const Eigen::Vector2d o2(k * d, 0.0), o4((k + 1) * d, 0.0), mid((k + 0.5) * d, 0.0);
    m.ground().points.emplace_back("O" + std::to_string(k + 1), o4);
    m.ground().points.emplace_back("M" + i, mid);
    const int coupler = add_link(m, "coupler" + i, 0.0, {{"A", o2 + r}, {"C", mid + r}, {"B", o4 + r}});
    const int rocker = add_link(m, "rocker" + i, theta, {{"O", o4}, {"A", o4 + r}});
    const int middle = add_link(m, "middle" + i, theta, {{"M", mid}, {"C", mid + r}});
    pin(m, "A" + i, crank, "A", coupler, "A");
    pin(m, "B" + i, coupler, "B", rocker, "A");
    pin(m, "O" + std::to_string(k + 1), rocker, "O", kGround, "O" + std::to_string(k + 1));
    pin(m, "M" + i, middle, "M", kGround, "M" + i);
    pin(m, "C" + i, middle, "C", coupler, "C");
    crank = rocker;
  }
  const int drv = m.add_constraint("input", std::make_shared<AngleDriver>(0, kGround, Motion{1.0, 0.0}));
  m.set_driver(drv, DriverQuantity::angle, theta);
  return m;
}

/// Seed 004 (exam 2020-21, exercise 1), the pantograph: O at the origin, crank OP (l1), coupler
/// Q-P-R (QP = l3), slider Q on the vertical line x = d, parallelogram O P R S, output arm R-S-T.
/// Dimensions implied by the seed's answers: l1 + l3 = 400 mm and d = 200 mm (s_max =
/// sqrt((l1+l3)^2 - d^2) = 346.4 mm with phi1 = -60 deg), l1/l3 = 0.6 (the velocity ratio) ->
/// l1 = 150 mm, l3 = 250 mm. Our choices: R 100 mm from P square to QP (a straight Q-P-R would
/// flatten the parallelogram O P R S exactly at the dead point, a bifurcation) and ST = 60 mm.
/// Drawn at phi1 = `phi1` on the branch with Q below O. Bodies: crank 0, coupler 1, slider 2,
/// arm RT 3, link OS 4. Driver: the crank angle (or the slider displacement if drive_slider).
inline Model pantograph(double phi1, bool drive_slider = false, double slider_value = 0.3) {
  const double l1 = 0.150, l3 = 0.250, d = 0.200, pr = 0.100;
  Model m;
  m.ground().points = {{"O", {0, 0}}, {"G", {d, 0}}};
  const Eigen::Vector2d P = polar(l1, phi1);
  // Q = (d, -s) with |Q - P| = l3, the lower solution.
  const double s = -P.y() + std::sqrt(l3 * l3 - (d - P.x()) * (d - P.x()));
  const Eigen::Vector2d Q(d, -s);
  const Eigen::Vector2d u = (P - Q).normalized();
  const Eigen::Vector2d R = P + pr * perp(u);
  const Eigen::Vector2d S = R - P;  // O S parallel and equal to P R
  const Eigen::Vector2d T = S + (S - R).normalized() * 0.060;
  const int crank = add_link(m, "crank", phi1, {{"O", {0, 0}}, {"P", P}});
  const double coupler_angle = std::atan2(u.y(), u.x());
  const int coupler = add_link(m, "coupler", coupler_angle, {{"Q", Q}, {"P", P}, {"R", R}});
  const int slider = add_link(m, "slider", 0.0, {{"Q", Q}});
  const double arm_angle = std::atan2((T - R).y(), (T - R).x());
  const int arm = add_link(m, "arm", arm_angle, {{"R", R}, {"S", S}, {"T", T}});
  const int link = add_link(m, "link", std::atan2(S.y(), S.x()), {{"O", {0, 0}}, {"S", S}});
  pin(m, "O_crank", crank, "O", kGround, "O");
  pin(m, "P", crank, "P", coupler, "P");
  pin(m, "Q", coupler, "Q", slider, "Q");
  pin(m, "R", coupler, "R", arm, "R");
  pin(m, "S", arm, "S", link, "S");
  pin(m, "O_link", link, "O", kGround, "O");
  // Slider on the vertical guide through G, axis pointing down so that s is positive.
  m.add_constraint("guide", std::make_shared<Prismatic>(BodyPoint{slider, {0, 0}}, BodyPoint{kGround, {d, 0}},
                                                        Eigen::Vector2d(0, -1), 0.0));
  if (drive_slider) {
    const int drv = m.add_constraint("input", std::make_shared<DisplacementDriver>(
                                                  BodyPoint{slider, {0, 0}}, BodyPoint{kGround, {d, 0}},
                                                  Eigen::Vector2d(0, -1), Motion{1.0, 0.0}));
    m.set_driver(drv, DriverQuantity::displacement, slider_value);
  } else {
    const int drv = m.add_constraint("input", std::make_shared<AngleDriver>(crank, kGround, Motion{1.0, 0.0}));
    m.set_driver(drv, DriverQuantity::angle, phi1);
  }
  return m;
}

/// Seed 004 (exam 2021, exercise 2), the lifting platform: parallelogram O1 P R O2 (arms l1,
/// platform P R), rod P Q (l2) and lever O2 Q T (O2Q = l3) driven by the torque T_m. The figure
/// is missing; the answers fix l3 and the load: F_PQ = T_m / (l3 sin(phi2 + phi3)) with
/// 113.4 N m and 445.1 N gives l3 = 275 mm, and T_m = m g l3 cos(phi1) sin(phi2+phi3) /
/// sin(phi2+phi1) then gives m = 50 kg (g = 9.81 m/s^2). Our choices: O2 straight above O1
/// (d = 0, a vertical mast), l1 = 400 mm, and l2, h from the loop equations at the exam's
/// configuration phi = (30, 42.6, 69.5) deg. Bodies: arm1 0, arm2 1, platform 2, rod 3, lever 4;
/// driver: lever angle phi3. The load hangs at `load_offset` from P on the platform.
/// The driver speed is zero: the seed's analysis is quasi-static.
inline Model lifting_platform(double phi3, Eigen::Vector2d load_offset = {0.3, 0.1}) {
  const double l1 = 0.400, l3 = 0.275, phi1 = 30 * kDeg, phi2 = 42.6 * kDeg, phi3_0 = 69.5 * kDeg;
  const double l2 = (l1 * std::cos(phi1) - l3 * std::cos(phi3_0)) / std::cos(phi2);
  const double h = l1 * std::sin(phi1) + l2 * std::sin(phi2) - l3 * std::sin(phi3_0);
  Model m;
  const Eigen::Vector2d O1(0, 0), O2(0, h);
  m.ground().points = {{"O1", O1}, {"O2", O2}};
  const Eigen::Vector2d P = polar(l1, phi1), R = O2 + polar(l1, phi1);
  const Eigen::Vector2d Q = P + Eigen::Vector2d(-l2 * std::cos(phi2), l2 * std::sin(phi2));
  const Eigen::Vector2d T = O2 + polar(1.3 * l3, phi3_0);
  const int arm1 = add_link(m, "arm1", phi1, {{"O1", O1}, {"P", P}});
  const int arm2 = add_link(m, "arm2", phi1, {{"O2", O2}, {"R", R}});
  const int platform = add_link(m, "platform", M_PI / 2, {{"P", P}, {"R", R}, {"load", P + load_offset}}, 50.0, "load");
  const int rod = add_link(m, "rod", M_PI - phi2, {{"P", P}, {"Q", Q}});
  const int lever = add_link(m, "lever", phi3_0, {{"O2", O2}, {"Q", Q}, {"T", T}});
  pin(m, "O1", arm1, "O1", kGround, "O1");
  pin(m, "O2_arm", arm2, "O2", kGround, "O2");
  pin(m, "O2_lever", lever, "O2", kGround, "O2");
  pin(m, "P_platform", arm1, "P", platform, "P");
  pin(m, "P_rod", rod, "P", arm1, "P");
  pin(m, "R", arm2, "R", platform, "R");
  pin(m, "Q", rod, "Q", lever, "Q");
  const int drv = m.add_constraint("input", std::make_shared<AngleDriver>(lever, kGround, Motion{0.0, 0.0}));
  m.set_driver(drv, DriverQuantity::angle, phi3);
  m.set_gravity({0.0, -9.81});
  return m;
}

/// Seed 004 (exam 2020-21 second paper, exercise 2), the spring-compressing mechanism, upper half
/// (the lower half is its mirror image and doubles the forces on the bar RP). Crank O1 P (l1,
/// phi1 from the vertical, clockwise), rod P Q (l2, phi2), lever V2 Q O2 (O2Q = l3,
/// O2V2 = l3 + l4, phi3). The figure is missing; the answers fix the ratios: F_PQ / F_m =
/// ((l3 + l4)/l3) cos(phi3)/sin(phi2 - phi3) with 1112 / 441.8 gives (l3 + l4)/l3 = 20/11, and
/// F_m = T l3 sin(phi2 - phi3) / (2 l1 (l3 + l4) cos(phi3) cos(phi2 - phi1)) (the seed prints
/// it without the l1, which the units require) with T = 20 N m gives l1 = 9 mm. Our choices:
/// l3 = 55 mm, l4 = 45 mm, l2 = 50 mm, O2 from the loop equations at phi = (43.76, 46.24, 0) deg.
/// Bodies: crank 0, rod 1, lever 2; driver: crank angle (= 90 deg - phi1, counter-clockwise).
inline Model spring_compressor(double crank_angle) {
  const double l1 = 0.009, l2 = 0.050, l3 = 0.055, l4 = 0.045;
  const double phi1 = 43.76 * kDeg, phi2 = 46.24 * kDeg, phi3 = 0.0;
  const Eigen::Vector2d O1(0, 0);
  const Eigen::Vector2d P = l1 * Eigen::Vector2d(std::sin(phi1), std::cos(phi1));
  const Eigen::Vector2d Q = P + l2 * Eigen::Vector2d(-std::cos(phi2), std::sin(phi2));
  const Eigen::Vector2d O2 = Q + l3 * Eigen::Vector2d(std::cos(phi3), -std::sin(phi3));
  const Eigen::Vector2d V = O2 - (l3 + l4) * Eigen::Vector2d(std::cos(phi3), -std::sin(phi3));
  Model m;
  m.ground().points = {{"O1", O1}, {"O2", O2}};
  const int crank = add_link(m, "crank", M_PI / 2 - phi1, {{"O1", O1}, {"P", P}});
  const int rod = add_link(m, "rod", M_PI - phi2, {{"P", P}, {"Q", Q}});
  const int lever = add_link(m, "lever", M_PI - phi3, {{"O2", O2}, {"Q", Q}, {"V", V}});
  pin(m, "O1", crank, "O1", kGround, "O1");
  pin(m, "P", crank, "P", rod, "P");
  pin(m, "Q", rod, "Q", lever, "Q");
  pin(m, "O2", lever, "O2", kGround, "O2");
  const int drv = m.add_constraint("input", std::make_shared<AngleDriver>(crank, kGround, Motion{1.0, 0.0}));
  m.set_driver(drv, DriverQuantity::angle, crank_angle);
  return m;
}

}  // namespace gearkit::kin::testing
