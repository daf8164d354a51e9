// Contact geometry by kinematic inversion: the cam stands still and the follower turns about the
// cam centre by -theta (in the cam's turning sense). With p(theta) a follower point in the fixed
// frame, its image in the cam frame is P = R(-sigma theta) p, so
//   R(sigma theta) dP/dtheta   = q  = p' - sigma J p,
//   R(sigma theta) d2P/dtheta2 = q2 = p'' - sigma J p' - sigma J q,
// with J the rotation by +90 deg and sigma = +1 for a counter-clockwise cam. Pressure angle and
// curvature are invariant under the rotation, so they are computed from q and q2 directly.
#include <gearkit/cam/cam_design.hpp>

#include "program_extremum.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace gearkit::cam {
namespace {

constexpr double pi = std::numbers::pi;

Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
Vec2 operator*(double k, Vec2 a) { return {k * a.x, k * a.y}; }
double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
double norm(Vec2 a) { return std::hypot(a.x, a.y); }
Vec2 J(Vec2 a) { return {-a.y, a.x}; }
Vec2 rotate(Vec2 a, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * a.x - s * a.y, s * a.x + c * a.y};
}

double prime_radius(const CamDesign& d) {
  return d.base_radius + (d.follower.contact == Contact::roller ? d.follower.roller_radius : 0);
}

/// Angle gamma_0 at the pivot between the line to the cam centre and the arm, with the roller
/// centre on the prime circle (law of cosines).
double gamma_0(const CamDesign& d) {
  const double a = d.follower.pivot_distance, L = d.follower.arm_length, Rp = prime_radius(d);
  return std::acos((a * a + L * L - Rp * Rp) / (2 * a * L));
}

/// Arm angle beta_0 of an oscillating flat face touching the base circle: the face line
/// N.X = f - a sin(beta) at distance base_radius from the centre.
double beta_0(const CamDesign& d) {
  return std::asin((d.follower.face_offset - d.base_radius) / d.follower.pivot_distance);
}

/// Point, first and second derivative of the follower point in the fixed frame.
struct FixedFrame {
  Vec2 p, dp, d2p;
  Vec2 path;  // unit direction in which the follower point moves when s grows
  Vec2 dpds;  // d(point)/ds
};

bool on_second_roller(const CamDesign& d) { return d.follower.surface == Surface::conjugate_cam; }

/// The roller centre (knife tip) of the first roller, or of the second one on the conjugate cam.
FixedFrame roller_centre(const CamDesign& d, const Motion& m) {
  const Follower& f = d.follower;
  const bool second = on_second_roller(d);
  if (f.motion == FollowerMotion::translating) {
    const double Rp = prime_radius(d);
    const double s0 = std::sqrt(Rp * Rp - f.offset * f.offset) - (second ? f.second.distance : 0);
    return {{f.offset, s0 + m.s}, {0, m.ds}, {0, m.d2s}, {0, 1}, {0, 1}};
  }
  const double a = f.pivot_distance, L = second ? f.second.arm_length : f.arm_length;
  const double g = gamma_0(d) + m.s + (second ? f.second.arm_angle : 0);
  const Vec2 dC{L * std::sin(g), L * std::cos(g)};
  const Vec2 d2C{L * std::cos(g), -L * std::sin(g)};
  return {{a - L * std::cos(g), L * std::sin(g)}, m.ds * dC, (m.ds * m.ds) * d2C + m.d2s * dC,
          {std::sin(g), std::cos(g)}, dC};
}

double roller_radius_of(const CamDesign& d) {
  if (d.follower.contact != Contact::roller) return 0;
  if (on_second_roller(d) && d.follower.second.roller_radius > 0) return d.follower.second.roller_radius;
  return d.follower.roller_radius;
}

