// Contact geometry by kinematic inversion: the cam stands still and the follower turns about the
// cam centre by -theta (in the cam's turning sense). With p(theta) a follower point in the fixed
// frame, its image in the cam frame is P = R(-sigma theta) p, so
//   R(sigma theta) dP/dtheta   = q  = p' - sigma J p,
//   R(sigma theta) d2P/dtheta2 = q2 = p'' - sigma J p' - sigma J q,
// with J the rotation by +90 deg and sigma = +1 for a counter-clockwise cam. Pressure angle and
// curvature are invariant under the rotation, so they are computed from q and q2 directly.
#include <gearkit/cam/cam_design.hpp>

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
};

FixedFrame roller_centre(const CamDesign& d, const Motion& m) {
  const Follower& f = d.follower;
  if (f.motion == FollowerMotion::translating) {
    const double Rp = prime_radius(d);
    const double s0 = std::sqrt(Rp * Rp - f.offset * f.offset);
    return {{f.offset, s0 + m.s}, {0, m.ds}, {0, m.d2s}, {0, 1}};
  }
  const double a = f.pivot_distance, L = f.arm_length;
  const double g = gamma_0(d) + m.s;
  const Vec2 dC{L * std::sin(g), L * std::cos(g)};
  const Vec2 d2C{L * std::cos(g), -L * std::sin(g)};
  return {{a - L * std::cos(g), L * std::sin(g)}, m.ds * dC, (m.ds * m.ds) * d2C + m.d2s * dC,
          {std::sin(g), std::cos(g)}};
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
  const double Rr = d.follower.contact == Contact::roller ? d.follower.roller_radius : 0;
  const Vec2 outward = rotate((sigma / qn) * J(q), -sigma * c.theta);
  c.contact = c.pitch - Rr * outward;
  const double denominator = 1 - Rr * c.curvature_pitch;
  c.curvature_profile = denominator == 0 ? INFINITY : c.curvature_pitch / denominator;
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
  if (d.follower.motion == FollowerMotion::translating) {
    c.face_position = X.x - d.follower.offset;
    c.pressure_angle = 0;  // the face normal is the direction of travel
  } else {
    const Vec2 A{d.follower.pivot_distance, 0};
    c.face_position = dot(X - A, u);
    const Vec2 path = J(X - A);
    c.pressure_angle = std::atan2(std::abs(cross(N, path)), std::abs(dot(N, path)));
  }
}

void require(bool ok, const char* field, const std::string& message) {
  if (!ok) throw DesignError(field, message);
}

}  // namespace

void validate(const CamDesign& d) {
  const Follower& f = d.follower;
  require(std::isfinite(d.base_radius) && d.base_radius > 0, "base_radius",
          fmt::format("expected a base circle radius > 0, found {} mm", d.base_radius));
  require(std::isfinite(f.roller_radius) && f.roller_radius >= 0, "roller_radius",
          fmt::format("expected a roller radius >= 0, found {} mm", f.roller_radius));
  if (f.contact == Contact::roller) {
    require(f.roller_radius > 0, "roller_radius", "a roller follower needs a roller radius > 0");
    require(d.base_radius >= f.roller_radius, "base_radius",
            fmt::format("expected a base circle radius >= the roller radius ({} mm), found {} mm", f.roller_radius,
                        d.base_radius));
  }
  const double Rp = prime_radius(d);
  const double max_s = d.program.max_s();
  if (f.motion == FollowerMotion::translating) {
    require(std::isfinite(f.offset), "offset", "expected a finite offset");
    if (f.contact != Contact::flat_face) {
      require(std::abs(f.offset) < Rp, "offset",
              fmt::format("expected |offset| < base radius + roller radius = {} mm, found {} mm", Rp, f.offset));
    }
    return;
  }
  const double a = f.pivot_distance, L = f.arm_length;
  require(std::isfinite(a) && a > 0, "pivot_distance", fmt::format("expected a pivot distance > 0, found {} mm", a));
  require(max_s < pi, "motion",
          fmt::format("an oscillating follower's lift is an angle; expected less than 180 deg, found {} deg",
                      max_s * 180 / pi));
  if (f.contact == Contact::flat_face) {
    require(std::isfinite(f.face_offset), "face_offset", "expected a finite face offset");
    require(std::abs(f.face_offset - d.base_radius) < a, "pivot_distance",
            fmt::format("the flat face cannot reach the base circle: |face_offset - base_radius| = {} mm must be "
                        "less than the pivot distance {} mm",
                        std::abs(f.face_offset - d.base_radius), a));
    require(beta_0(d) - max_s > -pi / 2, "motion",
            fmt::format("the face would swing past the cam centre line: arm angle {} deg at full lift",
                        (beta_0(d) - max_s) * 180 / pi));
    return;
  }
  require(std::isfinite(L) && L > 0, "arm_length", fmt::format("expected an arm length > 0, found {} mm", L));
  require(std::abs(a - L) < Rp && Rp < a + L, "pivot_distance",
          fmt::format("the follower cannot reach the cam: the prime circle radius {} mm must lie between "
                      "|pivot_distance - arm_length| = {} mm and pivot_distance + arm_length = {} mm",
                      Rp, std::abs(a - L), a + L));
  require(gamma_0(d) + max_s < pi, "arm_length",
          fmt::format("the arm would swing through the line of centres: {} deg + lift {} deg >= 180 deg",
                      gamma_0(d) * 180 / pi, max_s * 180 / pi));
}

ContactState contact_at(const CamDesign& design, double theta) {
  ContactState c;
  c.theta = theta;
  c.motion = design.program.at(theta);
  if (design.follower.contact == Contact::flat_face)
    flat_follower(design, c);
  else
    pitch_follower(design, c);
  return c;
}

}  // namespace gearkit::cam
