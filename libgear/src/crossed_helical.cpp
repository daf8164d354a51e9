#include <gearkit/gear/crossed_helical.hpp>

#include <gearkit/gear/cylindrical_gear.hpp>
#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/gear/rack.hpp>
#include <gearkit/gear/worm.hpp>

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace gearkit::gear {

double crossed_shaft_angle(double beta1, double beta2) { return beta1 + beta2; }

double crossed_centre_distance(double d1, double d2) { return 0.5 * (d1 + d2); }

double crossed_sliding_velocity(double v1, double Sigma, double beta2) {
  return v1 * std::fabs(std::sin(Sigma)) / std::cos(beta2);
}

double crossed_efficiency(double beta1, double beta2, double rho) {
  const double s = beta1 + beta2 < 0.0 ? -1.0 : 1.0;
  const double b1 = s * beta1, b2 = s * beta2;
  return std::cos(b2 + rho) * std::cos(b1) / (std::cos(b1 - rho) * std::cos(b2));
}

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;
constexpr double kMaxHelix = 85.0 / kDeg;

template <class Message>
void require(bool ok, const char* field, Message message) {
  if (!ok) throw GeometryError(field, message());
}

void validate_input(const CrossedHelicalInput& in) {
  for (const auto& [z, field] : {std::pair{in.z1, "z1"}, std::pair{in.z2, "z2"}})
    require(z >= 3 && z <= 100000, field, [&] { return fmt::format("expected 3 to 100000 teeth, found {}", z); });
  require(std::isfinite(in.m_n) && in.m_n > 0.0, "m_n", [&] { return fmt::format("expected a module > 0 mm, found {}", in.m_n); });
  require(in.alpha_n > 0.0 && in.alpha_n < std::numbers::pi / 4.0, "alpha_n",
          [&] { return fmt::format("expected a pressure angle in (0, 45) deg, found {:g} deg", in.alpha_n * kDeg); });
  for (const auto& [b, field] : {std::pair{in.beta1, "beta1"}, std::pair{in.beta2, "beta2"}})
    require(std::fabs(b) < kMaxHelix, field, [&] { return fmt::format("expected a helix angle in (-85, 85) deg, found {:g} deg", b * kDeg); });
  require(std::fabs(in.beta1 + in.beta2) > 1e-6, "beta2",
          [] { return std::string("expected crossed shafts: beta1 + beta2 = 0 makes the shafts parallel (use gearkit gear)"); });
  require(in.h_aP > 0.0 && in.h_fP >= in.h_aP && std::isfinite(in.h_fP), "h_aP",
          [&] { return fmt::format("expected 0 < h_aP* <= h_fP*, found h_aP* = {}, h_fP* = {}", in.h_aP, in.h_fP); });
  require(!in.mu || (*in.mu >= 0.0 && *in.mu < 1.0), "mu", [&] { return fmt::format("expected a friction coefficient in [0, 1), found {}", *in.mu); });
  require(std::isfinite(in.n1), "n1", [&] { return fmt::format("expected a finite speed, found {}", in.n1); });
}

CrossedGear gear_of(int z, double beta, const CrossedHelicalInput& in) {
  CrossedGear g;
  g.z = z;
  g.beta = beta;
  g.right_hand = beta > 0.0;
  g.m_t = transverse_module(in.m_n, beta);
  g.alpha_t = transverse_pressure_angle(in.alpha_n, beta);
  g.d = reference_diameter(z, in.m_n, beta);
  g.d_a = tip_diameter(g.d, in.m_n, in.h_aP, 0.0, 0.0);
  g.d_f = root_diameter(g.d, in.m_n, in.h_fP, 0.0);
  g.p_z = beta == 0.0 ? std::numeric_limits<double>::infinity() : std::numbers::pi * g.d / std::fabs(std::tan(beta));
  return g;
}

void checks(const CrossedHelicalInput& in, CrossedHelicalResult& r) {
  auto warn = [&r](std::string text) { r.warnings.push_back(std::move(text)); };
  const Rack rack{in.alpha_n, in.h_aP, in.h_fP, 0.0};
  for (int i = 0; i < 2; ++i) {
    const CrossedGear& g = r.gear[i];
    const double x_min = min_shift_no_undercut(g.d, in.m_n, g.alpha_t, rack);
    if (x_min > 1e-9) warn(fmt::format("gear {}: undercut (unshifted, x_min = {:.4f})", i + 1, x_min));
  }
  if (r.self_locking_21) warn(fmt::format("self-locking: eta_21 = {:.3f} <= 0, gear 2 cannot drive gear 1", r.eta_21));
  if (r.self_locking_12) warn(fmt::format("self-locking: eta_12 = {:.3f} <= 0, gear 1 cannot drive gear 2", r.eta_12));
}

}  // namespace