void pitch_follower(const CamDesign& d, ContactState& c) {
  const double sigma = rotation_sign(d.rotation);
  const FixedFrame f = roller_centre(d, c.motion);
  const Vec2 q = f.dp - sigma * J(f.p);
  const Vec2 q2 = f.d2p - sigma * J(f.dp) - sigma * J(q);
  const double qn = norm(q);
  c.follower_point = f.p;
  c.pitch = rotate(f.p, -sigma * c.theta);
  c.pitch_tangent = rotate(q, -sigma * c.theta);
  c.pressure_angle = std::atan2(dot(q, f.path), std::abs(cross(q, f.path)));
  // The pitch curve runs clockwise for a counter-clockwise cam: convex = negative cross product.
  c.curvature_pitch = -sigma * cross(q, q2) / (qn * qn * qn);
  const double Rr = roller_radius_of(d);
  // The wall: +1 the cam (inner wall of a groove), -1 the groove's outer wall, which lies beyond
  // the roller and touches it from outside.
  const double w = d.follower.surface == Surface::groove_outer_wall ? -1 : 1;
  const Vec2 outward_fixed = (sigma / qn) * J(q);  // from the cam side of the pitch curve outwards
  c.normal = w * outward_fixed;
  c.contact_fixed = f.p - Rr * c.normal;
  c.contact = rotate(c.contact_fixed, -sigma * c.theta);
  // Curvature of the wall as the roller sees it (> 0 convex towards the roller).
  const double denominator = 1 - w * Rr * c.curvature_pitch;
  c.curvature_profile = denominator == 0 ? INFINITY : w * c.curvature_pitch / denominator;
  c.folds = Rr > 0 && w * Rr * c.curvature_pitch >= 1;
  c.point_per_s = f.dpds;
  c.spin_per_s = d.follower.motion == FollowerMotion::oscillating ? -1 : 0;
}

/// Flat faces: the profile is the envelope of the face lines N.X = h in the cam frame. With the
/// normal's angle alpha(theta): X = h n + (dh/dalpha) J n and rho = h + d2h/dalpha2.
void flat_follower(const CamDesign& d, ContactState& c) {
  const double sigma = rotation_sign(d.rotation);
  const Motion& m = c.motion;
  Vec2 N, u;
  double h, dh, d2h, dalpha, d2alpha;
  if (d.follower.motion == FollowerMotion::translating) {
    N = {0, 1};
    u = {1, 0};
    h = d.base_radius + m.s, dh = m.ds, d2h = m.d2s;
    dalpha = -sigma, d2alpha = 0;
  } else {
    const double a = d.follower.pivot_distance;
    const double beta = beta_0(d) - m.s;
    N = {-std::sin(beta), std::cos(beta)};
    u = {std::cos(beta), std::sin(beta)};
    h = d.follower.face_offset - a * std::sin(beta);
    dh = a * std::cos(beta) * m.ds;
    d2h = a * (std::sin(beta) * m.ds * m.ds + std::cos(beta) * m.d2s);
    dalpha = -m.ds - sigma, d2alpha = -m.d2s;
  }
  c.envelope_regular = dalpha * (-sigma) > 0;
  const double h_alpha = dh / dalpha;
  const double rho = h + (d2h * dalpha - dh * d2alpha) / (dalpha * dalpha * dalpha);
  const Vec2 X = h * N + h_alpha * J(N);
  c.follower_point = X;
  c.contact = rotate(X, -sigma * c.theta);
  c.pitch = c.contact;
  c.pitch_tangent = rotate((rho * dalpha) * J(N), -sigma * c.theta);
  c.curvature_profile = rho == 0 ? INFINITY : 1 / rho;
  c.curvature_pitch = c.curvature_profile;
  c.folds = !c.envelope_regular || !(c.curvature_profile > 0);
  c.contact_fixed = X;
  c.normal = N;
  if (d.follower.motion == FollowerMotion::translating) {
    c.face_position = X.x - d.follower.offset;
    c.pressure_angle = 0;  // the face normal is the direction of travel
    c.point_per_s = {0, 1};
  } else {
    const Vec2 A{d.follower.pivot_distance, 0};
    c.face_position = dot(X - A, u);
    const Vec2 path = J(X - A);
    c.pressure_angle = std::atan2(std::abs(cross(N, path)), std::abs(dot(N, path)));
    c.spin_per_s = -1;  // the face turns by -psi (beta = beta_0 - psi)
    c.point_per_s = c.spin_per_s * path;
  }
}

