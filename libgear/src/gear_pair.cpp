#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/gear/backlash.hpp>
#include <gearkit/gear/cylindrical_gear.hpp>
#include <gearkit/gear/involute.hpp>
#include <gearkit/gear/measurement.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace gearkit::gear {

GeometryError::GeometryError(std::string field, const std::string& message)
    : std::invalid_argument(message), field_(std::move(field)) {}

const char* to_string(Mounting mounting) {
  switch (mounting) {
    case Mounting::zero: return "zero";
    case Mounting::v_zero: return "V-0";
    case Mounting::v: return "V";
  }
  return "V";
}

const char* to_string(ShiftSplit split) {
  switch (split) {
    case ShiftSplit::user_x1: return "user";
    case ShiftSplit::balanced_sliding: return "balanced";
    case ShiftSplit::proportional: return "proportional";
    case ShiftSplit::min_shift: return "min-shift";
  }
  return "user";
}

const char* to_string(UndercutLimit limit) { return limit == UndercutLimit::iso ? "ISO" : "practical"; }

double reference_centre_distance(int z1, int z2, double m_t) { return 0.5 * m_t * (z1 + z2); }

double working_pressure_angle(double alpha_t, double alpha_n, int z1, int z2, double sum_x) {
  const double inv_wt = involute(alpha_t) + 2.0 * std::tan(alpha_n) * sum_x / (z1 + z2);
  return inverse_involute(inv_wt);
}

double working_pressure_angle_for_centre_distance(double a_d, double alpha_t, double a) {
  const double c = a_d * std::cos(alpha_t) / a;
  if (!(c > 0.0 && c <= 1.0)) {
    throw std::domain_error(fmt::format("centre distance {:.6g} mm is below the sum of the base radii {:.6g} mm",
                                        std::fabs(a), std::fabs(a_d * std::cos(alpha_t))));
  }
  return std::acos(c);
}

double centre_distance(double a_d, double alpha_t, double alpha_wt) { return a_d * std::cos(alpha_t) / std::cos(alpha_wt); }

double sum_of_shifts(int z1, int z2, double alpha_t, double alpha_n, double alpha_wt) {
  return (z1 + z2) * (involute(alpha_wt) - involute(alpha_t)) / (2.0 * std::tan(alpha_n));
}

double centre_distance_modification(double a, double a_d, double m_n) { return (a - a_d) / m_n; }

double tip_shortening(double sum_x, double y) { return sum_x - y; }

Mounting mounting_type(double x1, double x2) {
  constexpr double tol = 1e-9;
  if (std::fabs(x1) < tol && std::fabs(x2) < tol) return Mounting::zero;
  if (std::fabs(x1 + x2) < tol) return Mounting::v_zero;
  return Mounting::v;
}

double transverse_contact_ratio(int z1, int z2, double alpha_a1, double alpha_a2, double alpha_wt) {
  const double t = std::tan(alpha_wt);
  return (z1 * (std::tan(alpha_a1) - t) + z2 * (std::tan(alpha_a2) - t)) / (2.0 * std::numbers::pi);
}

double transverse_contact_ratio_from_lengths(double rho_a1, double rho_a2, double a, double alpha_wt, double p_bt) {
  return (rho_a1 + rho_a2 - a * std::sin(alpha_wt)) / p_bt;
}

double overlap_ratio(double b, double beta, double m_n) { return b * std::fabs(std::sin(beta)) / (std::numbers::pi * m_n); }

double tip_clearance(double a, double d_ai, double d_fj) { return a - 0.5 * d_ai - 0.5 * d_fj; }

namespace {

// Pressure angle at the tip, 0 when the tip circle lies inside the base circle (the involute,
// and with it the contact, then ends at the base circle).
double tip_pressure_angle(double d_b, double d_a) {
  const double c = d_b / d_a;
  return c >= 1.0 ? 0.0 : std::acos(c);
}

}  // namespace

double max_specific_sliding(int z_i, int z_j, double d_bj, double d_aj, double a, double alpha_wt) {
  // rho = r_b tan(alpha_a) = sqrt(r_a^2 - r_b^2) with the sign of the gear (0 inside the base circle).
  const double rho_j_tip = std::copysign(std::sqrt(std::max(0.0, 0.25 * (d_aj * d_aj - d_bj * d_bj))), d_bj);
  const double rho_i_root = a * std::sin(alpha_wt) - rho_j_tip;
  if (rho_i_root * z_i <= 0.0) return -std::numeric_limits<double>::infinity();
  return 1.0 - (rho_j_tip / rho_i_root) * (static_cast<double>(z_i) / z_j);
}

double teeth_sum_for_centre_distance(double a, double m_n, double beta) { return 2.0 * a * std::cos(beta) / m_n; }

double face_width_of(const GearPairInput& in, int i) { return in.face_widths[static_cast<std::size_t>(i)].value_or(in.face_width); }

namespace {

// Axial ends of the faces: gear 1 centred on 0, gear 2 on face_offset.
struct FaceEnds {
  double left[2], right[2];
};

FaceEnds face_ends(const GearPairInput& in) {
  FaceEnds f{};
  for (int i = 0; i < 2; ++i) {
    const double c = i == 0 ? 0.0 : in.face_offset, half = 0.5 * face_width_of(in, i);
    f.left[i] = c - half;
    f.right[i] = c + half;
  }
  return f;
}

}  // namespace

