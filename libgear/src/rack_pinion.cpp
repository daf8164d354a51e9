#include <gearkit/gear/rack_pinion.hpp>

#include <gearkit/gear/cylindrical_gear.hpp>
#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/gear/measurement.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace gearkit::gear {

double rack_datum_distance(double d, double x, double m_n) { return 0.5 * d + x * m_n; }

double shift_for_datum_distance(double H_0, double d, double m_n) { return (H_0 - 0.5 * d) / m_n; }

double rack_travel_per_turn(double d) { return std::numbers::pi * d; }

double rack_path_of_contact(double d_a, double d_b, double alpha_t, double h_a2, double x, double m_n) {
  const double rho_a = 0.5 * std::sqrt(std::max(0.0, d_a * d_a - d_b * d_b));
  return rho_a - 0.5 * d_b * std::tan(alpha_t) + (h_a2 - x * m_n) / std::sin(alpha_t);
}

double rack_contact_ratio(double g_alpha, double m_t, double alpha_t) {
  return g_alpha / (std::numbers::pi * m_t * std::cos(alpha_t));
}

double rack_tip_contact_roll_length(double d_b, double alpha_t, double h_a2, double x, double m_n) {
  return 0.5 * d_b * std::tan(alpha_t) - (h_a2 - x * m_n) / std::sin(alpha_t);
}

double rack_pin_diameter(double e_n, double alpha_n) { return e_n / std::cos(alpha_n); }

double rack_over_pin_height(double e_n, double alpha_n, double D_M) {
  if (!(alpha_n > 0.0 && alpha_n < std::numbers::pi / 2.0) || !(D_M > 0.0)) {
    throw std::domain_error("rack over a pin: expected 0 < alpha_n < 90 deg and a pin diameter > 0");
  }
  return 0.5 * D_M * (1.0 + 1.0 / std::sin(alpha_n)) - 0.5 * e_n / std::tan(alpha_n);
}

double rack_engagement_half_length(double d_a, double H_0, double h_a2) {
  const double r_a = 0.5 * d_a, y_t = H_0 - h_a2;
  return r_a > y_t ? std::sqrt(r_a * r_a - y_t * y_t) : 0.0;
}

double rack_length_for_travel(double s, double c, double b, double beta) {
  return s + 2.0 * c + b * std::fabs(std::tan(beta));
}

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

template <class Message>
void require(bool ok, const char* field, Message message) {
  if (!ok) throw GeometryError(field, message());
}

void validate_input(const RackPinionInput& in) {
  require(in.z1 >= 3 && in.z1 <= 100000, "z1", [&] { return fmt::format("expected a pinion with 3 to 100000 teeth, found {}", in.z1); });
  require(std::isfinite(in.m_n) && in.m_n > 0.0, "m_n", [&] { return fmt::format("expected a module > 0 mm, found {}", in.m_n); });
  require(in.alpha_n > 0.0 && in.alpha_n < std::numbers::pi / 4.0, "alpha_n",
          [&] { return fmt::format("expected a pressure angle in (0, 45) deg, found {:g} deg", in.alpha_n * 180.0 / std::numbers::pi); });
  require(std::fabs(in.beta) < std::numbers::pi / 4.0, "beta",
          [&] { return fmt::format("expected a helix angle in (-45, 45) deg, found {:g} deg", in.beta * 180.0 / std::numbers::pi); });
  require(std::isfinite(in.x1) && std::fabs(in.x1) <= 5.0, "x1", [&] { return fmt::format("expected a profile shift in [-5, 5], found {}", in.x1); });
  require(std::isfinite(in.face_width) && in.face_width >= 0.0, "face_width", [&] { return fmt::format("expected a face width >= 0 mm, found {}", in.face_width); });
  require(!in.H_0 || (std::isfinite(*in.H_0) && *in.H_0 > 0.0), "H_0", [&] { return fmt::format("expected a datum line distance > 0 mm, found {}", *in.H_0); });
  require(!in.rack_height || std::isfinite(*in.rack_height), "rack_height", [&] { return fmt::format("expected a finite rack height, found {}", *in.rack_height); });
  require(!in.travel || (std::isfinite(*in.travel) && *in.travel >= 0.0), "travel", [&] { return fmt::format("expected a travel >= 0 mm, found {}", *in.travel); });
  for (const auto& [D, field] : {std::pair{in.pin_diameter1, "pin_diameter1"}, std::pair{in.pin_diameter2, "pin_diameter2"}})
    require(!D || (std::isfinite(*D) && *D > 0.0), field, [&] { return fmt::format("expected a pin diameter > 0 mm, found {}", *D); });
  for (const auto& [A, field] : {std::pair{in.A_sn1, "A_sn1"}, std::pair{in.A_sn2, "A_sn2"}})
    require(std::isfinite(A) && std::fabs(A) < in.m_n, field, [&] { return fmt::format("expected a thickness allowance smaller than the module, found {}", A); });
  try {
    validate(Rack{in.alpha_n, in.h_aP, in.h_fP, in.rho_fP});
  } catch (const std::invalid_argument& e) {
    throw GeometryError("rack", e.what());
  }
}