void require(bool ok, const char* field, const std::string& message) {
  if (!ok) throw DesignError(field, message);
}

/// A groove or a conjugate cam needs rollers; the second roller must stay clear of the cam
/// centre and push the follower back (its lever n . dp/ds < 0 all round: the conjugate cam can
/// only push, like the first).
void validate_closure(const CamDesign& d) {
  const Follower& f = d.follower;
  if (f.closure == Closure::spring) return;
  require(f.contact == Contact::roller, "closure",
          "a groove or conjugate cam needs a roller follower (contact: roller)");
  if (f.closure != Closure::conjugate) return;
  const SecondRoller& r = f.second;
  require(std::isfinite(r.roller_radius) && r.roller_radius >= 0, "second_roller",
          fmt::format("expected a second roller radius >= 0, found {:.6g} mm", r.roller_radius));
  if (f.motion == FollowerMotion::translating) {
    require(std::isfinite(r.distance) && r.distance > 0, "second_roller",
            fmt::format("expected a distance between the rollers > 0, found {:.6g} mm", r.distance));
  } else {
    require(std::isfinite(r.arm_length) && r.arm_length > 0, "second_roller",
            fmt::format("expected a second arm length > 0, found {:.6g} mm", r.arm_length));
    require(std::isfinite(r.arm_angle), "second_roller", "expected a finite angle between the arms");
  }
  const CamDesign second = conjugate_cam_of(d);
  const double R2 = roller_radius_of(second);
  auto clearance = [&](double theta) {  // the second roller must not reach the cam's centre
    const ContactState c = contact_at(second, theta);
    return -(norm(c.follower_point) - R2);
  };
  const detail::Peak worst = detail::maximum_over_turn(d.program, clearance, 360);
  require(-worst.value > 0, "second_roller",
          fmt::format("the second roller reaches the cam centre at cam angle {:.6g} deg: no conjugate cam fits "
                      "(move the second roller away)", worst.x * 180 / pi));
  auto lever = [&](double theta) {
    const ContactState c = contact_at(second, theta);
    return dot(c.normal, c.point_per_s);
  };
  const detail::Peak same_way = detail::maximum_over_turn(d.program, lever, 360);
  require(same_way.value < 0, "second_roller",
          fmt::format("the second roller does not close the joint: at cam angle {:.6g} deg its cam would push the "
                      "follower the same way as the first (put it on the other side of the cam centre)",
                      same_way.x * 180 / pi));
}

void validate_geometry(const CamDesign& d);

}  // namespace

void validate(const CamDesign& d) {
  validate_geometry(d);
  validate_closure(d);
}