double common_face_width(const GearPairInput& in) {
  if (!in.face_widths[0] && !in.face_widths[1] && in.face_offset == 0.0) return in.face_width;
  const FaceEnds f = face_ends(in);
  return std::max(0.0, std::min(f.right[0], f.right[1]) - std::max(f.left[0], f.left[1]));
}

double root_face_width(const GearPairInput& in, int i, double m_n) {
  const double b = common_face_width(in);
  if (!in.face_widths[0] && !in.face_widths[1] && in.face_offset == 0.0) return b;
  const FaceEnds f = face_ends(in);
  const double beyond_left = std::max(0.0, std::max(f.left[0], f.left[1]) - f.left[i]);
  const double beyond_right = std::max(0.0, f.right[i] - std::min(f.right[0], f.right[1]));
  return b + std::min(m_n, beyond_left) + std::min(m_n, beyond_right);
}

Rack tool_rack(const GearPairInput& in, int i, double alpha_n) {
  const std::optional<Rack>& own = in.tool[static_cast<std::size_t>(i)];
  return own ? Rack{alpha_n, own->h_aP, own->h_fP, own->rho_fP} : Rack{alpha_n, in.h_aP, in.h_fP, in.rho_fP};
}

HelixHand helix_hand(const GearPairInput& in, int i) {
  if (in.helix_angle == 0.0) return HelixHand::spur;
  const bool right = (in.helix_angle > 0.0) == (i == 0 || in.internal);
  return right ? HelixHand::right : HelixHand::left;
}

const char* to_string(HelixHand hand) {
  switch (hand) {
    case HelixHand::spur: return "spur";
    case HelixHand::right: return "right";
    case HelixHand::left: return "left";
  }
  return "spur";
}

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct Basics {
  int Z1 = 0, Z2 = 0;  // signed
  double m_n = 0, m_t = 0, alpha_n = 0, alpha_t = 0, beta = 0, beta_b = 0;
  double inv_alpha_t = 0, tan_alpha_n = 0, cos_beta = 1, cos_beta_b = 1;  // used by every gear: computed once
  double d1 = 0, d2 = 0, d_b1 = 0, d_b2 = 0, a_d = 0;
  std::array<Rack, 2> rack;  // the tool of each gear
};

// The message is built only on failure: validation runs on every table.
template <class Message>
void require(bool ok, const char* field, Message message) {
  if (!ok) throw GeometryError(field, message());
}

Basics basics_of(const GearPairInput& in) {
  require(in.z1 >= 1, "z1", [&] { return fmt::format("expected a number of teeth >= 1, found {}", in.z1); });
  require(in.z2 >= 1, "z2", [&] { return fmt::format("expected a number of teeth >= 1, found {}", in.z2); });
  require(!in.internal || in.z2 > in.z1, "z2", [&] { return
          fmt::format("an internal gear needs more teeth than its pinion (z2 > z1 = {}), found {}", in.z1, in.z2); });
  require(std::isfinite(in.module) && in.module > 0.0, "module", [&] { return fmt::format("expected a module > 0 mm, found {}", in.module); });
  require(std::isfinite(in.pressure_angle) && in.pressure_angle > 0.0 && in.pressure_angle < 45.0 * kDeg, "pressure_angle", [&] { return
          fmt::format("expected a pressure angle in (0, 45) deg, found {} deg", in.pressure_angle / kDeg); });
  require(std::isfinite(in.helix_angle) && std::fabs(in.helix_angle) < 45.0 * kDeg, "helix_angle", [&] { return
          fmt::format("expected a helix angle with |beta| < 45 deg, found {} deg", in.helix_angle / kDeg); });
  require(std::isfinite(in.face_width) && in.face_width >= 0.0, "face_width", [&] { return
          fmt::format("expected a face width >= 0 mm, found {}", in.face_width); });
  for (int i = 0; i < 2; ++i) {
    const std::optional<double>& b_i = in.face_widths[static_cast<std::size_t>(i)];
    require(!b_i || (std::isfinite(*b_i) && *b_i >= 0.0), i == 0 ? "face_width1" : "face_width2", [&] { return
            fmt::format("expected a face width >= 0 mm, found {}", *b_i); });
  }
  require(std::isfinite(in.face_offset), "face_offset", [&] { return fmt::format("expected a finite offset, found {}", in.face_offset); });
  Basics b;
  b.beta = in.helix_angle;
  if (in.system == ModuleSystem::normal) {
    b.m_n = in.module;
    b.alpha_n = in.pressure_angle;
    b.m_t = transverse_module(b.m_n, b.beta);
    b.alpha_t = transverse_pressure_angle(b.alpha_n, b.beta);
  } else {
    b.m_t = in.module;
    b.alpha_t = in.pressure_angle;
    b.m_n = b.m_t * std::cos(b.beta);
    b.alpha_n = normal_pressure_angle(b.alpha_t, b.beta);
  }
  for (int i = 0; i < 2; ++i) {
    b.rack[i] = tool_rack(in, i, b.alpha_n);
    try {
      validate(b.rack[i]);
    } catch (const std::invalid_argument& e) {
      throw GeometryError(in.tool[i] ? (i == 0 ? "tool1" : "tool2") : "rack", in.tool[i] ? fmt::format("tool of gear {}: {}", i + 1, e.what()) : e.what());
    }
  }
  b.beta_b = base_helix_angle(b.beta, b.alpha_n);
  b.inv_alpha_t = involute(b.alpha_t);
  b.tan_alpha_n = std::tan(b.alpha_n);
  b.cos_beta = std::cos(b.beta);
  b.cos_beta_b = std::cos(b.beta_b);
  b.Z1 = in.z1;
  b.Z2 = in.internal ? -in.z2 : in.z2;
  b.d1 = reference_diameter(b.Z1, b.m_n, b.beta);
  b.d2 = reference_diameter(b.Z2, b.m_n, b.beta);
  b.d_b1 = base_diameter(b.d1, b.alpha_t);
  b.d_b2 = base_diameter(b.d2, b.alpha_t);
  b.a_d = reference_centre_distance(b.Z1, b.Z2, b.m_t);
  return b;
}

