#include <gearkit/gear/inspection.hpp>

#include <gearkit/gear/cylindrical_gear.hpp>
#include <gearkit/gear/iso286.hpp>
#include <gearkit/gear/measurement.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace gearkit::gear {

const char* to_string(AllowanceSource source) {
  switch (source) {
    case AllowanceSource::given: return "given";
    case AllowanceSource::din3967: return "DIN 3967";
    case AllowanceSource::iso_tr_10064_2: break;
  }
  return "ISO/TR 10064-2";
}

int default_centre_distance_it(int grade) {
  if (grade <= 4) return 6;
  if (grade >= 11) return 10;
  return 7 + (grade - 5) / 2;  // 5-6: 7, 7-8: 8, 9-10: 9
}

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string field(const char* name, int i) { return fmt::format("{}{}", name, i + 1); }

// The pair as backlash.hpp sees it (signed ISO 21771 values), nominal thicknesses, nominal a.
BacklashInput nominal_pair(const GearPairInput& in, const GearPairResult& t) {
  const GearResult& g1 = t.gear[0];
  const int sign = in.internal ? -1 : 1;
  BacklashInput b;
  b.z1 = in.z1;
  b.z2 = sign * in.z2;
  b.d1 = reference_diameter(b.z1, g1.m_n, g1.beta);
  b.d2 = reference_diameter(b.z2, g1.m_n, g1.beta);
  b.d_b1 = base_diameter(b.d1, g1.alpha_t);
  b.d_b2 = base_diameter(b.d2, g1.alpha_t);
  b.alpha_t = g1.alpha_t;
  b.beta_b = g1.beta_b;
  b.s_t1 = g1.s_t;
  b.s_t2 = t.gear[1].s_t;
  b.a = sign * t.pair.a;
  return b;
}

ToothData tooth(const GearResult& g, int Z, double A_sn) {
  return make_tooth_data(Z, g.m_n, g.alpha_n, g.beta, g.s_t + A_sn / std::cos(g.beta));
}

std::optional<FlankTolerances> gear_tolerances(const GearPairInput& in, const GearResult& g, int i,
                                               const InspectionInput& ii) {
  if (!ii.grade[i]) return std::nullopt;
  ToleranceInput t;
  t.d = g.d;
  t.m_n = g.m_n;
  t.b = in.face_width;
  t.z = g.z;
  t.beta = g.beta;
  t.grade = *ii.grade[i];
  t.edition = ii.edition;
  try {
    return flank_tolerances(t);
  } catch (const std::domain_error& e) {
    throw GeometryError(field("grade", i), e.what());
  }
}

// Centre distance allowances: given, or the js field of the IT grade (given or from the grades).
void centre_distance_allowances(const GearPairResult& t, const InspectionInput& ii, PairInspection& p) {
  if (ii.centre_distance_allowances) {
    p.A_ae = ii.centre_distance_allowances->A_sne;
    p.A_ai = ii.centre_distance_allowances->A_sni;
    p.centre_distance_field = "given";
    if (!(p.A_ae >= p.A_ai)) {
      throw GeometryError("centre_distance_allowances",
                          fmt::format("expected upper >= lower, found {} < {} mm", p.A_ae, p.A_ai));
    }
    return;
  }
  std::optional<int> it = ii.centre_distance_it;
  if (!it && (ii.grade[0] || ii.grade[1])) {
    it = default_centre_distance_it(std::max(ii.grade[0].value_or(0), ii.grade[1].value_or(0)));
  }
  if (!it) {
    p.centre_distance_field = "none";
    return;
  }
  try {
    p.A_ae = js_limit_deviation(*it, t.pair.a);
  } catch (const std::domain_error& e) {
    throw GeometryError("centre_distance_it", e.what());
  }
  p.A_ai = -p.A_ae;
  p.centre_distance_field = fmt::format("js{}", *it);
}

// The states the minimum backlash must hold in: 20 deg C and, if given, the operating temperatures.
std::vector<BacklashInput> thermal_states(const BacklashInput& nominal, const InspectionInput& ii) {
  std::vector<BacklashInput> states{nominal};
  if (ii.T_gears || ii.T_housing) {
    const double T_g = ii.T_gears.value_or(20.0);
    const double T_h = ii.T_housing.value_or(T_g);
    states.push_back(at_temperature(nominal, ii.alpha_gear1 * (T_g - 20.0), ii.alpha_gear2 * (T_g - 20.0),
                                    ii.alpha_housing * (T_h - 20.0)));
  }
  return states;
}