// Span and over-pins of the pinion (measurement.hpp), nominal and with the allowance A_sn1.
void pinion_measurements(const RackPinionInput& in, RackPinionResult& r) {
  const ToothData nominal = make_tooth_data(in.z1, in.m_n, in.alpha_n, in.beta, r.s_t);
  const ToothData actual = make_tooth_data(in.z1, in.m_n, in.alpha_n, in.beta, r.s_t + in.A_sn1 / std::cos(in.beta));
  r.k_span = span_teeth(nominal);
  r.W_k = span_measurement(nominal, r.k_span);
  r.W_k_actual = span_measurement(actual, r.k_span);
  try {
    r.pin_diameter1 = in.pin_diameter1 ? *in.pin_diameter1 : pin_diameter_for_contact_at(nominal, r.d + 2.0 * r.x1 * in.m_n);
    r.M_d = dimension_over_pins(nominal, r.pin_diameter1);
    r.M_d_actual = dimension_over_pins(actual, r.pin_diameter1);
  } catch (const std::domain_error&) {
    r.M_d = r.M_d_actual = kNaN;
    r.warnings.push_back("pinion: no measurement over pins possible (the pin does not fit the tooth space)");
  }
}

// The rack's space width on its datum line is half the normal pitch, less its allowance (a thinner
// rack tooth widens the space); the pin sits in that space.
void rack_measurements(const RackPinionInput& in, RackPinionResult& r) {
  r.e_n2 = 0.5 * r.p_n;
  r.pin_diameter2 = in.pin_diameter2 ? *in.pin_diameter2 : rack_pin_diameter(r.e_n2, in.alpha_n);
  r.M_r = rack_over_pin_height(r.e_n2, in.alpha_n, r.pin_diameter2);
  r.M_r_actual = rack_over_pin_height(r.e_n2 - in.A_sn2, in.alpha_n, r.pin_diameter2);
  r.M_r_back = in.rack_height ? *in.rack_height + r.M_r : kNaN;
  if (r.M_r - 0.5 * r.pin_diameter2 * (1.0 + std::sin(in.alpha_n)) > r.h_a2) {
    r.warnings.push_back(fmt::format("rack: the {:.3f} mm pin touches the flanks above the rack's tips", r.pin_diameter2));
  } else if (r.M_r <= r.h_a2) {
    r.warnings.push_back(fmt::format("rack: the {:.3f} mm pin does not stand out of the rack's tips (M = {:.3f} mm, h_a = {:.3f} mm)",
                                     r.pin_diameter2, r.M_r, r.h_a2));
  }
}

void checks(const RackPinionInput& in, RackPinionResult& r) {
  auto warn = [&r](std::string text) { r.warnings.push_back(std::move(text)); };
  if (r.x1 < r.x_min - 1e-9) {
    warn(fmt::format("pinion: undercut (x = {:.4f} < x_min = {:.4f}; practical limit x'_min = {:.4f})", r.x1, r.x_min, r.x_min_practical));
  }
  if (r.rho_rack_tip < r.rho_Ff - 1e-9) {
    warn("involute interference: the rack's tip meets the pinion below its form circle");
  }
  if (std::isnan(r.s_an)) {
    warn("pinion: tip circle inside the base circle, the tip is not involute");
  } else if (r.s_an <= 0.0) {
    warn(fmt::format("pinion: pointed tooth (tip thickness {:.3f} mm)", r.s_an));
  } else if (r.s_an < 0.2 * in.m_n) {
    warn(fmt::format("pinion: thin tip, s_an = {:.3f} mm < 0.2 m_n = {:.3f} mm", r.s_an, 0.2 * in.m_n));
  }
  if (r.eps_alpha < 1.0) {
    warn(fmt::format("transverse contact ratio {:.3f} < 1: the pinion and rack do not mesh continuously", r.eps_alpha));
  } else if (r.eps_alpha < 1.2) {
    warn(fmt::format("transverse contact ratio {:.3f} < 1.2", r.eps_alpha));
  }
}

}  // namespace

