#include <gearkit/gear/sizing.hpp>

#include <gearkit/gear/inspection.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <optional>

namespace gearkit::gear {

std::vector<double> iso54_series1() { return {1, 1.25, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10, 12, 16, 20, 25}; }

namespace {

void check(const SizingInput& in) {
  validate(in.load);
  auto require = [](bool ok, const char* field, const std::string& message) {
    if (!ok) throw RatingError(field, message);
  };
  require(std::isfinite(in.ratio) && in.ratio >= 1.0 && in.ratio <= 20.0, "ratio", fmt::format("expected a ratio 1..20, found {}", in.ratio));
  require(in.ratio_tolerance >= 0.0 && in.ratio_tolerance <= 0.2, "ratio_tolerance",
          fmt::format("expected a ratio tolerance 0..0.2, found {}", in.ratio_tolerance));
  require(in.z1_min >= 5 && in.z1_max >= in.z1_min && in.z1_max <= 500, "z1",
          fmt::format("expected 5 <= z1 min <= z1 max <= 500, found {}..{}", in.z1_min, in.z1_max));
  for (double m : in.modules) require(std::isfinite(m) && m > 0.0 && m <= 100.0, "modules", fmt::format("expected modules in (0, 100] mm, found {}", m));
  for (double x : in.shifts) require(std::isfinite(x) && std::fabs(x) <= 1.0, "shifts", fmt::format("expected |x1| <= 1, found {}", x));
  require(in.width_ratio_max > 0.0 && in.width_ratio_max <= 3.0, "width_ratio", fmt::format("expected b/d1 in (0, 3], found {}", in.width_ratio_max));
  require(in.width_module_min >= 0.0 && in.width_module_min <= 100.0, "width_module",
          fmt::format("expected b/m_n 0..100, found {}", in.width_module_min));
  require(in.count >= 1 && in.count <= 100, "count", fmt::format("expected 1..100 candidates, found {}", in.count));
  require(!in.centre_distance || (std::isfinite(*in.centre_distance) && *in.centre_distance > 0.0), "centre_distance",
          fmt::format("expected a centre distance > 0 mm, found {}", in.centre_distance.value_or(0.0)));
  require(std::isfinite(in.x_sum_min) && std::isfinite(in.x_sum_max) && in.x_sum_min <= in.x_sum_max, "centre_distance",
          fmt::format("expected shift sum limits min <= max, found {} and {}", in.x_sum_min, in.x_sum_max));
  // With hunting teeth every z2 within the tolerance is tried; with a centre distance one shift per pair.
  const long long z2_per_z1 = in.hunting_tooth ? static_cast<long long>(std::ceil(2.0 * in.ratio_tolerance * in.ratio * in.z1_max)) + 1 : 1;
  const long long n = static_cast<long long>(in.modules.empty() ? iso54_series1().size() : in.modules.size()) *
                      (in.z1_max - in.z1_min + 1) * (in.centre_distance ? 1LL : static_cast<long long>(in.shifts.size())) * z2_per_z1;
  require(n <= kMaxSizingCombinations, "modules",
          fmt::format("{} module x tooth count x shift combinations exceed the limit of {}", n, kMaxSizingCombinations));
}

// Geometry problems that rule a candidate out (warnings that are not only advice).
bool unusable(const GearPairResult& g) {
  for (const auto& w : g.warnings) {
    for (const char* bad : {"undercut", "interference", "pointed", "does not mesh", "thin tip", "negative"}) {
      if (w.find(bad) != std::string::npos) return true;
    }
  }
  return false;
}

struct Trial {
  GearPairInput geometry;
  double margin = -1;  // min(S_H/S_Hmin, S_F/S_Fmin) over both gears
  double S_H = 0, S_F = 0;
  double a = 0;  // working centre distance of the geometry
};

Trial rate_at_width(GearPairInput geometry, const RatingInput& load, double b, long long& evaluated) {
  Trial t;
  geometry.face_width = b;
  t.geometry = geometry;
  GearPairResult g;
  try {
    g = compute_gear_pair(geometry);
  } catch (const GeometryError&) {
    return t;
  }
  if (unusable(g)) return t;
  t.a = g.pair.a;
  ++evaluated;
  PairRating r;
  try {
    r = rate_gear_pair(geometry, g, load);
  } catch (const RatingError&) {
    return t;  // a tooth form without a 30-degree tangent: not a candidate
  }
  t.S_H = std::min(r.gear[0].S_H, r.gear[1].S_H);
  t.S_F = std::min(r.gear[0].S_F, r.gear[1].S_F);
  t.margin = std::min(t.S_H / load.S_Hmin, t.S_F / load.S_Fmin);
  return t;
}

// The load with the upper thickness allowances of the grade by ISO/TR 10064-2 (inspection.hpp),
// as `gearkit gear --quality` rates the teeth: the allowances do not depend on the face width.
// nullopt when the inspection cannot find them (the pair is then not a candidate).
std::optional<RatingInput> load_with_allowances(const GearPairInput& geometry, const RatingInput& load, double b) {
  if (!load.quality || load.A_sne[0] || load.A_sne[1]) return load;
  GearPairInput g = geometry;
  g.face_width = b;
  InspectionInput ii;
  ii.grade = {*load.quality, *load.quality};
  ii.edition = load.iso1328_edition;
  try {
    const InspectionResult by_grade = compute_inspection(g, compute_gear_pair(g), ii);
    RatingInput with = load;
    for (int i = 0; i < 2; ++i) with.A_sne[i] = by_grade.gear[i].allowances.A_sne;
    return with;
  } catch (const GeometryError&) {
    return std::nullopt;
  }
}

// The smallest whole-millimetre face width that meets both minimum safety factors, by bisection
// (the safety factors grow with b); nullopt when even b_max does not.
std::optional<SizingCandidate> smallest_width(const GearPairInput& geometry, const SizingInput& in, long long& evaluated) {
  const double d1 = geometry.z1 * geometry.module / std::cos(geometry.helix_angle);
  const double d2 = d1 * geometry.z2 / geometry.z1;
  int hi = static_cast<int>(std::floor(in.width_ratio_max * d1));
  if (hi < 1) return std::nullopt;
  const std::optional<RatingInput> load = load_with_allowances(geometry, in.load, hi);
  if (!load) return std::nullopt;
  Trial best = rate_at_width(geometry, *load, hi, evaluated);
  if (best.margin < 1.0) return std::nullopt;
  int lo = static_cast<int>(std::ceil(in.width_module_min * geometry.module)) - 1;  // fails, or below the smallest width
  if (lo >= hi) return std::nullopt;
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    const Trial t = rate_at_width(geometry, *load, mid, evaluated);
    if (t.margin >= 1.0) {
      hi = mid;
      best = t;
    } else {
      lo = mid;
    }
  }
  SizingCandidate c;
  c.m_n = geometry.module;
  c.z1 = geometry.z1;
  c.z2 = geometry.z2;
  c.x1 = geometry.x1;
  c.x2 = geometry.x2;
  c.b = hi;
  c.u = static_cast<double>(geometry.z2) / geometry.z1;
  c.d1 = d1;
  c.d2 = d2;
  // V-0 pairs keep the reference centre distance as before; shifted pairs (a required centre
  // distance) report the working one the geometry computed.
  c.a = in.centre_distance ? best.a : 0.5 * (d1 + d2);
  c.S_H = best.S_H;
  c.S_F = best.S_F;
  c.volume = c.b * std::numbers::pi / 4.0 * (d1 * d1 + d2 * d2);
  return c;
}

// The wheel tooth counts tried with pinion z1: the nearest to u z1, or with hunting teeth every z2
// within the ratio tolerance that shares no factor with z1.
std::vector<int> wheel_teeth(const SizingInput& in, int z1) {
  auto within = [&](int z2) { return z2 >= z1 && std::fabs(static_cast<double>(z2) / z1 - in.ratio) <= in.ratio_tolerance * in.ratio; };
  std::vector<int> z2s;
  if (!in.hunting_tooth) {
    const int z2 = static_cast<int>(std::lround(in.ratio * z1));
    if (within(z2)) z2s.push_back(z2);
    return z2s;
  }
  const int lo = static_cast<int>(std::floor(in.ratio * (1.0 - in.ratio_tolerance) * z1));
  const int hi = static_cast<int>(std::ceil(in.ratio * (1.0 + in.ratio_tolerance) * z1));
  for (int z2 = lo; z2 <= hi; ++z2) {
    if (within(z2) && std::gcd(z1, z2) == 1) z2s.push_back(z2);
  }
  return z2s;
}

// The shifts of a pair at the required centre distance (compute_gear_pair's centre-distance path,
// balanced sliding), or nullopt when the distance cannot be met within the shift sum limits.
std::optional<GearPairInput> at_centre_distance(GearPairInput g, const SizingInput& in) {
  GearPairInput t = g;
  t.centre_distance = *in.centre_distance;
  t.split = ShiftSplit::balanced_sliding;
  try {
    const GearPairResult r = compute_gear_pair(t);
    const double sum = r.gear[0].x + r.gear[1].x;
    if (!(sum >= in.x_sum_min && sum <= in.x_sum_max)) return std::nullopt;
    g.x1 = r.gear[0].x;
    g.x2 = r.gear[1].x;
    return g;
  } catch (const GeometryError&) {
    return std::nullopt;
  }
}

}  // namespace