// Sum of the upper allowances of both gears that leaves exactly j_target in the tightest state
// (allowance_for_backlash is exact: j_bn is linear in the allowances at a given distance).
double required_upper_sum(const std::vector<BacklashInput>& states, const PairInspection& p, double alpha_n,
                          double j_target) {
  double each = std::numeric_limits<double>::infinity();
  for (const BacklashInput& s : states) {
    for (double A_a : {p.A_ae, p.A_ai}) {
      each = std::min(each, allowance_for_backlash(with_centre_distance_deviation(s, A_a), alpha_n, j_target));
    }
  }
  return 2.0 * each;
}

// ISO/TR 10064-2 allowances of gear i given the upper allowance it must take.
void iso_tr_allowances(const GearResult& g, int i, const InspectionInput& ii, double A_sne, GearInspection& gi) {
  if (!gi.tolerances) {
    throw GeometryError(field("grade", i), fmt::format("gear {} needs an accuracy grade or its thickness allowances", i + 1));
  }
  gi.source = AllowanceSource::iso_tr_10064_2;
  try {
    gi.b_r = radial_infeed_tolerance(*ii.grade[i], g.d);
  } catch (const std::domain_error& e) {
    throw GeometryError(field("grade", i), e.what());
  }
  gi.allowances.A_sne = A_sne;
  gi.allowances.A_sni = A_sne - 1e-3 * tooth_thickness_tolerance(gi.tolerances->F_rT, gi.b_r, g.alpha_n);
}

ThicknessAllowances din3967_allowances_of(const Din3967Designation& designation, const GearResult& g, int i) {
  try {
    return din3967_allowances(designation, g.d);
  } catch (const std::exception& e) {  // an unknown series or a diameter beyond the tables
    throw GeometryError(field("din3967_", i), e.what());
  }
}

void thickness_allowances(const std::vector<BacklashInput>& states, const GearPairResult& t,
                          const InspectionInput& ii, InspectionResult& r) {
  double given_upper = 0.0;
  int computed = 0;
  for (int i = 0; i < 2; ++i) {
    GearInspection& gi = r.gear[i];
    if (ii.din3967[i] && !ii.allowances[i]) {
      gi.allowances = din3967_allowances_of(*ii.din3967[i], t.gear[i], i);
      gi.source = AllowanceSource::din3967;
      gi.din3967 = fmt::format("{}{}", ii.din3967[i]->tolerance_series, ii.din3967[i]->deviation_series);
      gi.b_r = kNaN;
      given_upper += gi.allowances.A_sne;
    } else if (ii.allowances[i]) {
      gi.allowances = *ii.allowances[i];
      if (!(gi.allowances.A_sne >= gi.allowances.A_sni)) {
        throw GeometryError(field("allowances", i), fmt::format("expected upper >= lower, found {} < {} mm",
                                                                gi.allowances.A_sne, gi.allowances.A_sni));
      }
      gi.b_r = kNaN;
      given_upper += gi.allowances.A_sne;
    } else {
      ++computed;
    }
  }
  const double alpha_n = t.gear[0].alpha_n;
  r.pair.j_bn_min_target =
      ii.j_bn_min ? *ii.j_bn_min : computed ? recommended_min_backlash(t.pair.a, t.gear[0].m_n) : kNaN;
  if (computed == 0) return;
  const double each = (required_upper_sum(states, r.pair, alpha_n, r.pair.j_bn_min_target) - given_upper) / computed;
  for (int i = 0; i < 2; ++i) {
    if (!ii.allowances[i] && !ii.din3967[i]) iso_tr_allowances(t.gear[i], i, ii, each, r.gear[i]);
  }
}

// Usable pin diameters of an external gear: contact on the usable flank (form circle to tip) at
// both thickness limits, and standing out of the tip circle.
void pin_range(const GearResult& g, const ToothData& thick, const ToothData& thin, GearInspection& gi) {
  gi.D_M_min = gi.D_M_max = kNaN;
  if (g.internal) return;
  try {
    const double d_low = std::max(std::isfinite(g.d_Ff) ? g.d_Ff : 0.0, g.d_b * (1.0 + 1e-6));
    gi.D_M_min = std::max({pin_diameter_for_contact_at(thick, d_low), pin_diameter_for_contact_at(thin, d_low),
                           pin_diameter_flush_with_tip(thick, g.d_a), pin_diameter_flush_with_tip(thin, g.d_a)});
    gi.D_M_max = std::min(pin_diameter_for_contact_at(thick, g.d_a), pin_diameter_for_contact_at(thin, g.d_a));
  } catch (const std::domain_error&) {
    gi.D_M_min = gi.D_M_max = kNaN;  // reported as "no usable pin" by the checks
  }
}

