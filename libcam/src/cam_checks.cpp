#include <gearkit/cam/cam_checks.hpp>

#include "program_extremum.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gearkit::cam {
namespace {

constexpr double two_pi = 2 * std::numbers::pi;

bool folds_here(const CamDesign&, const ContactState& c) { return c.folds; }

/// +1 for a cam's own surface, -1 for a groove's outer wall (which bends the other way).
double wall_sign(const CamDesign& d) { return d.follower.surface == Surface::groove_outer_wall ? -1 : 1; }

/// The largest |pressure angle| at `samples` cam angles (a lower bound of the true largest);
/// +infinity if a flat face's envelope folds there.
double sampled_pressure_angle(const CamDesign& d, int samples) {
  double worst = 0;
  for (int i = 0; i < samples; ++i) {
    const ContactState c = contact_at(d, d.program.start() + two_pi * i / samples);
    if (d.follower.contact == Contact::flat_face && folds_here(d, c)) return INFINITY;
    worst = std::max(worst, std::abs(c.pressure_angle));
  }
  return worst;
}

/// The largest |pressure angle| over the turn, found (not sampled); +infinity if a flat face's
/// envelope folds anywhere.
double max_pressure_angle(const CamDesign& d, int samples) {
  auto f = [&](double theta) {
    const ContactState c = contact_at(d, theta);
    if (d.follower.contact == Contact::flat_face && folds_here(d, c)) return double(INFINITY);
    return std::abs(c.pressure_angle);
  };
  return detail::maximum_over_turn(d.program, f, samples).value;
}

/// Narrows a sampled extreme: the largest f near the sample at theta (spacing h), by
/// golden-section search over the two neighbouring intervals.
template <class F>
detail::Peak refine(double theta, double h, F&& f) {
  const detail::Peak sampled{theta, f(theta)};
  return detail::golden_maximum(f, theta - h, theta + h, 1e-12, sampled);
}

/// Replaces the sampled extremes of the checks with the extremes found near them.
void refine_extremes(const CamDesign& d, double h, CamChecks& r) {
  const double Rr = roller_radius(d), w = wall_sign(d);
  const bool flat = d.follower.contact == Contact::flat_face;
  {
    const detail::Peak p = refine(r.pressure_angle_max.theta, h,
                                  [&](double t) { return std::abs(contact_at(d, t).pressure_angle); });
    r.pressure_angle_max = {contact_at(d, p.x).pressure_angle, p.x};
  }
  if (flat && std::isfinite(r.rho_profile_min.value)) {
    const detail::Peak p = refine(r.rho_profile_min.theta, h, [&](double t) { return -1 / contact_at(d, t).curvature_profile; });
    r.rho_profile_min = r.rho_pitch_min = {-p.value, p.x};
  }
  if (!flat && std::isfinite(r.rho_pitch_min.value)) {
    const detail::Peak p = refine(r.rho_pitch_min.theta, h, [&](double t) { return contact_at(d, t).curvature_pitch; });
    r.rho_pitch_min = {1 / p.value, p.x};
  }
  if (!flat && std::isfinite(r.rho_profile_min.value)) {
    const detail::Peak p = refine(r.rho_profile_min.theta, h, [&](double t) { return w * contact_at(d, t).curvature_pitch; });
    r.rho_profile_min = {1 / p.value - Rr, p.x};
  }
  if (!flat && std::isfinite(r.rho_concave_min.value)) {
    const detail::Peak p = refine(r.rho_concave_min.theta, h, [&](double t) { return -w * contact_at(d, t).curvature_pitch; });
    r.rho_concave_min = {1 / p.value + Rr, p.x};
  }
}

/// The profile's radius of curvature where it is convex towards the follower [mm]; <= 0 where
/// it folds (undercut), +infinity where it is concave or straight.
double rho_of(const CamDesign& d, const ContactState& c) {
  if (d.follower.contact == Contact::flat_face) return c.envelope_regular ? 1 / c.curvature_profile : -INFINITY;
  const double k = wall_sign(d) * c.curvature_pitch;
  return k > 0 ? 1 / k - roller_radius(d) : INFINITY;
}

/// Undercuts narrower than the sampling: at every sampled local minimum of rho that is still
/// positive, the minimum between the neighbouring samples is found (golden-section search); if
/// it is <= 0 the fold's ends are found by bisection towards the samples either side (rho > 0).
void undercuts_between_samples(const CamDesign& d, double h, CamChecks& r) {
  auto rho = [&](double theta) { return rho_of(d, contact_at(d, theta)); };
  const std::size_t n = r.samples.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double prev = rho_of(d, r.samples[(i + n - 1) % n]), cur = rho_of(d, r.samples[i]),
                 next = rho_of(d, r.samples[(i + 1) % n]);
    if (!(cur > 0 && std::isfinite(cur) && cur <= prev && cur <= next && (cur < prev || cur < next))) continue;
    const double at = r.samples[i].theta;
    const detail::Peak low = detail::golden_maximum([&](double t) { return -rho(t); }, at - h, at + h, 1e-12, {at, -cur});
    if (low.value < 0) continue;
    auto edge = [&](double outside) {
      double in = low.x, out = outside;
      for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (in + out);
        (rho(mid) <= 0 ? in : out) = mid;
      }
      return in;
    };
    r.undercut = true;
    r.undercut_ranges.push_back({edge(at + h), edge(at - h)});  // {end (value), start (theta)}
  }
  std::sort(r.undercut_ranges.begin(), r.undercut_ranges.end(),
            [](const ValueAt& a, const ValueAt& b) { return a.theta < b.theta; });
}

}  // namespace