SizingResult size_gear_pair(const SizingInput& in) {
  check(in);
  SizingResult result;
  const std::vector<double> modules = in.modules.empty() ? iso54_series1() : in.modules;
  std::vector<SizingCandidate> all;
  const std::vector<double> x1s = in.centre_distance ? std::vector<double>{0.0} : in.shifts;
  for (double m : modules) {
    for (int z1 = in.z1_min; z1 <= in.z1_max; ++z1) {
      for (int z2 : wheel_teeth(in, z1)) {
        for (double x : x1s) {
          ++result.combinations;
          GearPairInput g;
          g.z1 = z1;
          g.z2 = z2;
          g.module = m;
          g.pressure_angle = in.pressure_angle;
          g.helix_angle = in.helix_angle;
          g.h_aP = in.h_aP;
          g.h_fP = in.h_fP;
          g.rho_fP = in.rho_fP;
          g.x1 = x;
          g.x2 = -x;
          if (in.centre_distance) {
            const auto shifted = at_centre_distance(g, in);
            if (!shifted) continue;
            g = *shifted;
          }
          if (auto c = smallest_width(g, in, result.evaluated)) all.push_back(*c);
        }
      }
    }
  }
  std::sort(all.begin(), all.end(), [](const SizingCandidate& a, const SizingCandidate& b) { return a.volume < b.volume; });
  if (static_cast<int>(all.size()) > in.count) all.resize(in.count);
  result.best = std::move(all);
  return result;
}

}  // namespace gearkit::gear