namespace {

void validate_geometry(const CamDesign& d) {
  const Follower& f = d.follower;
  require(std::isfinite(d.base_radius) && d.base_radius > 0, "base_radius",
          fmt::format("expected a base circle radius > 0, found {:.6g} mm", d.base_radius));
  require(std::isfinite(f.roller_radius) && f.roller_radius >= 0, "roller_radius",
          fmt::format("expected a roller radius >= 0, found {:.6g} mm", f.roller_radius));
  if (f.contact == Contact::roller) {
    require(f.roller_radius > 0, "roller_radius", "a roller follower needs a roller radius > 0");
    require(d.base_radius >= f.roller_radius, "base_radius",
            fmt::format("expected a base circle radius >= the roller radius ({:.6g} mm), found {:.6g} mm", f.roller_radius,
                        d.base_radius));
  }
  const double Rp = prime_radius(d);
  const double max_s = d.program.max_s();
  if (f.motion == FollowerMotion::translating) {
    require(std::isfinite(f.offset), "offset", "expected a finite offset");
    if (f.contact != Contact::flat_face) {
      require(std::abs(f.offset) < Rp, "offset",
              fmt::format("expected |offset| < base radius + roller radius = {:.6g} mm, found {:.6g} mm", Rp, f.offset));
    }
    return;
  }
  const double a = f.pivot_distance, L = f.arm_length;
  require(std::isfinite(a) && a > 0, "pivot_distance", fmt::format("expected a pivot distance > 0, found {:.6g} mm", a));
  require(max_s < pi, "motion",
          fmt::format("an oscillating follower's lift is an angle; expected less than 180 deg, found {:.6g} deg",
                      max_s * 180 / pi));
  if (f.contact == Contact::flat_face) {
    require(std::isfinite(f.face_offset), "face_offset", "expected a finite face offset");
    require(std::abs(f.face_offset - d.base_radius) < a, "pivot_distance",
            fmt::format("the flat face cannot reach the base circle: |face_offset - base_radius| = {:.6g} mm must be "
                        "less than the pivot distance {:.6g} mm",
                        std::abs(f.face_offset - d.base_radius), a));
    require(beta_0(d) - max_s > -pi / 2, "motion",
            fmt::format("the face would swing past the cam centre line: arm angle {:.6g} deg at full lift",
                        (beta_0(d) - max_s) * 180 / pi));
    return;
  }
  require(std::isfinite(L) && L > 0, "arm_length", fmt::format("expected an arm length > 0, found {:.6g} mm", L));
  require(std::abs(a - L) < Rp && Rp < a + L, "pivot_distance",
          fmt::format("the follower cannot reach the cam: the prime circle radius {:.6g} mm must lie between "
                      "|pivot_distance - arm_length| = {:.6g} mm and pivot_distance + arm_length = {:.6g} mm",
                      Rp, std::abs(a - L), a + L));
  require(gamma_0(d) + max_s < pi, "arm_length",
          fmt::format("the arm would swing through the line of centres: {:.6g} deg + lift {:.6g} deg >= 180 deg",
                      gamma_0(d) * 180 / pi, max_s * 180 / pi));
}

}  // namespace

double roller_radius(const CamDesign& design) { return roller_radius_of(design); }

CamDesign outer_wall_of(const CamDesign& design) {
  CamDesign d = design;
  d.follower.surface = Surface::groove_outer_wall;
  return d;
}

CamDesign conjugate_cam_of(const CamDesign& design) {
  CamDesign d = design;
  d.follower.surface = Surface::conjugate_cam;
  return d;
}

ContactState contact_at(const CamDesign& design, double theta) { return contact_at(design, theta, design.program.at(theta)); }

ContactState contact_at(const CamDesign& design, double theta, const Motion& motion) {
  ContactState c;
  c.theta = theta;
  c.motion = motion;
  if (design.follower.contact == Contact::flat_face)
    flat_follower(design, c);
  else
    pitch_follower(design, c);
  return c;
}

std::vector<PitchCorner> pitch_corners(const CamDesign& design) {
  std::vector<PitchCorner> out;
  if (design.follower.contact == Contact::flat_face) return out;
  const double sigma = rotation_sign(design.rotation);
  auto unit = [](Vec2 v) { return (1 / norm(v)) * v; };
  for (const MotionProgram::Break& b : velocity_jumps(design.program)) {
    const auto [before, after] = design.program.limits_at(b);
    const ContactState c0 = contact_at(design, b.theta, before), c1 = contact_at(design, b.theta, after);
    PitchCorner k{b.theta, c0.pitch, unit(c0.pitch_tangent), unit(c1.pitch_tangent), 0};
    // The pitch curve runs clockwise for a counter-clockwise cam: turning clockwise is convex.
    k.turn = -sigma * std::atan2(cross(k.before, k.after), dot(k.before, k.after));
    out.push_back(k);
  }
  return out;
}

}  // namespace gearkit::cam
