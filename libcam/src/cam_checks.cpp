#include <gearkit/cam/cam_checks.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gearkit::cam {
namespace {

constexpr double two_pi = 2 * std::numbers::pi;

bool folds_here(const CamDesign& d, const ContactState& c) {
  if (d.follower.contact == Contact::flat_face) return !c.envelope_regular || !(c.curvature_profile > 0);
  if (d.follower.contact == Contact::roller) return c.curvature_pitch * d.follower.roller_radius >= 1;
  return false;
}

double max_pressure_angle(const CamDesign& d, int samples) {
  double worst = 0;
  for (int i = 0; i < samples; ++i) {
    const ContactState c = contact_at(d, d.program.start() + two_pi * i / samples);
    worst = std::max(worst, std::abs(c.pressure_angle));
    if (d.follower.contact == Contact::flat_face && folds_here(d, c)) return INFINITY;
  }
  return worst;
}

}  // namespace

CamChecks check_design(const CamDesign& d, const CheckOptions& options) {
  CamChecks r;
  const int n = std::max(options.samples, 8);
  r.samples.reserve(n);
  r.rho_pitch_min.value = r.rho_profile_min.value = r.rho_concave_min.value = INFINITY;
  r.face_min = INFINITY, r.face_max = -INFINITY;
  const double Rr = d.follower.contact == Contact::roller ? d.follower.roller_radius : 0;
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
    } else if (c.curvature_pitch > 0) {
      const double rho = 1 / c.curvature_pitch;
      if (rho < r.rho_pitch_min.value) r.rho_pitch_min = {rho, theta};
      if (rho - Rr < r.rho_profile_min.value) r.rho_profile_min = {rho - Rr, theta};
    } else if (c.curvature_pitch < 0) {
      const double rho = -1 / c.curvature_pitch + Rr;
      if (rho < r.rho_concave_min.value) r.rho_concave_min = {rho, theta};
    }
    const bool fold = folds_here(d, c);
    if (fold && !in_fold) r.undercut_ranges.push_back({theta, theta});
    if (fold) r.undercut_ranges.back().value = theta;
    in_fold = fold;
    r.undercut = r.undercut || fold;
  }
  if (d.follower.contact != Contact::flat_face) r.face_min = r.face_max = 0;
  r.pressure_angle_exceeded = std::abs(r.pressure_angle_max.value) > options.pressure_angle_limit;
  try {
    r.base_radius_min = smallest_base_radius(d, options.pressure_angle_limit, std::min(n, 1440));
  } catch (const DesignError&) {
    r.base_radius_min = INFINITY;
  }
  return r;
}

double smallest_base_radius(const CamDesign& d, double limit, int samples) {
  const Follower& f = d.follower;
  const double sigma = rotation_sign(d.rotation);
  const double Rr = f.contact == Contact::roller ? f.roller_radius : 0;
  if (f.motion == FollowerMotion::translating) {
    double need = 0;
    for (int i = 0; i < samples; ++i) {
      const Motion m = d.program.at(d.program.start() + two_pi * i / samples);
      if (f.contact == Contact::flat_face)
        need = std::max(need, -(m.s + m.d2s));
      else
        need = std::max(need, std::abs(m.ds - sigma * f.offset) / std::tan(limit) - m.s);
    }
    if (f.contact == Contact::flat_face) return need;
    return std::max(std::hypot(need, f.offset) - Rr, Rr);
  }
  // Oscillating: march up from the smallest admissible circle, then bisect.
  auto meets = [&](double rb) {
    CamDesign trial = d;
    trial.base_radius = rb;
    try {
      validate(trial);
    } catch (const DesignError&) {
      return false;
    }
    return max_pressure_angle(trial, samples) <= limit;
  };
  const double reach = f.contact == Contact::flat_face ? f.face_offset + f.pivot_distance
                                                       : f.pivot_distance + f.arm_length - Rr;
  double lo = std::max(Rr, 1e-3 * reach), hi = lo;
  while (!meets(hi)) {
    lo = hi;
    hi *= 1.15;
    if (hi > reach) {
      throw DesignError("base_radius", fmt::format("no base circle up to {} mm keeps the pressure angle within {} deg",
                                                   reach, limit * 180 / std::numbers::pi));
    }
  }
  for (int k = 0; k < 40 && hi - lo > 1e-6 * hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    (meets(mid) ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace gearkit::cam