// Tip diameters and the specific sliding difference for a trial x1 (x2 = sum_x - x1).
double sliding_difference(const Basics& b, double sum_x, double k, double a, double alpha_wt, double x1) {
  const double x2 = sum_x - x1;
  const double d_a1 = tip_diameter(b.d1, b.m_n, b.rack[0].h_aP, x1, k);
  const double d_a2 = tip_diameter(b.d2, b.m_n, b.rack[1].h_aP, x2, k);
  const double z1 = max_specific_sliding(b.Z1, b.Z2, b.d_b2, d_a2, a, alpha_wt);
  const double z2 = max_specific_sliding(b.Z2, b.Z1, b.d_b1, d_a1, a, alpha_wt);
  if (std::isinf(z1) && std::isinf(z2)) return std::numeric_limits<double>::quiet_NaN();
  if (std::isinf(z1)) return -1e300;
  if (std::isinf(z2)) return 1e300;
  return z1 - z2;
}

// x1 that equalises the maximum specific sliding of both gears (bisection: the difference
// grows monotonically with x1). Returns NaN when no split brackets a solution.
double balanced_x1(const Basics& b, double sum_x, double k, double a, double alpha_wt) {
  double lo = 0.5 * sum_x - 3.0, hi = 0.5 * sum_x + 3.0;
  double f_lo = sliding_difference(b, sum_x, k, a, alpha_wt, lo);
  double f_hi = sliding_difference(b, sum_x, k, a, alpha_wt, hi);
  if (!(f_lo < 0.0 && f_hi > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  for (int i = 0; i < 200 && hi - lo > 1e-13; ++i) {
    const double mid = 0.5 * (lo + hi);
    const double f = sliding_difference(b, sum_x, k, a, alpha_wt, mid);
    if (std::isnan(f)) return f;
    (f < 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// KHK "Gear Technical Reference", internal gears, trochoid interference: the pinion tip must
// clear the ring tip while entering and leaving the mesh:
// theta1 z1/z2 + inv a_w - inv a_a2 >= theta2 (all magnitudes). Returns that margin, or +inf
// when the tip circles do not intersect (no interference possible).
double trochoid_margin(double r_a1, double r_a2, double r_b1, double r_b2, double a, int z1, int z2, double alpha_w) {
  const double c1 = (r_a2 * r_a2 - r_a1 * r_a1 - a * a) / (2.0 * a * r_a1);
  const double c2 = (a * a + r_a2 * r_a2 - r_a1 * r_a1) / (2.0 * a * r_a2);
  if (std::fabs(c1) > 1.0 || std::fabs(c2) > 1.0) return std::numeric_limits<double>::infinity();
  const double alpha_a1 = tip_pressure_angle(r_b1, r_a1);
  const double alpha_a2 = tip_pressure_angle(r_b2, r_a2);
  const double theta1 = std::acos(c1) + involute(alpha_a1) - involute(alpha_w);
  const double theta2 = std::acos(c2);
  return theta1 * z1 / z2 + involute(alpha_w) - involute(alpha_a2) - theta2;
}

// Same as make_tooth_data, from the pair's angles (computed once per pair, not per measurement).
ToothData tooth_data(int i, const Basics& b, double s_t) {
  ToothData g{i == 0 ? b.Z1 : b.Z2, b.m_n, b.alpha_n, b.beta, s_t};
  g.m_t = b.m_t;
  g.alpha_t = b.alpha_t;
  g.inv_alpha_t = b.inv_alpha_t;
  g.d = i == 0 ? b.d1 : b.d2;
  g.d_b = i == 0 ? b.d_b1 : b.d_b2;
  g.beta_b = b.beta_b;
  g.cos_beta = b.cos_beta;
  g.cos_beta_b = b.cos_beta_b;
  g.tan_alpha_n = b.tan_alpha_n;
  g.x = (s_t / b.m_t - std::numbers::pi / 2.0) / (2.0 * b.tan_alpha_n);
  return g;
}

}  // namespace

namespace {

// Transverse tip thickness of external gear i with shift x at its full (not shortened) tip
// circle d + 2 m_n (h_aP* + x); positive when the tip lies inside the base circle.
double full_tip_thickness(const Basics& b, int i, double x) {
  const double d = i == 0 ? b.d1 : b.d2;
  const double d_b = i == 0 ? b.d_b1 : b.d_b2;
  const double d_a = tip_diameter(d, b.m_n, b.rack[i].h_aP, x, 0.0);
  if (std::fabs(d_a) <= std::fabs(d_b)) return 1.0;
  return tooth_thickness_at(reference_tooth_thickness(b.m_t, x, b.alpha_n), d, d_b, b.alpha_t, d_a);
}

// Shift coefficient at which the tooth of external gear i becomes pointed at its full tip circle
// (the tip thickness decreases monotonically with x: bisection to 1e-7).
double pointed_shift(const Basics& b, int i) {
  double lo = -0.5, hi = 20.0;
  while (hi - lo > 1e-7) {
    const double mid = 0.5 * (lo + hi);
    (full_tip_thickness(b, i, mid) > 0.0 ? lo : hi) = mid;
  }
  return lo;
}

GearPairResult compute_checked(const GearPairInput& in);

}  // namespace

GearPairResult compute_gear_pair(const GearPairInput& in) {
  // Degenerate geometry that slipped through the checks (a diameter inside a base circle, an
  // angle out of range) is the input's fault: report it against the input, never as a crash.
  try {
    return compute_checked(in);
  } catch (const GeometryError&) {
    throw;
  } catch (const std::domain_error& e) {
    throw GeometryError(in.centre_distance ? "centre_distance" : "x1",
                        fmt::format("the pair has no valid geometry with these data: {}", e.what()));
  }
}

namespace {

// Working values shared by the steps of compute_checked (signed ISO 21771 values).
struct Work {
  const GearPairInput& in;
  Basics b;
  double sign = 1.0;
  double x1 = 0, x2 = 0, a = 0, alpha_wt = 0, k_used = 0;
  double s_t[2] = {0, 0}, A_sn[2] = {0, 0}, d_a[2] = {0, 0}, rho_Ff[2] = {0, 0};
  double rho_tip1 = 0, rho_tip2 = 0, g_len = 0;
  BacklashInput bl{};
};

// The undercut limit of gear i (external) by the chosen criterion; -inf for a ring.
double undercut_limit_of(const Basics& b, int i, UndercutLimit limit) {
  const int z = i == 0 ? b.Z1 : b.Z2;
  if (z < 0) return -std::numeric_limits<double>::infinity();
  if (limit == UndercutLimit::iso) return min_shift_no_undercut(i == 0 ? b.d1 : b.d2, b.m_n, b.alpha_t, b.rack[i]);
  const double z_n = b.beta == 0.0 ? z : virtual_number_of_teeth(z, b.beta, b.alpha_n);
  return practical_min_shift(z_n, b.rack[i]);
}

// The split with the least max |x_i| that keeps x_i >= the undercut limits: x1 = sum/2
// clamped to [x_min1, sum - x_min2]; NaN when that interval is empty.
double min_shift_x1(const Basics& b, double sum_x, UndercutLimit limit) {
  const double lo = undercut_limit_of(b, 0, limit), hi = sum_x - undercut_limit_of(b, 1, limit);
  if (lo > hi + 1e-12) return std::numeric_limits<double>::quiet_NaN();
  return std::clamp(0.5 * sum_x, lo, std::max(lo, hi));
}

// Shifts and working pressure angle for a given centre distance (the split of the shift sum).
void mount_at_centre_distance(Work& w, GearPairResult& r) {
  const GearPairInput& in = w.in;
  const Basics& b = w.b;
  PairResult& p = r.pair;
  double &x1 = w.x1, &x2 = w.x2, &a = w.a, &alpha_wt = w.alpha_wt;
  x1 = in.x1;
  x2 = in.x2;
  const double sign = w.sign;
  const double x_thin = -std::numbers::pi / (4.0 * b.tan_alpha_n);  // s = 0 at the reference circle
  const double a_in = *in.centre_distance;
  require(std::isfinite(a_in) && a_in > 0.0, "centre_distance", [&] { return fmt::format("expected a centre distance > 0 mm, found {}", a_in); });
  a = sign * a_in;
  try {
    alpha_wt = working_pressure_angle_for_centre_distance(b.a_d, b.alpha_t, a);
  } catch (const std::domain_error&) {
    throw GeometryError("centre_distance",
                        fmt::format("the pair cannot reach {:.4f} mm: the centre distance must be at least {:.4f} mm ({} of the base radii)",
                                    a_in, std::fabs(b.a_d * std::cos(b.alpha_t)), in.internal ? "difference" : "sum"));
  }
  p.sum_x = sum_of_shifts(b.Z1, b.Z2, b.alpha_t, b.alpha_n, alpha_wt);
  const double y = centre_distance_modification(a, b.a_d, b.m_n);
  const double k = std::max(0.0, tip_shortening(p.sum_x, y));
  const double k_used = in.apply_tip_shortening ? k : 0.0;
  p.split = in.split;
  switch (in.split) {
    case ShiftSplit::user_x1: x1 = in.x1; break;
    case ShiftSplit::proportional: x1 = p.sum_x * b.Z1 / (b.Z1 + b.Z2); break;
    case ShiftSplit::min_shift:
      x1 = min_shift_x1(b, p.sum_x, in.undercut_limit);
      if (std::isnan(x1)) {
        x1 = undercut_limit_of(b, 0, in.undercut_limit);
        r.warnings.push_back(fmt::format("no split of x1 + x2 = {:.4f} keeps both gears above the {} undercut limit; gear 1 "
                                         "gets its limit x1 = {:.4f}", p.sum_x, to_string(in.undercut_limit), x1));
      }
      break;
    case ShiftSplit::balanced_sliding:
      x1 = balanced_x1(b, p.sum_x, k_used, a, alpha_wt);
      if (std::isnan(x1)) {
        x1 = p.sum_x * b.Z1 / (b.Z1 + b.Z2);
        p.split = ShiftSplit::proportional;
        r.warnings.push_back("no split of the shift sum balances the specific sliding; the proportional split is used");
      }
      break;
  }
  x2 = p.sum_x - x1;
  // Reachable unless the split leaves a pointed tooth; then the shift sum decides whether any
  // split could do better (error) or only this one is poor (warnings follow).
  if (!in.internal && (full_tip_thickness(b, 0, x1) <= 0.0 || full_tip_thickness(b, 1, x2) <= 0.0)) {
    const double limit = pointed_shift(b, 0) + pointed_shift(b, 1);
    if (p.sum_x > limit) {
      throw GeometryError("centre_distance",
                          fmt::format("the pair cannot reach {:.4f} mm: it needs x1 + x2 = {:.4f}, but the teeth become "
                                      "pointed beyond x1 + x2 = {:.4f} (at most {:.4f} mm)",
                                      a_in, p.sum_x, limit, std::fabs(centre_distance(b.a_d, b.alpha_t,
                                          working_pressure_angle(b.alpha_t, b.alpha_n, b.Z1, b.Z2, limit)))));
    }
  }
  if (x1 <= x_thin || x2 <= x_thin) {
    throw GeometryError("centre_distance",
                        fmt::format("the pair cannot reach {:.4f} mm: the shift split x1 = {:.4f}, x2 = {:.4f} leaves no tooth at "
                                    "the reference circle",
                                    a_in, x1, x2));
  }
}

// Working pressure angle and centre distance for given shifts.
void mount_at_shifts(Work& w, GearPairResult& r) {
  const Basics& b = w.b;
  PairResult& p = r.pair;
  double &x1 = w.x1, &x2 = w.x2, &a = w.a, &alpha_wt = w.alpha_wt;
  x1 = w.in.x1;
  x2 = w.in.x2;
  const double x_thin = -std::numbers::pi / (4.0 * b.tan_alpha_n);  // s = 0 at the reference circle
  require(std::isfinite(x1) && x1 > x_thin, "x1", [&] { return fmt::format("expected x1 > {:.4f} (tooth thickness > 0), found {}", x_thin, x1); });
  require(std::isfinite(x2) && x2 > x_thin, "x2", [&] { return fmt::format("expected x2 > {:.4f} (tooth thickness > 0), found {}", x_thin, x2); });
  p.sum_x = x1 + x2;
  p.split = ShiftSplit::user_x1;
  try {
    alpha_wt = working_pressure_angle(b.alpha_t, b.alpha_n, b.Z1, b.Z2, p.sum_x);
  } catch (const std::domain_error&) {
    throw GeometryError("x2", fmt::format("the shift sum x1 + x2 = {:.4f} is out of reach: it would need a working pressure "
                                          "angle below zero (the base circles would overlap)",
                                          p.sum_x));
  }
  a = centre_distance(b.a_d, b.alpha_t, alpha_wt);
}

void pair_basics(Work& w, PairResult& p) {
  const GearPairInput& in = w.in;
  const Basics& b = w.b;
  const double a = w.a, alpha_wt = w.alpha_wt, x1 = w.x1, x2 = w.x2;
  p.alpha_wt = alpha_wt;
  p.a = std::fabs(a);
  p.a_d = std::fabs(b.a_d);
  p.y = centre_distance_modification(a, b.a_d, b.m_n);
  p.k = tip_shortening(p.sum_x, p.y);
  p.tip_shortened = in.apply_tip_shortening && p.k > 1e-12;
  w.k_used = p.tip_shortened ? p.k : 0.0;
  p.mounting = mounting_type(x1, x2);
  p.u = static_cast<double>(in.z2) / in.z1;
}

// Thickness allowances (given, or for a target backlash) and the backlash input.
void thickness_allowances(Work& w) {
  const GearPairInput& in = w.in;
  const Basics& b = w.b;
  const double a = w.a, sign = w.sign;
  double A_sn1 = in.A_sn1, A_sn2 = in.A_sn2;
  const double a_actual = a + sign * in.A_a;
  const double x_of[2] = {w.x1, w.x2};
  double* s_t = w.s_t;
  for (int i = 0; i < 2; ++i) s_t[i] = reference_tooth_thickness(b.m_t, x_of[i], b.alpha_n);
  w.bl = BacklashInput{b.Z1, b.Z2, b.d1, b.d2, b.d_b1, b.d_b2, b.alpha_t, b.beta_b, s_t[0], s_t[1], a_actual};
  if (in.backlash_target) {
    require(std::isfinite(*in.backlash_target) && *in.backlash_target >= 0.0, "backlash_target", [&] { return
            fmt::format("expected a backlash >= 0 mm, found {}", *in.backlash_target); });
    try {
      A_sn1 = A_sn2 = allowance_for_backlash(w.bl, b.alpha_n, *in.backlash_target);
    } catch (const std::domain_error&) {
      throw GeometryError("A_a", "the centre distance deviation puts the base circles out of reach");
    }
  }
  w.A_sn[0] = A_sn1;
  w.A_sn[1] = A_sn2;
}

// Dimensions of gear i.
void gear_dimensions(Work& w, int i, GearResult& g) {
  const Basics& b = w.b;
  const double a = w.a, k_used = w.k_used;
  const double x_of[2] = {w.x1, w.x2};
  const int Z[2] = {b.Z1, b.Z2};
  const double d[2] = {b.d1, b.d2};
  const double d_b[2] = {b.d_b1, b.d_b2};
  const double* s_t = w.s_t;
  const double* A_sn = w.A_sn;
  const bool ring = Z[i] < 0;
  g.z = std::abs(Z[i]);
  g.internal = ring;
  g.x = x_of[i];
  g.shift_mm = g.x * b.m_n;
  g.m_n = b.m_n;
  g.m_t = b.m_t;
  g.alpha_n = b.alpha_n;
  g.alpha_t = b.alpha_t;
  g.beta = b.beta;
  g.beta_b = b.beta_b;
  const double side = ring ? -1.0 : 1.0;  // explicit diameters are magnitudes
  const double d_a = w.in.d_a[i] ? side * *w.in.d_a[i] : tip_diameter(d[i], b.m_n, b.rack[i].h_aP, g.x, k_used);
  w.d_a[i] = d_a;
  const double d_f = w.in.d_f[i] ? side * *w.in.d_f[i] : root_diameter(d[i], b.m_n, b.rack[i].h_fP, g.x);
  const double d_w = 2.0 * a * Z[i] / (b.Z1 + b.Z2);
  g.d = std::fabs(d[i]);
  g.d_b = std::fabs(d_b[i]);
  g.d_w = std::fabs(d_w);
  g.d_a = std::fabs(d_a);
  g.d_f = std::fabs(d_f);
  g.p_t = std::numbers::pi * b.m_t;
  g.p_n = std::numbers::pi * b.m_n;
  g.p_bt = g.p_t * std::cos(b.alpha_t);
  g.p_en = g.p_n * std::cos(b.alpha_n);
  g.s_t = s_t[i];
  g.e_t = g.p_t - g.s_t;
  g.s_n = g.s_t * std::cos(b.beta);
  g.e_n = g.e_t * std::cos(b.beta);
  const ToothData nominal = tooth_data(i, b, s_t[i]);
  if (std::fabs(d_a) > std::fabs(d_b[i])) {
    const double s_at = tooth_thickness_at(nominal, d_a);
    g.s_an = b.beta == 0.0 ? s_at : s_at * std::cos(helix_angle_at(b.beta, d[i], d_a));
  } else {
    g.s_an = std::numeric_limits<double>::quiet_NaN();
  }
  g.z_n = b.beta == 0.0 ? g.z : std::fabs(virtual_number_of_teeth(Z[i], b.beta, b.alpha_n));
  g.A_sn = A_sn[i];
}

// Undercut limit, form circle and the measurements (span, pins, chordal) of gear i.
void gear_measurements(Work& w, int i, GearResult& g, std::vector<std::string>& warnings) {
  const GearPairInput& in = w.in;
  const Basics& b = w.b;
  const int Z[2] = {b.Z1, b.Z2};
  const double d[2] = {b.d1, b.d2};
  const double d_b[2] = {b.d_b1, b.d_b2};
  const double* s_t = w.s_t;
  const double* A_sn = w.A_sn;
  const bool ring = Z[i] < 0;
  const double d_a = w.d_a[i];
  const ToothData nominal = tooth_data(i, b, s_t[i]);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (!ring) {
    g.x_min = min_shift_no_undercut(d[i], b.m_n, b.alpha_t, b.rack[i]);
    g.x_min_practical = practical_min_shift(g.z_n, b.rack[i]);
    const double rho_Ff = form_roll_length(d_b[i], b.alpha_t, b.m_n, g.x, b.rack[i]);
    w.rho_Ff[i] = std::max(0.0, rho_Ff);
    g.d_Ff = rho_Ff > 0.0 ? 2.0 * std::hypot(0.5 * g.d_b, rho_Ff) : g.d_b;
  } else {
    g.x_min = nan;
    g.x_min_practical = nan;
    g.d_Ff = nan;
  }
  const ToothData actual = tooth_data(i, b, s_t[i] + A_sn[i] / std::cos(b.beta));
  if (!ring && g.z >= 2) {
    g.k_span = span_teeth(nominal);
    g.W_k = span_measurement(nominal, g.k_span);
    g.W_k_actual = A_sn[i] == 0.0 ? g.W_k : span_measurement(actual, g.k_span);
  } else {
    g.k_span = 0;
    g.W_k = g.W_k_actual = nan;
  }
  const std::optional<double>& D_given = i == 0 ? in.pin_diameter1 : in.pin_diameter2;
  try {
    if (D_given) {
      require(std::isfinite(*D_given) && *D_given > 0.0, i == 0 ? "pin_diameter1" : "pin_diameter2", [&] { return
              fmt::format("expected a pin diameter > 0 mm, found {}", *D_given); });
      g.pin_diameter = *D_given;
    } else {
      g.pin_diameter = pin_diameter_for_contact_at(nominal, d[i] + 2.0 * g.x * b.m_n);
    }
    g.M_d = dimension_over_pins(nominal, g.pin_diameter);
    g.M_d_actual = A_sn[i] == 0.0 ? g.M_d : dimension_over_pins(actual, g.pin_diameter);
  } catch (const std::domain_error&) {
    g.M_d = g.M_d_actual = nan;
    warnings.push_back(fmt::format("gear {}: no measurement over pins possible (the pin does not fit the tooth space)", i + 1));
  }
  g.chordal_s = chordal_thickness(nominal);
  g.chordal_h = chordal_height(nominal, d_a);
}

// Contact ratios, clearances, specific sliding and backlash.
void pair_quantities(Work& w, GearPairResult& r) {
  const GearPairInput& in = w.in;
  const Basics& b = w.b;
  PairResult& p = r.pair;
  const double a = w.a, alpha_wt = w.alpha_wt, sign = w.sign;
  const double* s_t = w.s_t;
  const double A_sn1 = w.A_sn[0], A_sn2 = w.A_sn[1];
  BacklashInput& bl = w.bl;
  const double d_a1 = (r.gear[0].d_a), d_a2 = sign * r.gear[1].d_a;
  const double d_f1 = r.gear[0].d_f, d_f2 = sign * r.gear[1].d_f;
  // Roll lengths to the tip circles (0 when a tip lies inside its base circle: the involute, and
  // the contact, end there), signed like the base radii.
  auto tip_roll = [](double d_b_i, double d_a_i) {
    return std::copysign(std::sqrt(std::max(0.0, 0.25 * (d_a_i * d_a_i - d_b_i * d_b_i))), d_b_i);
  };
  w.rho_tip1 = tip_roll(b.d_b1, d_a1);
  w.rho_tip2 = tip_roll(b.d_b2, d_a2);
  w.g_len = a * std::sin(alpha_wt);
  const double rho_tip1 = w.rho_tip1, rho_tip2 = w.rho_tip2;
  p.eps_alpha = transverse_contact_ratio_from_lengths(rho_tip1, rho_tip2, a, alpha_wt, r.gear[0].p_bt);
  p.eps_beta = overlap_ratio(common_face_width(in), b.beta, b.m_n);
  p.eps_gamma = p.eps_alpha + p.eps_beta;
  p.c1 = tip_clearance(a, d_a1, d_f2);
  p.c2 = tip_clearance(a, d_a2, d_f1);
  p.zeta1 = max_specific_sliding(b.Z1, b.Z2, b.d_b2, d_a2, a, alpha_wt);
  p.zeta2 = max_specific_sliding(b.Z2, b.Z1, b.d_b1, d_a1, a, alpha_wt);
  p.A_a = in.A_a;
  bl.s_t1 = s_t[0] + A_sn1 / std::cos(b.beta);
  bl.s_t2 = s_t[1] + A_sn2 / std::cos(b.beta);
  if (A_sn1 != 0.0 || A_sn2 != 0.0 || in.A_a != 0.0) {
    try {
      p.j_wt = circumferential_backlash(bl);
      p.j_bn = normal_backlash(p.j_wt, working_pressure_angle_at(bl), b.beta_b);
    } catch (const std::domain_error&) {
      throw GeometryError("A_a", "the centre distance deviation puts the base circles out of reach");
    }
  }  // else zero by construction: nominal teeth mesh without backlash at a (test_backlash.cpp)
}

void tooth_checks(const Work& w, GearPairResult& r) {
  const Basics& b = w.b;
  const PairResult& p = r.pair;
  auto warn = [&r](std::string text) { r.warnings.push_back(std::move(text)); };
  for (int i = 0; i < 2; ++i) {
    const GearResult& g = r.gear[i];
    if (!g.internal && g.x < g.x_min - 1e-9) {
      // The two criteria answer differently between x'_min and x_min: say which says what.
      if (g.x >= g.x_min_practical - 1e-9)
        warn(fmt::format("gear {}: undercut by ISO (x = {:.4f} < x_min = {:.4f}: the rack's tip rounding cuts into the "
                         "involute), but within the practical limit x'_min = {:.4f} of DIN 3960 and course notes "
                         "((14 - z)/17 at 20 deg), which accepts this slight undercut",
                         i + 1, g.x, g.x_min, g.x_min_practical));
      else
        warn(fmt::format("gear {}: undercut (x = {:.4f} < x_min = {:.4f}, and below the practical limit x'_min = {:.4f})",
                         i + 1, g.x, g.x_min, g.x_min_practical));
    }
    if (std::isnan(g.s_an)) {
      warn(fmt::format("gear {}: tip circle inside the base circle, the tip is not involute", i + 1));
    } else if (g.s_an <= 0.0) {
      warn(fmt::format("gear {}: pointed tooth (tip thickness {:.3f} mm)", i + 1, g.s_an));
    } else if (g.s_an < 0.2 * b.m_n) {
      warn(fmt::format("gear {}: thin tip, s_an = {:.3f} mm < 0.2 m_n = {:.3f} mm", i + 1, g.s_an, 0.2 * b.m_n));
    }
  }
  if (p.eps_alpha < 1.0) {
    warn(fmt::format("transverse contact ratio {:.3f} < 1: the pair does not mesh continuously", p.eps_alpha));
  } else if (p.eps_alpha < 1.2) {
    warn(fmt::format("transverse contact ratio {:.3f} < 1.2", p.eps_alpha));
  }
}

// Explicit root diameters that the tool does not cut: the tool data then do not describe the gear
// (the root rating and the form circle use the tool).
void root_diameter_checks(const Work& w, GearPairResult& r) {
  for (int i = 0; i < 2; ++i) {
    if (!w.in.d_f[i]) continue;
    const double cut = std::fabs(root_diameter(i == 0 ? w.b.d1 : w.b.d2, w.b.m_n, w.b.rack[i].h_fP, r.gear[i].x));
    if (std::fabs(*w.in.d_f[i] - cut) > 1e-3) {
      r.warnings.push_back(fmt::format("gear {}: root diameter d_f = {:.4f} mm given, the tool (h_fP* = {:g}) cuts {:.4f} mm: "
                                       "the tooth root rating uses the tool",
                                       i + 1, *w.in.d_f[i], w.b.rack[i].h_fP, cut));
    }
  }
}

// Involute and trochoid interference: the contact at the root of gear i must start on its
// generated involute.
void interference_checks(const Work& w, GearPairResult& r) {
  const GearPairInput& in = w.in;
  const Basics& b = w.b;
  const PairResult& p = r.pair;
  auto warn = [&r](std::string text) { r.warnings.push_back(std::move(text)); };
  const double g_len = w.g_len, rho_tip1 = w.rho_tip1, rho_tip2 = w.rho_tip2, alpha_wt = w.alpha_wt;
  const double d_a2 = w.sign * r.gear[1].d_a;
  const double* rho_Ff_of = w.rho_Ff;
  const double rho_root1 = g_len - rho_tip2;
  const double rho_root2 = g_len - rho_tip1;
  {
    const double rho_Ff1 = rho_Ff_of[0];
    if (rho_root1 < rho_Ff1 - 1e-9) {
      warn(fmt::format("involute interference: the tip of gear 2 reaches gear 1 below its form circle (d_Ff1 = {:.3f} mm)",
                       r.gear[0].d_Ff));
    }
    if (!in.internal) {
      const double rho_Ff2 = rho_Ff_of[1];
      if (rho_root2 < rho_Ff2 - 1e-9) {
        warn(fmt::format("involute interference: the tip of gear 1 reaches gear 2 below its form circle (d_Ff2 = {:.3f} mm)",
                         r.gear[1].d_Ff));
      }
    } else {
      if (std::fabs(d_a2) <= std::fabs(b.d_b2)) {
        warn("involute interference: the ring tip circle lies inside its base circle");
      }
      const double margin = trochoid_margin(0.5 * r.gear[0].d_a, 0.5 * r.gear[1].d_a, 0.5 * r.gear[0].d_b,
                                            0.5 * r.gear[1].d_b, p.a, in.z1, in.z2, alpha_wt);
      if (margin < 0.0) {
        warn(fmt::format("tip interference of the internal pair (trochoid interference, margin {:.4f} rad)", margin));
      }
    }
  }
}

// Whether the measurements can be taken, clearances and backlash.
void measurement_checks(const Work& w, GearPairResult& r) {
  const GearPairInput& in = w.in;
  const Basics& b = w.b;
  const PairResult& p = r.pair;
  auto warn = [&r](std::string text) { r.warnings.push_back(std::move(text)); };
  for (int i = 0; i < 2; ++i) {
    const GearResult& g = r.gear[i];
    // A micrometer needs the pins to stand out of the tip circle (inwards for a ring).
    if (std::isfinite(g.M_d) && (g.internal ? g.M_d >= g.d_a : g.M_d <= g.d_a)) {
      warn(fmt::format("gear {}: the {:.3f} mm pins do not stand out of the tip circle (M_d = {:.3f} mm, d_a = {:.3f} mm)",
                       i + 1, g.pin_diameter, g.M_d, g.d_a));
    }
    // The anvils of a span measurement must lie on the face: b > W_k sin(beta_b).
    const double b_i = face_width_of(in, i);
    if (g.k_span > 0 && b_i > 0.0 && b_i <= g.W_k * std::sin(std::fabs(b.beta_b))) {
      warn(fmt::format("gear {}: face width {:.3f} mm too narrow for the span over {} teeth (needs > {:.3f} mm)", i + 1,
                       b_i, g.k_span, g.W_k * std::sin(std::fabs(b.beta_b))));
    }
  }
  if (p.c1 < -1e-9) warn(fmt::format("negative tip clearance {:.3f} mm between the tip of gear 1 and the root of gear 2", p.c1));
  if (p.c2 < -1e-9) warn(fmt::format("negative tip clearance {:.3f} mm between the tip of gear 2 and the root of gear 1", p.c2));
  if (p.j_wt < -1e-9) warn(fmt::format("negative backlash {:.4f} mm: the teeth jam at the actual centre distance", p.j_wt));
}

void check_diameters(const GearPairInput& in) {
  for (int i = 0; i < 2; ++i) {
    for (const auto& [value, field] : {std::pair{in.d_a[i], i == 0 ? "d_a1" : "d_a2"}, std::pair{in.d_f[i], i == 0 ? "d_f1" : "d_f2"}}) {
      require(!value || (std::isfinite(*value) && *value > 0.0), field, [&] { return fmt::format("expected a diameter > 0 mm, found {}", *value); });
    }
  }
}

GearPairResult compute_checked(const GearPairInput& in) {
  check_diameters(in);
  Work w{in, basics_of(in)};
  w.sign = in.internal ? -1.0 : 1.0;
  GearPairResult r;
  if (in.centre_distance) {
    mount_at_centre_distance(w, r);
  } else {
    mount_at_shifts(w, r);
  }
  pair_basics(w, r.pair);
  thickness_allowances(w);
  for (int i = 0; i < 2; ++i) {
    gear_dimensions(w, i, r.gear[i]);
    gear_measurements(w, i, r.gear[i], r.warnings);
  }
  pair_quantities(w, r);
  tooth_checks(w, r);
  interference_checks(w, r);
  measurement_checks(w, r);
  root_diameter_checks(w, r);
  return r;
}

}  // namespace

}  // namespace gearkit::gear