CamChecks check_design(const CamDesign& d, const CheckOptions& options) {
  CamChecks r;
  const int n = std::max(options.samples, 8);
  r.samples.reserve(n);
  r.rho_pitch_min.value = r.rho_profile_min.value = r.rho_concave_min.value = INFINITY;
  r.face_min = INFINITY, r.face_max = -INFINITY;
  const double Rr = roller_radius(d), w = wall_sign(d);
  bool in_fold = false;
  for (int i = 0; i < n; ++i) {
    const double theta = d.program.start() + two_pi * i / n;
    const ContactState c = contact_at(d, theta);
    r.samples.push_back(c);
    if (std::abs(c.pressure_angle) > std::abs(r.pressure_angle_max.value) || i == 0)
      r.pressure_angle_max = {c.pressure_angle, theta};
    if (d.follower.contact == Contact::flat_face) {
      const double rho = 1 / c.curvature_profile;
      if (rho < r.rho_profile_min.value) r.rho_profile_min = {rho, theta};
      r.rho_pitch_min = r.rho_profile_min;
      r.face_min = std::min(r.face_min, c.face_position);
      r.face_max = std::max(r.face_max, c.face_position);
    } else {
      if (c.curvature_pitch > 0 && 1 / c.curvature_pitch < r.rho_pitch_min.value)
        r.rho_pitch_min = {1 / c.curvature_pitch, theta};
      const double k = w * c.curvature_pitch;  // > 0 where the wall is convex towards the roller
      if (k > 0 && 1 / k - Rr < r.rho_profile_min.value) r.rho_profile_min = {1 / k - Rr, theta};
      if (k < 0 && -1 / k + Rr < r.rho_concave_min.value) r.rho_concave_min = {-1 / k + Rr, theta};
    }
    const bool fold = folds_here(d, c);
    if (fold && !in_fold) r.undercut_ranges.push_back({theta, theta});
    if (fold) r.undercut_ranges.back().value = theta;
    in_fold = fold;
    r.undercut = r.undercut || fold;
  }
  if (d.follower.contact != Contact::flat_face) r.face_min = r.face_max = 0;
  refine_extremes(d, two_pi / n, r);
  undercuts_between_samples(d, two_pi / n, r);
  r.radius_max = largest_radius(d);
  r.corners = pitch_corners(d);
  r.pressure_angle_exceeded = std::abs(r.pressure_angle_max.value) > options.pressure_angle_limit;
  r.base_radius_min = NAN;  // the groove's outer wall and the conjugate cam follow from the first cam
  if (d.follower.surface != Surface::cam) return r;
  try {
    r.base_radius_min = smallest_base_radius(d, options.pressure_angle_limit, std::min(n, 1440));
  } catch (const DesignError&) {
    r.base_radius_min = INFINITY;
  }
  return r;
}

ValueAt largest_radius(const CamDesign& d) {
  auto radius = [&](double theta) {
    const Vec2 p = contact_at(d, theta).contact;
    return std::hypot(p.x, p.y);
  };
  const detail::Peak p = detail::maximum_over_turn(d.program, radius, 720);
  return {p.value, p.x};
}

double smallest_base_radius(const CamDesign& d, double limit, int samples) {
  const Follower& f = d.follower;
  const double sigma = rotation_sign(d.rotation);
  const double Rr = f.contact == Contact::roller ? f.roller_radius : 0;
  if (f.motion == FollowerMotion::translating) {
    // The bound is the supremum over the turn, found piece by piece (a sampled maximum would
    // be short of it, leaving a cam "at the limit" cusped or over the limit).
    auto flat_need = [&](double theta) {
      const Motion m = d.program.at(theta);
      return -(m.s + m.d2s);
    };
    auto pitch_need = [&](double theta) {
      const Motion m = d.program.at(theta);
      return std::abs(m.ds - sigma * f.offset) / std::tan(limit) - m.s;
    };
    if (f.contact == Contact::flat_face) return std::max(0.0, detail::maximum_over_turn(d.program, flat_need, samples).value);
    const double need = std::max(0.0, detail::maximum_over_turn(d.program, pitch_need, samples).value);
    return std::max(std::hypot(need, f.offset) - Rr, Rr);
  }
  // Oscillating: march up from the smallest admissible circle and bisect on the sampled
  // pressure angle (fast, never above the true one), then finish the bisection on the largest
  // pressure angle found between the samples, so that the result meets the limit.
  auto meets = [&](double rb, bool found) {
    CamDesign trial = d;
    trial.base_radius = rb;
    try {
      validate(trial);
    } catch (const DesignError&) {
      return false;
    }
    return (found ? max_pressure_angle(trial, samples) : sampled_pressure_angle(trial, samples)) <= limit;
  };
  const double reach = f.contact == Contact::flat_face ? f.face_offset + f.pivot_distance
                                                       : f.pivot_distance + f.arm_length - Rr;
  double lo = std::max(Rr, 1e-3 * reach), hi = lo;
  auto fail = [&] {
    throw DesignError("base_radius", fmt::format("no base circle up to {:.6g} mm keeps the pressure angle within {:.6g} deg",
                                                 reach, limit * 180 / std::numbers::pi));
  };
  while (!meets(hi, false)) {
    lo = hi;
    hi *= 1.15;
    if (hi > reach) fail();
  }
  for (int k = 0; k < 40 && hi - lo > 1e-4 * hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    (meets(mid, false) ? hi : lo) = mid;
  }
  while (!meets(hi, true)) {  // the sampled bracket may be a hair short of the found maximum
    lo = hi;
    hi *= 1.001;
    if (hi > reach) fail();
  }
  for (int k = 0; k < 40 && hi - lo > 1e-6 * hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    (meets(mid, true) ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace gearkit::cam