RackPinionResult compute_rack_pinion(const RackPinionInput& in) {
  validate_input(in);
  RackPinionResult r;
  const Rack rack{in.alpha_n, in.h_aP, in.h_fP, in.rho_fP};
  r.m_t = transverse_module(in.m_n, in.beta);
  r.alpha_t = transverse_pressure_angle(in.alpha_n, in.beta);
  r.beta_b = base_helix_angle(in.beta, in.alpha_n);
  r.p_n = std::numbers::pi * in.m_n;
  r.p_t = std::numbers::pi * r.m_t;
  r.p_bt = r.p_t * std::cos(r.alpha_t);
  r.d = reference_diameter(in.z1, in.m_n, in.beta);
  r.x1 = in.H_0 ? shift_for_datum_distance(*in.H_0, r.d, in.m_n) : in.x1;
  require(std::fabs(r.x1) <= 5.0, "H_0", [&] { return fmt::format("the datum line distance gives a profile shift x = {:.3f} outside [-5, 5]", r.x1); });
  r.H_0 = rack_datum_distance(r.d, r.x1, in.m_n);
  r.a_back = in.rack_height ? r.H_0 + *in.rack_height : kNaN;
  r.d_b = base_diameter(r.d, r.alpha_t);
  r.d_a = tip_diameter(r.d, in.m_n, in.h_aP, r.x1, 0.0);
  r.d_f = root_diameter(r.d, in.m_n, in.h_fP, r.x1);
  r.s_t = reference_tooth_thickness(r.m_t, r.x1, in.alpha_n);
  r.s_n = r.s_t * std::cos(in.beta);
  r.s_an = r.d_a > r.d_b ? tooth_thickness_at(r.s_t, r.d, r.d_b, r.alpha_t, r.d_a) * std::cos(helix_angle_at(in.beta, r.d, r.d_a)) : kNaN;
  r.travel_per_turn = rack_travel_per_turn(r.d);
  r.h_a2 = in.h_aP * in.m_n;
  r.h_f2 = in.h_fP * in.m_n;
  r.c = r.H_0 + r.h_f2 - 0.5 * r.d_a;
  r.g_alpha = rack_path_of_contact(r.d_a, r.d_b, r.alpha_t, r.h_a2, r.x1, in.m_n);
  r.eps_alpha = rack_contact_ratio(r.g_alpha, r.m_t, r.alpha_t);
  r.eps_beta = overlap_ratio(in.face_width, in.beta, in.m_n);
  r.eps_gamma = r.eps_alpha + r.eps_beta;
  r.z_n = virtual_number_of_teeth(in.z1, in.beta, in.alpha_n);
  r.x_min = min_shift_no_undercut(r.d, in.m_n, r.alpha_t, rack);
  r.x_min_practical = practical_min_shift(r.z_n, rack);
  r.rho_Ff = form_roll_length(r.d_b, r.alpha_t, in.m_n, r.x1, rack);
  r.rho_rack_tip = rack_tip_contact_roll_length(r.d_b, r.alpha_t, r.h_a2, r.x1, in.m_n);
  pinion_measurements(in, r);
  rack_measurements(in, r);
  r.engagement_half_length = rack_engagement_half_length(r.d_a, r.H_0, r.h_a2);
  if (in.travel) {
    r.rack_length = rack_length_for_travel(*in.travel, r.engagement_half_length, in.face_width, in.beta);
    r.rack_teeth = static_cast<int>(std::ceil(r.rack_length / r.p_t - 1e-9));
  } else {
    r.rack_length = kNaN;
  }
  checks(in, r);
  return r;
}

RackForces rack_forces(double T, double d, double alpha_t, double beta) {
  RackForces f;
  f.F_t = 2000.0 * std::fabs(T) / d;
  f.F_r = f.F_t * std::tan(alpha_t);
  f.F_a = f.F_t * std::fabs(std::tan(beta));
  const double s = T < 0.0 ? -1.0 : 1.0;
  // The in-plane force on the rack is normal to the tooth line (sin beta, 0, cos beta) of a
  // right-hand pinion at the pitch point: along (cos beta, 0, -sin beta) for a push towards +x.
  f.on_rack = {s * f.F_t, -f.F_r, -s * f.F_t * std::tan(beta)};
  f.on_pinion = {-f.on_rack[0], -f.on_rack[1], -f.on_rack[2]};
  return f;
}

}  // namespace gearkit::gear