// The span of `thick` and `thin` teeth over k teeth and where its anvils touch; NaN for a ring.
struct Spans {
  double W_thick = kNaN, W_thin = kNaN, d_thick = kNaN, d_thin = kNaN;
};

Spans spans(const GearResult& g, const ToothData& thick, const ToothData& thin) {
  Spans s;
  if (g.k_span <= 0) return s;
  s.W_thick = span_measurement(thick, g.k_span);
  s.W_thin = span_measurement(thin, g.k_span);
  s.d_thick = span_contact_diameter(thick, s.W_thick);
  s.d_thin = span_contact_diameter(thin, s.W_thin);
  return s;
}

// Span and pin limits from the measurement allowances. Both take the thickest accepted tooth as one
// limit and the thinnest as the other (never re-sorted by value); without an acceptance band both
// are left undefined alike.
void measurements(const GearResult& g, int Z, GearInspection& gi) {
  gi.measured = measurement_allowances(gi.allowances, 1e-3 * gi.F_r, g.alpha_n);
  gi.acceptance_band = gi.measured.A_sne >= gi.measured.A_sni;
  const ToothData thick = tooth(g, Z, gi.measured.A_sne);
  const ToothData thin = tooth(g, Z, gi.measured.A_sni);
  gi.k = g.k_span;
  const Spans s = spans(g, thick, thin);
  gi.b_min_span = g.k_span > 0 ? std::max({g.W_k, s.W_thick, s.W_thin}) * std::sin(std::fabs(g.beta_b)) : kNaN;
  gi.D_M = g.pin_diameter;
  double M_thick = kNaN, M_thin = kNaN;
  try {
    M_thick = dimension_over_pins(thick, gi.D_M);
    M_thin = dimension_over_pins(thin, gi.D_M);
  } catch (const std::domain_error&) {
    M_thick = M_thin = kNaN;
  }
  const bool band = gi.acceptance_band;
  gi.W_k_max = band ? s.W_thick : kNaN;
  gi.W_k_min = band ? s.W_thin : kNaN;
  gi.d_W_max = band ? s.d_thick : kNaN;
  gi.d_W_min = band ? s.d_thin : kNaN;
  gi.M_d_max = band ? (g.internal ? M_thin : M_thick) : kNaN;
  gi.M_d_min = band ? (g.internal ? M_thick : M_thin) : kNaN;
  pin_range(g, thick, thin, gi);
}

// ---- checks (engineering problems are warnings) ----

void scope_warnings(const GearInspection& gi, int i, std::vector<std::string>& w) {
  if (!gi.tolerances || gi.tolerances->outside_scope.empty()) return;
  std::string list;
  for (const std::string& s : gi.tolerances->outside_scope) list += (list.empty() ? "" : ", ") + s;
  const bool is_2013 = gi.tolerances->edition == Iso1328Edition::iso2013;
  w.push_back(fmt::format("gear {}: outside the range of {} ({}): {}", i + 1, to_string(gi.tolerances->edition), list,
                          is_2013 ? "tolerances extrapolated, to be agreed between the parties"
                                  : "tolerances of the nearest tabulated range"));
}

void span_warnings(const GearPairInput& in, const GearResult& g, const GearInspection& gi, int i,
                   std::vector<std::string>& w) {
  if (!gi.acceptance_band) {
    w.push_back(fmt::format("gear {}: the thickness tolerance {:.4f} mm is narrower than the runout allows "
                            "(1.44 F_r tan alpha_n): no acceptance band, no span or pin limits", i + 1, gi.T_sn));
  }
  if (gi.k == 0) return;
  const double d_low = std::isfinite(g.d_Ff) ? g.d_Ff : g.d_b;
  if (gi.d_W_min < d_low || gi.d_W_max > g.d_a) {
    w.push_back(fmt::format("gear {}: the span anvils touch at d = {:.3f}..{:.3f} mm, outside the usable flank "
                            "{:.3f}..{:.3f} mm: choose another k", i + 1, gi.d_W_min, gi.d_W_max, d_low, g.d_a));
  }
  // The gear table already warns when the nominal span does not fit (gear_pair.hpp): one warning
  // per gear, this one only when the span limits need more face width than the nominal span.
  const bool nominal_warned = in.face_width > 0.0 && in.face_width <= g.W_k * std::sin(std::fabs(g.beta_b));
  if (in.face_width > 0.0 && in.face_width <= gi.b_min_span && !nominal_warned) {
    w.push_back(fmt::format("gear {}: face width {:.3f} mm too narrow for the span limits over {} teeth (needs > {:.3f} mm)",
                            i + 1, in.face_width, gi.k, gi.b_min_span));
  }
}

