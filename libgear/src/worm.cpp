#include <gearkit/gear/worm.hpp>

#include <gearkit/gear/gear_pair.hpp>

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace gearkit::gear {

const char* to_string(WormFlank flank) {
  switch (flank) {
    case WormFlank::ZA: return "ZA";
    case WormFlank::ZN: return "ZN";
    case WormFlank::ZI: return "ZI";
    case WormFlank::ZK: return "ZK";
  }
  return "?";
}

double worm_lead_angle(int z1, double m_x, double d_m1) { return std::atan(z1 * m_x / d_m1); }

double worm_axial_pitch(double m_x) { return std::numbers::pi * m_x; }

double worm_lead(int z1, double p_x) { return z1 * p_x; }

double worm_normal_module(double m_x, double gamma) { return m_x * std::cos(gamma); }

double worm_axial_pressure_angle(double alpha_n, double gamma) { return std::atan(std::tan(alpha_n) / std::cos(gamma)); }

double worm_normal_pressure_angle(double alpha_x, double gamma) { return std::atan(std::tan(alpha_x) * std::cos(gamma)); }

double worm_base_lead_angle(double gamma, double alpha_n) { return std::acos(std::cos(gamma) * std::cos(alpha_n)); }

double worm_base_diameter(double d_m1, double gamma, double gamma_b) { return d_m1 * std::tan(gamma) / std::tan(gamma_b); }

double worm_tip_diameter(double d_m1, double h_aP, double m_x) { return d_m1 + 2.0 * h_aP * m_x; }

double worm_root_diameter(double d_m1, double h_fP, double m_x) { return d_m1 - 2.0 * h_fP * m_x; }

double wheel_reference_diameter(int z2, double m_x) { return z2 * m_x; }

double worm_centre_distance(double d_m1, double d2, double x2, double m_x) { return 0.5 * (d_m1 + d2) + x2 * m_x; }

double wheel_shift_for_centre_distance(double a, double d_m1, double d2, double m_x) { return (a - 0.5 * (d_m1 + d2)) / m_x; }

double wheel_tip_diameter(double d2, double h_aP, double x2, double m_x) { return d2 + 2.0 * m_x * (h_aP + x2); }

double wheel_root_diameter(double d2, double h_fP, double x2, double m_x) { return d2 - 2.0 * m_x * (h_fP - x2); }

double wheel_throat_radius(double a, double d_a2) { return a - 0.5 * d_a2; }

double wheel_outside_diameter(double d_a2, double m_x) { return d_a2 + m_x; }

double wheel_face_width(double d_a1, double m_x) { return 0.45 * (d_a1 + 4.0 * m_x); }

double worm_length(double d_e2, double a, double d_a1) {
  const double r = 0.5 * d_e2, h = a - 0.5 * d_a1;
  return r > h ? 2.0 * std::sqrt(r * r - h * h) : 0.0;
}

double worm_working_diameter(double a, double d2) { return 2.0 * a - d2; }

double peripheral_velocity(double d, double n) { return std::numbers::pi * std::fabs(d * n) / 60000.0; }

double worm_sliding_velocity(double v1, double gamma) { return v1 / std::cos(gamma); }

double friction_angle(double mu, double alpha_n) { return std::atan(mu / std::cos(alpha_n)); }

double worm_friction_coefficient_agma(double v_g) {
  if (!(v_g >= 0.0) || !std::isfinite(v_g)) throw std::domain_error("friction coefficient: expected a sliding velocity >= 0 m/s");
  const double V = v_g / 0.00508;  // ft/min
  if (V == 0.0) return 0.150;
  if (V <= 10.0) return 0.124 * std::exp(-0.074 * std::pow(V, 0.645));
  return 0.103 * std::exp(-0.110 * std::pow(V, 0.450)) + 0.012;
}

double worm_efficiency_worm_driving(double gamma, double rho) { return std::tan(gamma) / std::tan(gamma + rho); }

double worm_efficiency_wheel_driving(double gamma, double rho) { return std::tan(gamma - rho) / std::tan(gamma); }

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDeg = 180.0 / std::numbers::pi;

template <class Message>
void require(bool ok, const char* field, Message message) {
  if (!ok) throw GeometryError(field, message());
}

void validate_input(const WormInput& in) {
  require(in.z1 >= 1 && in.z1 <= 20, "z1", [&] { return fmt::format("expected a worm with 1 to 20 threads, found {}", in.z1); });
  require(in.z2 >= 1 && in.z2 <= 100000, "z2", [&] { return fmt::format("expected a wheel with 1 to 100000 teeth, found {}", in.z2); });
  require(std::isfinite(in.m_x) && in.m_x > 0.0, "m_x", [&] { return fmt::format("expected an axial module > 0 mm, found {}", in.m_x); });
  require(in.alpha_0 > 0.0 && in.alpha_0 < std::numbers::pi / 4.0, "alpha_0",
          [&] { return fmt::format("expected a pressure angle in (0, 45) deg, found {:g} deg", in.alpha_0 * kDeg); });
  require(in.q.has_value() != in.d_m1.has_value(), "q", [] { return std::string("expected either the diameter quotient q or the worm diameter d_m1"); });
  require(!in.q || (std::isfinite(*in.q) && *in.q > 0.0), "q", [&] { return fmt::format("expected a diameter quotient > 0, found {}", *in.q); });
  require(!in.d_m1 || (std::isfinite(*in.d_m1) && *in.d_m1 > 0.0), "d_m1", [&] { return fmt::format("expected a worm diameter > 0 mm, found {}", *in.d_m1); });
  require(in.h_aP > 0.0 && in.h_fP >= in.h_aP && std::isfinite(in.h_fP), "h_aP",
          [&] { return fmt::format("expected 0 < h_aP* <= h_fP*, found h_aP* = {}, h_fP* = {}", in.h_aP, in.h_fP); });
  require(std::isfinite(in.x2) && std::fabs(in.x2) <= 5.0, "x2", [&] { return fmt::format("expected a profile shift in [-5, 5], found {}", in.x2); });
  require(!in.centre_distance || (std::isfinite(*in.centre_distance) && *in.centre_distance > 0.0), "centre_distance",
          [&] { return fmt::format("expected a centre distance > 0 mm, found {}", *in.centre_distance); });
  require(!in.mu || (*in.mu >= 0.0 && *in.mu < 1.0), "mu", [&] { return fmt::format("expected a friction coefficient in [0, 1), found {}", *in.mu); });
  require(in.mu_static >= 0.0 && in.mu_static < 1.0, "mu_static", [&] { return fmt::format("expected a friction coefficient in [0, 1), found {}", in.mu_static); });
  require(std::isfinite(in.n1), "n1", [&] { return fmt::format("expected a finite worm speed, found {}", in.n1); });
}

void geometry(const WormInput& in, WormResult& r) {
  r.d_m1 = in.d_m1 ? *in.d_m1 : *in.q * in.m_x;
  r.q = r.d_m1 / in.m_x;
  r.gamma = worm_lead_angle(in.z1, in.m_x, r.d_m1);
  r.p_x = worm_axial_pitch(in.m_x);
  r.p_z = worm_lead(in.z1, r.p_x);
  r.m_n = worm_normal_module(in.m_x, r.gamma);
  if (in.flank == WormFlank::ZA) {
    r.alpha_x = in.alpha_0;
    r.alpha_n = worm_normal_pressure_angle(in.alpha_0, r.gamma);
  } else {
    r.alpha_n = in.alpha_0;
    r.alpha_x = worm_axial_pressure_angle(in.alpha_0, r.gamma);
  }
  r.gamma_b = in.flank == WormFlank::ZI ? worm_base_lead_angle(r.gamma, r.alpha_n) : kNaN;
  r.d_b1 = in.flank == WormFlank::ZI ? worm_base_diameter(r.d_m1, r.gamma, r.gamma_b) : kNaN;
  r.d_a1 = worm_tip_diameter(r.d_m1, in.h_aP, in.m_x);
  r.d_f1 = worm_root_diameter(r.d_m1, in.h_fP, in.m_x);
  require(r.d_f1 > 0.0, in.d_m1 ? "d_m1" : "q", [&] { return fmt::format("the worm's root diameter d_f1 = {:.3f} mm is not positive: "
                                                                        "the worm diameter is too small for the module", r.d_f1); });
  r.d2 = wheel_reference_diameter(in.z2, in.m_x);
  r.x2 = in.centre_distance ? wheel_shift_for_centre_distance(*in.centre_distance, r.d_m1, r.d2, in.m_x) : in.x2;
  require(std::fabs(r.x2) <= 5.0, "centre_distance", [&] { return fmt::format("the centre distance gives a wheel profile shift x2 = {:.3f} "
                                                                             "outside [-5, 5]", r.x2); });
  r.a = worm_centre_distance(r.d_m1, r.d2, r.x2, in.m_x);
  r.d_a2 = wheel_tip_diameter(r.d2, in.h_aP, r.x2, in.m_x);
  r.d_f2 = wheel_root_diameter(r.d2, in.h_fP, r.x2, in.m_x);
  r.r_k = wheel_throat_radius(r.a, r.d_a2);
  r.d_e2 = wheel_outside_diameter(r.d_a2, in.m_x);
  r.b2 = wheel_face_width(r.d_a1, in.m_x);
  r.b1 = worm_length(r.d_e2, r.a, r.d_a1);
  r.d_w1 = worm_working_diameter(r.a, r.d2);
  require(r.d_w1 > 0.0, "centre_distance", [&] { return fmt::format("the worm's working diameter 2 a - d2 = {:.3f} mm is not positive", r.d_w1); });
  r.gamma_w = worm_lead_angle(in.z1, in.m_x, r.d_w1);
  r.u = static_cast<double>(in.z2) / in.z1;
}

void kinematics(const WormInput& in, WormResult& r) {
  r.wheel_sense = (in.right_hand ? -1.0 : 1.0) * in.z1 / in.z2;
  r.n1 = in.n1;
  r.n2 = r.wheel_sense * in.n1;
  r.v1 = peripheral_velocity(r.d_w1, in.n1);
  r.v2 = peripheral_velocity(r.d2, r.n2);
  r.v_g = worm_sliding_velocity(r.v1, r.gamma_w);
  r.mu_from_velocity = !in.mu;
  r.mu = in.mu ? *in.mu : worm_friction_coefficient_agma(r.v_g);
  r.rho = friction_angle(r.mu, r.alpha_n);
  r.rho_static = friction_angle(in.mu_static, r.alpha_n);
  r.eta_12 = worm_efficiency_worm_driving(r.gamma_w, r.rho);
  r.eta_21 = worm_efficiency_wheel_driving(r.gamma_w, r.rho);
  r.self_locking_static = r.gamma_w <= r.rho_static;
  r.self_locking_dynamic = r.gamma_w <= r.rho;
}

void checks(const WormInput& in, WormResult& r) {
  auto warn = [&r](std::string text) { r.warnings.push_back(std::move(text)); };
  if (r.self_locking_dynamic) {
    warn(fmt::format("self-locking (dynamic): gamma_w = {:.3f} deg <= rho' = {:.3f} deg, eta_21 = {:.3f}: the wheel cannot drive the worm",
                     r.gamma_w * kDeg, r.rho * kDeg, r.eta_21));
  }
  if (r.self_locking_static) {
    warn(fmt::format("self-locking (static): gamma_w = {:.3f} deg <= rho'_0 = {:.3f} deg (mu_0 = {:g}): the wheel cannot start the worm "
                     "from rest{}", r.gamma_w * kDeg, r.rho_static * kDeg, in.mu_static,
                     r.self_locking_dynamic ? "" : "; running, it can drive it (vibration may release it)"));
  }
  if (r.x2 < -0.5 || r.x2 > 1.0) {
    warn(fmt::format("wheel profile shift x2 = {:.3f} outside the usual range [-0.5, 1] (Niemann/Winter)", r.x2));
  }
  // In its mid-plane the wheel is generated by the worm's axial section, a rack of alpha_x.
  const double s = std::sin(r.alpha_x);
  const double x_min = in.h_aP - 0.5 * in.z2 * s * s;
  if (r.x2 < x_min - 1e-9) {
    warn(fmt::format("wheel: undercut in the mid-plane (x2 = {:.3f} < {:.3f} = h_aP* - z2 sin^2(alpha_x) / 2)", r.x2, x_min));
  }
  if (r.gamma > std::numbers::pi / 4.0) warn(fmt::format("lead angle {:.2f} deg > 45 deg: a crossed helical pair rather than a worm", r.gamma * kDeg));
  if (!in.mu && in.n1 == 0.0) warn("no worm speed given: the friction coefficient is AGMA's at rest (0.150), efficiencies are those of starting");
}

}  // namespace

