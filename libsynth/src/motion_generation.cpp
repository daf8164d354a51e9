#include <gearkit/synth/motion_generation.hpp>

#include "plane.hpp"

#include <Eigen/Dense>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

namespace gearkit::synth {

namespace {

using cd = std::complex<double>;

void need_poses(std::span<const Pose> poses, std::size_t n, const char* what) {
  if (poses.size() != n) throw std::invalid_argument(fmt::format("{}: needs exactly {} poses", what, n));
}

double pose_scale(std::span<const Pose> poses) {
  double s = 0;
  for (const Pose& p : poses) s = std::max(s, (p.point - poses[0].point).norm());
  return std::max(s, 1e-9);
}

// The candidate without the transmission sweep; `quick` rates it by the angle at the poses only.
MotionCandidate assemble(std::span<const Pose> poses, const Dyad& in, const Dyad& out, bool require_crank,
                         bool quick) {
  MotionCandidate c;
  FourBar& f = c.linkage;
  f.O2 = in.ground_pivot;
  f.O4 = out.ground_pivot;
  f.crank = (in.moving_pivot - in.ground_pivot).norm();
  f.rocker = (out.moving_pivot - out.ground_pivot).norm();
  f.coupler = (out.moving_pivot - in.moving_pivot).norm();
  const double scale = std::max({f.crank, f.rocker, f.coupler, f.ground()});
  if (std::min({f.crank, f.rocker, f.coupler, f.ground()}) <= 1e-9 * scale || !(scale < 1e9))
    throw NoSolution("degenerate dyads: a link of zero length or two pivots together");
  const double theta3 = plane::angle_of(out.moving_pivot - in.moving_pivot);
  f.coupler_point = plane::rotate(poses[0].point - in.moving_pivot, -theta3);
  for (const Pose& p : poses) {
    const Vec2 A = carry(poses[0], p, in.moving_pivot), B = carry(poses[0], p, out.moving_pivot);
    c.theta2.push_back(plane::angle_of(A - f.O2));
    c.branches.push_back(branch_of(A, B, f.O4));
  }
  f.branch = c.branches[0] == 0 ? 1 : c.branches[0];
  c.defects = check_defects(f, c.theta2, c.branches, require_crank);
  c.link_ratio = scale / std::min({f.crank, f.rocker, f.coupler, f.ground()});
  if (quick || c.defects.order_defect) {
    c.transmission = {std::numbers::pi, 0};
    for (double t : c.theta2)
      if (const auto pose = pose_at(f, t)) {
        c.transmission.min = std::min(c.transmission.min, transmission_angle(*pose, f));
        c.transmission.max = std::max(c.transmission.max, transmission_angle(*pose, f));
      }
  } else {
    c.transmission = transmission_range(f, c.theta2[0], c.defects.travel, c.defects.direction);
  }
  return c;
}

}  // namespace

Pose pose_from_points(const Vec2& C, const Vec2& D) {
  if ((D - C).norm() == 0) throw std::invalid_argument("pose_from_points: C and D coincide");
  return {C, plane::angle_of(D - C)};
}

Vec2 carry(const Pose& from, const Pose& to, const Vec2& p) {
  return to.point + plane::rotate(plane::rotate(p - from.point, -from.angle), to.angle);
}

Dyad dyad_two_positions(const Pose& p1, const Pose& p2, const Vec2& moving_pivot, double offset) {
  const Vec2 M2 = carry(p1, p2, moving_pivot);
  const Vec2 chord = M2 - moving_pivot;
  if (chord.norm() <= 1e-12 * std::max(1.0, moving_pivot.norm()))
    throw NoSolution("the moving pivot does not move between the two poses (it sits on their pole)");
  const Vec2 u = chord.normalized();
  return {(moving_pivot + M2) / 2 + offset * Vec2(-u.y(), u.x()), moving_pivot};
}

Dyad dyad_from_moving_pivot(std::span<const Pose> poses, const Vec2& moving_pivot) {
  need_poses(poses, 3, "dyad_from_moving_pivot");
  const auto centre = plane::circumcentre(moving_pivot, carry(poses[0], poses[1], moving_pivot),
                                          carry(poses[0], poses[2], moving_pivot));
  if (!centre) throw NoSolution("the moving pivot's three positions are in line: no ground pivot");
  return {*centre, moving_pivot};
}

Dyad dyad_from_ground_pivot(std::span<const Pose> poses, const Vec2& ground_pivot) {
  need_poses(poses, 3, "dyad_from_ground_pivot");
  // The inversion: where the ground pivot appears to be, seen from the coupler in pose 1.
  const auto centre = plane::circumcentre(ground_pivot, carry(poses[1], poses[0], ground_pivot),
                                          carry(poses[2], poses[0], ground_pivot));
  if (!centre) throw NoSolution("seen from the coupler, the ground pivot's positions are in line: no moving pivot");
  return {ground_pivot, *centre};
}

Dyad dyad_from_rotations(std::span<const Pose> poses, double beta2, double beta3) {
  need_poses(poses, 3, "dyad_from_rotations");
  const auto e = [](double a) { return std::polar(1.0, a) - 1.0; };
  const auto c = [](const Vec2& v) { return cd(v.x(), v.y()); };
  const cd a11 = e(beta2), a12 = e(poses[1].angle - poses[0].angle);
  const cd a21 = e(beta3), a22 = e(poses[2].angle - poses[0].angle);
  const cd d2 = c(poses[1].point - poses[0].point), d3 = c(poses[2].point - poses[0].point);
  const cd det = a11 * a22 - a12 * a21;
  if (std::abs(det) < 1e-9) throw NoSolution("the dyad equations are singular for these free choices (beta = alpha?)");
  const cd W = (d2 * a22 - a12 * d3) / det, Z = (a11 * d3 - a21 * d2) / det;
  const cd P1 = c(poses[0].point);
  const cd G = P1 - W - Z, M = P1 - Z;
  return {{G.real(), G.imag()}, {M.real(), M.imag()}};
}

MotionCandidate four_bar_from_dyads(std::span<const Pose> poses, const Dyad& input, const Dyad& output,
                                    bool require_crank) {
  if (poses.size() < 2) throw std::invalid_argument("four_bar_from_dyads: needs at least two poses");
  return assemble(poses, input, output, require_crank, false);
}

bool better_candidate(const MotionCandidate& a, const MotionCandidate& b, double max_link_ratio) {
  if (a.defects.ok() != b.defects.ok()) return a.defects.ok();
  const bool ra = a.link_ratio <= max_link_ratio, rb = b.link_ratio <= max_link_ratio;
  if (ra != rb) return ra;
  return a.transmission.min > b.transmission.min;
}

MotionCandidate best_two_position(std::span<const Pose> poses, const Vec2& in_pivot, const Vec2& out_pivot, int grid,
                                  double max_link_ratio, bool require_crank) {
  need_poses(poses, 2, "best_two_position");
  if (grid < 2 || grid > kMaxTwoPositionGrid) throw std::invalid_argument("best_two_position: grid out of range");
  const double l_in = (carry(poses[0], poses[1], in_pivot) - in_pivot).norm();
  const double l_out = (carry(poses[0], poses[1], out_pivot) - out_pivot).norm();
  std::optional<MotionCandidate> best;
  for (int i = 0; i < grid; ++i)
    for (int j = 0; j < grid; ++j) {
      try {
        const double si = (-2 + 4.0 * i / (grid - 1)) * l_in, sj = (-2 + 4.0 * j / (grid - 1)) * l_out;
        MotionCandidate c = assemble(poses, dyad_two_positions(poses[0], poses[1], in_pivot, si),
                                     dyad_two_positions(poses[0], poses[1], out_pivot, sj), require_crank, false);
        if (!best || better_candidate(c, *best, max_link_ratio)) best = std::move(c);
      } catch (const NoSolution&) {
      }
    }
  if (!best) throw NoSolution("no two-position four-bar: the moving pivots do not move between the poses");
  return *best;
}

MotionCandidate best_three_position(std::span<const Pose> poses, int grid, double max_link_ratio,
                                    bool require_crank) {
  need_poses(poses, 3, "best_three_position");
  if (grid < 2 || grid > kMaxThreePositionGrid) throw std::invalid_argument("best_three_position: grid out of range");
  const double span = pose_scale(poses);
  Vec2 lo = poses[0].point, hi = poses[0].point;
  for (const Pose& p : poses) {
    lo = lo.cwiseMin(p.point);
    hi = hi.cwiseMax(p.point);
  }
  lo -= Vec2(span, span);
  hi += Vec2(span, span);
  std::vector<Dyad> dyads;
  for (int i = 0; i < grid; ++i)
    for (int j = 0; j < grid; ++j) {
      const Vec2 m(lo.x() + (hi.x() - lo.x()) * i / (grid - 1), lo.y() + (hi.y() - lo.y()) * j / (grid - 1));
      try {
        const Dyad d = dyad_from_moving_pivot(poses, m);
        dyads.push_back(d);
      } catch (const NoSolution&) {
      }
    }
  return best_pair_of_dyads(poses, dyads, max_link_ratio, require_crank);
}

MotionCandidate best_pair_of_dyads(std::span<const Pose> poses, std::span<const Dyad> dyads, double max_link_ratio,
                                   bool require_crank) {
  const auto better = [&](const MotionCandidate& a, const MotionCandidate& b) {
    return better_candidate(a, b, max_link_ratio);
  };
  // Pivots more than five times the poses' spread away make a linkage far larger than its task.
  Vec2 centre(0, 0);
  for (const Pose& p : poses) centre += p.point / static_cast<double>(poses.size());
  const double reach = 5 * pose_scale(poses);
  const auto near = [&](const Dyad& d) {
    return (d.ground_pivot - centre).norm() <= reach && (d.moving_pivot - centre).norm() <= reach;
  };
  std::vector<MotionCandidate> shortlist;
  for (std::size_t i = 0; i < dyads.size(); ++i)
    for (std::size_t j = 0; j < dyads.size(); ++j) {
      if (i == j || !near(dyads[i]) || !near(dyads[j])) continue;
      try {
        shortlist.push_back(assemble(poses, dyads[i], dyads[j], require_crank, true));
      } catch (const NoSolution&) {
        continue;
      }
      if (shortlist.size() > 64) {
        std::partial_sort(shortlist.begin(), shortlist.begin() + 16, shortlist.end(), better);
        shortlist.resize(16);
      }
    }
  if (shortlist.empty()) throw NoSolution("no pair of the dyads assembles into a four-bar");
  std::optional<MotionCandidate> best;
  for (MotionCandidate& c : shortlist) {
    if (!c.defects.order_defect)
      c.transmission = transmission_range(c.linkage, c.theta2[0], c.defects.travel, c.defects.direction);
    if (!best || better(c, *best)) best = std::move(c);
  }
  return *best;
}

}  // namespace gearkit::synth