void pin_warnings(const GearResult& g, const GearInspection& gi, int i, std::vector<std::string>& w) {
  if (g.internal) return;
  if (!(gi.D_M_min <= gi.D_M_max)) {
    w.push_back(fmt::format("gear {}: no pin diameter touches the usable flank and stands out of the tip circle", i + 1));
  } else if (gi.D_M < gi.D_M_min || gi.D_M > gi.D_M_max) {
    w.push_back(fmt::format("gear {}: pin diameter {:.3f} mm outside the usable range {:.3f}..{:.3f} mm", i + 1, gi.D_M,
                            gi.D_M_min, gi.D_M_max));
  }
}

void backlash_warnings(const PairInspection& p, std::vector<std::string>& w) {
  if (p.range.min.j_n <= 0.0) {
    w.push_back(fmt::format("minimum backlash j_n,min = {:.4f} mm <= 0: the thickest teeth jam at the least "
                            "favourable centre distance", p.range.min.j_n));
  }
  if (p.operating && p.operating->min.j_n <= 0.0) {
    w.push_back(fmt::format("minimum backlash at the operating temperatures j_n,min = {:.4f} mm <= 0: the teeth "
                            "can jam when warm", p.operating->min.j_n));
  }
  if (std::isfinite(p.j_bn_min_target) && p.range.min.j_n < p.j_bn_min_target - 1e-9) {
    w.push_back(fmt::format("minimum backlash {:.4f} mm below the required {:.4f} mm", p.range.min.j_n,
                            p.j_bn_min_target));
  }
}

void inspection_checks(const GearPairInput& in, const GearPairResult& t, InspectionResult& r) {
  for (int i = 0; i < 2; ++i) {
    scope_warnings(r.gear[i], i, r.warnings);
    span_warnings(in, t.gear[i], r.gear[i], i, r.warnings);
    pin_warnings(t.gear[i], r.gear[i], i, r.warnings);
  }
  backlash_warnings(r.pair, r.warnings);
}

}  // namespace

InspectionResult compute_inspection(const GearPairInput& in, const GearPairResult& t, const InspectionInput& ii) {
  InspectionResult r;
  for (int i = 0; i < 2; ++i) {
    if (!ii.grade[i] && !ii.allowances[i] && !ii.din3967[i]) {
      throw GeometryError(field("grade", i), fmt::format("gear {} needs an accuracy grade or its thickness allowances", i + 1));
    }
    r.gear[i].tolerances = gear_tolerances(in, t.gear[i], i, ii);
    r.gear[i].F_r = r.gear[i].tolerances ? r.gear[i].tolerances->F_rT : 0.0;
  }
  centre_distance_allowances(t, ii, r.pair);
  const BacklashInput nominal = nominal_pair(in, t);
  const std::vector<BacklashInput> states = thermal_states(nominal, ii);
  try {
    thickness_allowances(states, t, ii, r);
    for (int i = 0; i < 2; ++i) {
      r.gear[i].T_sn = r.gear[i].allowances.A_sne - r.gear[i].allowances.A_sni;
      measurements(t.gear[i], i == 0 ? nominal.z1 : nominal.z2, r.gear[i]);
    }
    const PairLimits limits{r.gear[0].allowances.A_sne, r.gear[0].allowances.A_sni, r.gear[1].allowances.A_sne,
                            r.gear[1].allowances.A_sni, r.pair.A_ae, r.pair.A_ai};
    r.pair.range = backlash_range(nominal, t.gear[0].beta, limits);
    if (states.size() > 1) r.pair.operating = backlash_range(states[1], t.gear[0].beta, limits);
  } catch (const std::domain_error& e) {
    throw GeometryError("centre_distance_allowances", e.what());
  }
  inspection_checks(in, t, r);
  return r;
}

}  // namespace gearkit::gear