CrossedHelicalResult compute_crossed_helical(const CrossedHelicalInput& in) {
  validate_input(in);
  CrossedHelicalResult r;
  r.gear = {gear_of(in.z1, in.beta1, in), gear_of(in.z2, in.beta2, in)};
  r.Sigma = crossed_shaft_angle(in.beta1, in.beta2);
  r.a = crossed_centre_distance(r.gear[0].d, r.gear[1].d);
  r.u = static_cast<double>(in.z2) / in.z1;
  r.n1 = in.n1;
  r.n2 = -in.n1 / r.u;
  r.v1 = peripheral_velocity(r.gear[0].d, in.n1);
  r.v2 = peripheral_velocity(r.gear[1].d, r.n2);
  r.v_g = crossed_sliding_velocity(r.v1, r.Sigma, in.beta2);
  r.mu = in.mu ? *in.mu : 0.05;
  r.rho = friction_angle(r.mu, in.alpha_n);
  r.eta_12 = crossed_efficiency(in.beta1, in.beta2, r.rho);
  r.eta_21 = crossed_efficiency(in.beta2, in.beta1, r.rho);
  r.self_locking_12 = r.eta_12 <= 0.0;
  r.self_locking_21 = r.eta_21 <= 0.0;
  checks(in, r);
  return r;
}

CrossedForces crossed_forces(const CrossedHelicalResult& c, double alpha_n, double torque, int on_gear, int driver) {
  if (!(torque > 0.0) || !std::isfinite(torque)) throw std::domain_error("crossed helical forces: expected a torque > 0 N m");
  if ((on_gear != 1 && on_gear != 2) || (driver != 1 && driver != 2)) throw std::domain_error("crossed helical forces: gears are 1 and 2");
  if ((driver == 1 && c.self_locking_12) || (driver == 2 && c.self_locking_21))
    throw std::domain_error(fmt::format("crossed helical forces: gear {} cannot drive (self-locking)", driver));
  const double s = c.Sigma < 0.0 ? -1.0 : 1.0, rho = c.rho;
  const double b1 = s * c.gear[0].beta, b2 = s * c.gear[1].beta;
  const bool one = driver == 1;
  // The friction along the teeth adds to the driver's tangential force and subtracts from the driven one's.
  const double c1 = one ? std::cos(b1 - rho) : std::cos(b1 + rho);
  const double c2 = one ? std::cos(b2 + rho) : std::cos(b2 - rho);
  CrossedForces f;
  f.driver = driver;
  const double F_t = 2000.0 * torque / c.gear[on_gear - 1].d;
  const double K = F_t / (on_gear == 1 ? c1 : c2);
  f.F_t1 = K * c1;
  f.F_t2 = K * c2;
  f.T1 = f.F_t1 * c.gear[0].d / 2000.0;
  f.T2 = f.F_t2 * c.gear[1].d / 2000.0;
  // Axial forces along each gear's angular velocity, then along +x and +g2 (omega2 is along -g2 when omega1 is along +x).
  const double A1 = one ? s * K * std::sin(b1 - rho) : -s * K * std::sin(b1 + rho);
  const double A2 = one ? -s * K * std::sin(b2 + rho) : s * K * std::sin(b2 - rho);
  const double s1 = c.n1 < 0.0 ? -1.0 : 1.0;  // n1 = 0 counts as positive
  f.F_a1 = s1 * A1;
  f.F_a2 = -s1 * A2;
  f.F_n = K * std::cos(rho) / std::cos(alpha_n);
  f.F_r = f.F_n * std::sin(alpha_n);
  // Gear 1's pitch point lies at +z from its axis and moves along -s1 y; its driver's force opposes that.
  f.on_1 = {f.F_a1, (one ? 1.0 : -1.0) * s1 * f.F_t1, -f.F_r};
  f.on_2 = {-f.on_1[0], -f.on_1[1], -f.on_1[2]};
  const double omega1 = 2.0 * c.v1 / (c.gear[0].d * 1e-3), omega2 = 2.0 * c.v2 / (c.gear[1].d * 1e-3);
  f.P_in = one ? f.T1 * omega1 : f.T2 * omega2;
  f.P_out = one ? f.T2 * omega2 : f.T1 * omega1;
  f.P_loss = c.mu * f.F_n * c.v_g;
  return f;
}

}  // namespace gearkit::gear