WormResult compute_worm(const WormInput& in) {
  validate_input(in);
  WormResult r;
  geometry(in, r);
  kinematics(in, r);
  checks(in, r);
  return r;
}

WormForces worm_forces(const WormResult& w, double torque, bool on_worm, bool worm_drives) {
  if (!(torque > 0.0) || !std::isfinite(torque)) throw std::domain_error("worm forces: expected a torque > 0 N m");
  if (!worm_drives && w.eta_21 <= 0.0) throw std::domain_error("worm forces: the wheel cannot drive a self-locking worm");
  WormForces f;
  f.worm_drives = worm_drives;
  const double g = w.gamma_w, rho = w.rho, tan_an = std::tan(w.alpha_n);
  // tan(gamma -+ rho') converts F_t1 into F_t2: the friction adds to the driver's force.
  const double ratio = worm_drives ? std::tan(g + rho) : std::tan(g - rho);  // F_t1 / F_t2
  if (on_worm) {
    f.F_t1 = 2000.0 * torque / w.d_w1;
    f.F_t2 = f.F_t1 / ratio;
  } else {
    f.F_t2 = 2000.0 * torque / w.d2;
    f.F_t1 = f.F_t2 * ratio;
  }
  f.T1 = f.F_t1 * w.d_w1 / 2000.0;
  f.T2 = f.F_t2 * w.d2 / 2000.0;
  f.F_a1 = f.F_t2;
  f.F_a2 = f.F_t1;
  f.F_r = worm_drives ? f.F_t1 * tan_an * std::cos(rho) / std::sin(g + rho) : f.F_t2 * tan_an * std::cos(rho) / std::cos(g - rho);
  f.F_n = f.F_r / std::sin(w.alpha_n);
  // Unit directions: the worm's surface at the pitch point moves along e1, the wheel's along e2.
  const double s1 = w.n1 < 0.0 ? -1.0 : 1.0;
  const double e2x = w.wheel_sense < 0.0 ? -s1 : s1;
  const double sign = worm_drives ? 1.0 : -1.0;  // the driver pushes the driven gear along its motion
  f.on_wheel = {sign * f.F_t2 * e2x, sign * f.F_t1 * s1, -f.F_r};
  f.on_worm = {-f.on_wheel[0], -f.on_wheel[1], -f.on_wheel[2]};
  const double omega1 = std::fabs(w.v1) > 0.0 ? 2.0 * w.v1 / (w.d_w1 * 1e-3) : 0.0;
  const double omega2 = std::fabs(w.v2) > 0.0 ? 2.0 * w.v2 / (w.d2 * 1e-3) : 0.0;
  f.P_in = worm_drives ? f.T1 * omega1 : f.T2 * omega2;
  f.P_out = worm_drives ? f.T2 * omega2 : f.T1 * omega1;
  f.P_loss = w.mu * f.F_n * w.v_g;
  return f;
}

}  // namespace gearkit::gear
