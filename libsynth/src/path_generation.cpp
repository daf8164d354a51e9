#include <gearkit/synth/path_generation.hpp>

#include <gearkit/synth/function_generation.hpp>

#include <gearkit/kin/fourbar.hpp>

#include <fmt/format.h>
#include <nlopt.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>

namespace gearkit::synth {

namespace {

constexpr double pi = std::numbers::pi;
constexpr double penalty_weight = 1e3;

// Variables of the design vector (normalised lengths, rad); crank increments follow T1 when the
// timing is free. The placement (O2 and the ground's direction) is not searched: for every
// candidate the best rigid placement onto the targets is solved in closed form (Kabsch).
enum Var { R1, R2, R3, R4, RCX, RCY, T1, FIRST_INCREMENT };

// The task in normalised units: lengths divided by the targets' span S, origin at their centre.
struct Problem {
  std::vector<Vec2> targets;
  std::vector<double> timing;  // empty: free
  PathConstraints constraints;
  double link_lo = 0, link_hi = 0;
  Region O2, O4;
  int branch = 1, direction = 1;
  long evaluations = 0;
  std::vector<double> theta2;  // scratch: crank angles in the linkage's frame
  std::vector<Vec2> local;     // scratch: coupler points in the linkage's frame
  std::vector<char> closed;    // scratch: assembled at that point
  int dimension() const { return FIRST_INCREMENT + (timing.empty() ? static_cast<int>(targets.size()) - 1 : 0); }
};

// global = R(angle) local + shift
struct Placement {
  double angle = 0;
  Vec2 shift{0, 0};
  Vec2 operator()(const Vec2& v) const {
    const double c = std::cos(angle), s = std::sin(angle);
    return Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y()) + shift;
  }
};

// The linkage in its own frame: O2 at the origin, O4 on the +x axis.
FourBar local_linkage(const double* x, int branch) {
  FourBar f;
  f.O4 = Vec2(x[R1], 0);
  f.crank = x[R2];
  f.coupler = x[R3];
  f.rocker = x[R4];
  f.coupler_point = Vec2(x[RCX], x[RCY]);
  f.branch = branch;
  return f;
}

void crank_angles(const double* x, const Problem& p, std::vector<double>& theta2) {
  theta2.resize(p.targets.size());
  double turn = 0;
  for (std::size_t j = 0; j < p.targets.size(); ++j) {
    if (j > 0) turn += p.timing.empty() ? x[FIRST_INCREMENT + j - 1] : p.timing[j] - p.timing[j - 1];
    theta2[j] = x[T1] + p.direction * turn;
  }
}

// The rigid motion that best maps the assembled local points onto their targets (2-D Kabsch:
// the rotation from the summed cross and dot products of the centred pairs).
Placement best_placement(const std::vector<Vec2>& local, const std::vector<Vec2>& targets, const std::vector<char>& closed) {
  Vec2 cl(0, 0), ct(0, 0);
  int n = 0;
  for (std::size_t j = 0; j < local.size(); ++j)
    if (closed[j]) {
      cl += local[j];
      ct += targets[j];
      ++n;
    }
  if (n == 0) return {};
  cl /= n;
  ct /= n;
  double sx = 0, sy = 0;
  for (std::size_t j = 0; j < local.size(); ++j)
    if (closed[j]) {
      const Vec2 u = local[j] - cl, v = targets[j] - ct;
      sx += u.dot(v);
      sy += u.x() * v.y() - u.y() * v.x();
    }
  Placement pl;
  pl.angle = std::atan2(sy, sx);
  pl.shift = ct - Placement{pl.angle, Vec2(0, 0)}(cl);
  return pl;
}

FourBar placed(const FourBar& local, const Placement& pl) {
  FourBar f = local;
  f.O2 = pl(local.O2);
  f.O4 = pl(local.O4);
  return f;
}

double squared(double v) { return v > 0 ? v * v : 0.0; }

double region_violation(const Region& r, const Vec2& p) {
  return squared(r.min.x() - p.x()) + squared(p.x() - r.max.x()) + squared(r.min.y() - p.y()) +
         squared(p.y() - r.max.y());
}

// Acute transmission angle at relative crank angle phi (from the ground line), or -1 if open.
double acute_transmission(double a, double b, double c, double d, double phi) {
  const double L2 = a * a + d * d - 2 * a * d * std::cos(phi);
  const double cmu = (b * b + c * c - L2) / (2 * b * c);
  if (std::abs(cmu) > 1) return -1;
  const double mu = std::acos(cmu);
  return std::min(mu, pi - mu);
}

// Sum of squared constraint violations (normalised lengths, rad).
double violations(const double* x, const Problem& p) {
  const PathConstraints& c = p.constraints;
  const double r[4] = {x[R1], x[R2], x[R3], x[R4]};
  const double s = *std::min_element(r, r + 4), l = *std::max_element(r, r + 4);
  double v = squared(l / s - c.max_link_ratio) * 0.01;
  if (c.require_crank()) {
    v += squared(s + l - (r[0] + r[1] + r[2] + r[3] - s - l) + 1e-3);
    // The shortest link: the crank or the ground (crank), or exactly one of them.
    if (c.grashof == GrashofType::crank) v += squared(std::min(x[R1], x[R2]) - std::min(x[R3], x[R4]));
    if (c.grashof == GrashofType::crank_rocker) v += squared(x[R2] - std::min({x[R1], x[R3], x[R4]}));
    if (c.grashof == GrashofType::double_crank) v += squared(x[R1] - std::min({x[R2], x[R3], x[R4]}));
    for (double phi : {0.0, pi}) {
      const double mu = acute_transmission(x[R2], x[R3], x[R4], x[R1], phi);
      v += mu < 0 ? 1.0 : squared(c.min_transmission - mu);
    }
  }
  if (p.timing.empty()) {
    double total = 0;
    for (int k = FIRST_INCREMENT; k < p.dimension(); ++k) total += x[k];
    v += squared(total - 2 * pi);
  }
  return v;
}

double objective(unsigned, const double* x, double*, void* data) {
  Problem& p = *static_cast<Problem*>(data);
  ++p.evaluations;
  const FourBar f = local_linkage(x, p.branch);
  crank_angles(x, p, p.theta2);
  const std::size_t n = p.targets.size();
  p.local.resize(n);
  p.closed.assign(n, 0);
  double e = 0;
  for (std::size_t j = 0; j < n; ++j) {
    const auto pose = pose_at(f, p.theta2[j]);
    if (!pose) {
      e += 1.0;
      continue;
    }
    p.local[j] = pose->P;
    p.closed[j] = 1;
    if (!p.constraints.require_crank())
      e += penalty_weight * squared(p.constraints.min_transmission - transmission_angle(*pose, f));
  }
  const Placement pl = best_placement(p.local, p.targets, p.closed);
  for (std::size_t j = 0; j < n; ++j)
    if (p.closed[j]) e += (pl(p.local[j]) - p.targets[j]).squaredNorm();
  const double regions = region_violation(p.O2, pl(f.O2)) + region_violation(p.O4, pl(f.O4));
  return e + penalty_weight * (violations(x, p) + regions);
}

struct Bounds {
  std::vector<double> lo, hi;
};

Bounds bounds_of(const Problem& p) {
  Bounds b;
  b.lo = {p.link_lo, p.link_lo, p.link_lo, p.link_lo, -3.0, -3.0, 0.0};
  b.hi = {p.link_hi, p.link_hi, p.link_hi, p.link_hi, 3.0, 3.0, 2 * pi};
  for (int k = FIRST_INCREMENT; k < p.dimension(); ++k) {
    b.lo.push_back(0.0);
    b.hi.push_back(2 * pi);
  }
  return b;
}

using Optimizer = std::unique_ptr<nlopt_opt_s, decltype(&nlopt_destroy)>;

// One NLopt stage from x (updated in place); returns the objective at the result.
double run_stage(nlopt_algorithm algorithm, Problem& p, const Bounds& b, std::vector<double>& x, long maxeval,
                 unsigned seed) {
  const auto n = static_cast<unsigned>(x.size());
  Optimizer opt(nlopt_create(algorithm, n), &nlopt_destroy);
  if (!opt) throw std::runtime_error("path generation: NLopt could not create the optimiser");
  nlopt_srand(seed);
  nlopt_set_lower_bounds(opt.get(), b.lo.data());
  nlopt_set_upper_bounds(opt.get(), b.hi.data());
  nlopt_set_min_objective(opt.get(), &objective, &p);
  nlopt_set_maxeval(opt.get(), static_cast<int>(std::max(1L, maxeval)));
  nlopt_set_xtol_rel(opt.get(), 1e-12);
  nlopt_set_ftol_abs(opt.get(), 1e-16);
  for (unsigned k = 0; k < n; ++k) x[k] = std::clamp(x[k], b.lo[k], b.hi[k]);
  double f = std::numeric_limits<double>::infinity();
  nlopt_optimize(opt.get(), x.data(), &f);  // a stop on maxeval or a roundoff-limited end is normal
  return objective(n, x.data(), nullptr, &p);
}

// The outcome of one global restart.
struct Start {
  std::vector<double> x;
  double f = 0;
  int branch = 1, direction = 1;
  long evaluations = 0;
};

std::vector<Start> global_stage(Problem& p, const Bounds& b, const PathBudget& budget, long evaluations) {
  std::vector<Start> starts;
  for (int k = 0; k < budget.restarts; ++k) {
    Start s;
    s.branch = p.branch = k % 2 == 0 ? 1 : -1;
    s.direction = p.direction = (k / 2) % 2 == 0 ? 1 : -1;
    p.evaluations = 0;
    s.x.resize(b.lo.size());
    for (std::size_t i = 0; i < s.x.size(); ++i) s.x[i] = (b.lo[i] + b.hi[i]) / 2;
    // A portfolio: the evolution strategy suits the many free crank angles of free timing,
    // controlled random search the fewer variables of prescribed timing.
    const nlopt_algorithm algorithm = (k / 4) % 2 == 0 ? NLOPT_GN_ESCH : NLOPT_GN_CRS2_LM;
    s.f = run_stage(algorithm, p, b, s.x, evaluations / budget.restarts, budget.seed * 7919u + static_cast<unsigned>(k));
    s.evaluations = p.evaluations;
    starts.push_back(std::move(s));
  }
  return starts;
}

void validate(const PathTask& t) {
  const auto bad = [](const std::string& what) { throw std::invalid_argument("path generation: " + what); };
  const std::size_t n = t.points.size();
  if (n < 3 || n > static_cast<std::size_t>(kMaxPathPoints))
    bad(fmt::format("needs 3..{} target points, found {}", kMaxPathPoints, n));
  for (const Vec2& q : t.points)
    if (!q.allFinite()) bad("a target point is not finite");
  if (t.timing) {
    if (t.timing->size() != n) bad("the timing needs one crank angle per target point");
    for (std::size_t j = 1; j < n; ++j)
      if (!((*t.timing)[j] > (*t.timing)[j - 1])) bad("the timing must increase from point to point");
    if (!((*t.timing)[0] == 0) || !((*t.timing)[n - 1] < 2 * pi)) bad("the timing starts at 0 and stays within one turn");
  }
  const PathBudget& b = t.budget;
  if (b.evaluations < 1000 || b.evaluations > kMaxEvaluations)
    bad(fmt::format("evaluations must be 1000..{}", kMaxEvaluations));
  if (b.evaluations * static_cast<long>(n) > kMaxPointEvaluations)
    bad(fmt::format("evaluations x points must stay within {} ({} x {} asked)", kMaxPointEvaluations, b.evaluations, n));
  if (b.restarts < 1 || b.restarts > kMaxRestarts) bad(fmt::format("restarts must be 1..{}", kMaxRestarts));
  const PathConstraints& c = t.constraints;
  if (!(c.min_transmission >= 0 && c.min_transmission < pi / 2)) bad("the minimum transmission angle must be 0..90 deg");
  if (!(c.max_link_ratio > 1)) bad("the link-length ratio limit must exceed 1");
  if (c.min_link && c.max_link && !(*c.min_link > 0 && *c.max_link > *c.min_link)) bad("link-length bounds must be 0 < min < max");
  for (const auto* r : {&c.O2_region, &c.O4_region})
    if (*r && !((*r)->max.x() >= (*r)->min.x() && (*r)->max.y() >= (*r)->min.y())) bad("a pivot region is empty");
}

Region scaled(const Region& r, const Vec2& centre, double S) { return {(r.min - centre) / S, (r.max - centre) / S}; }

Problem normalised(const PathTask& t, Vec2& centre, double& S) {
  Vec2 lo = t.points[0], hi = t.points[0];
  for (const Vec2& q : t.points) {
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  centre = (lo + hi) / 2;
  S = (hi - lo).norm();
  if (!(S > 0)) throw std::invalid_argument("path generation: the target points all coincide");
  Problem p;
  for (const Vec2& q : t.points) p.targets.push_back((q - centre) / S);
  if (t.timing) p.timing = *t.timing;
  p.constraints = t.constraints;
  p.link_lo = t.constraints.min_link ? *t.constraints.min_link / S : 0.05;
  p.link_hi = t.constraints.max_link ? *t.constraints.max_link / S : 4.0;
  const Region wide{Vec2(-2.5, -2.5), Vec2(2.5, 2.5)};
  p.O2 = t.constraints.O2_region ? scaled(*t.constraints.O2_region, centre, S) : wide;
  p.O4 = t.constraints.O4_region ? scaled(*t.constraints.O4_region, centre, S) : wide;
  return p;
}

// The linkage of design vector x in metres, with its exact checks.
PathResult result_of(Problem& p, const std::vector<double>& x, const Vec2& centre, double S,
                     const std::vector<Vec2>& targets) {
  objective(static_cast<unsigned>(x.size()), x.data(), nullptr, &p);  // fills the local points
  const Placement pl = best_placement(p.local, p.targets, p.closed);
  PathResult r;
  r.linkage = placed(local_linkage(x.data(), p.branch), pl);
  FourBar& f = r.linkage;
  f.O2 = centre + S * f.O2;
  f.O4 = centre + S * f.O4;
  f.crank *= S;
  f.coupler *= S;
  f.rocker *= S;
  f.coupler_point *= S;
  crank_angles(x.data(), p, r.theta2);
  for (double& t : r.theta2) t += pl.angle;
  r.error = tracking_error(f, r.theta2, targets, &r.reached);
  for (std::size_t j = 0; j < r.reached.size(); ++j) r.max_distance = std::max(r.max_distance, (r.reached[j] - targets[j]).norm());
  const std::vector<int> branches(r.theta2.size(), f.branch);
  r.defects = check_defects(f, r.theta2, branches, p.constraints.require_crank());
  r.transmission = crank_turns_fully(f) ? transmission_range(f, f.ground_angle(), 2 * pi, 1)
                                        : transmission_range(f, r.theta2[0], r.defects.travel, r.defects.direction);
  return r;
}

// Why the linkage breaks a constraint (empty when it meets all).
std::string infeasibility(const PathResult& r, const PathTask& t) {
  const PathConstraints& c = t.constraints;
  const FourBar& f = r.linkage;
  const double links[4] = {f.ground(), f.crank, f.coupler, f.rocker};
  const double ratio = *std::max_element(links, links + 4) / *std::min_element(links, links + 4);
  if (!std::isfinite(r.error)) return "the linkage cannot be assembled at every target";
  if (!r.defects.ok()) return r.defects.notes.front();
  const kin::GrashofClass g = kin::grashof(f.ground(), f.crank, f.coupler, f.rocker).kind;
  if (c.grashof == GrashofType::crank_rocker && !(g == kin::GrashofClass::crank_rocker && f.crank <= std::min({f.ground(), f.coupler, f.rocker})))
    return "not a crank-rocker (the crank is not the shortest link)";
  if (c.grashof == GrashofType::double_crank && g != kin::GrashofClass::double_crank) return "not a double crank";
  if (r.transmission.min < c.min_transmission - 1e-6)
    return fmt::format("transmission angle {:.2f} deg below the {:.2f} deg minimum", r.transmission.min * 180 / pi,
                       c.min_transmission * 180 / pi);
  if (ratio > c.max_link_ratio * (1 + 1e-9)) return fmt::format("link-length ratio {:.3g} above {:.3g}", ratio, c.max_link_ratio);
  if (c.O2_region && !c.O2_region->contains(f.O2)) return "O2 outside its region";
  if (c.O4_region && !c.O4_region->contains(f.O4)) return "O4 outside its region";
  return {};
}

}  // namespace

long default_path_evaluations(std::size_t points) {
  return std::clamp(3'000'000L / static_cast<long>(std::max<std::size_t>(points, 1)), 1000L, 300'000L);
}

bool Region::contains(const Vec2& p) const {
  const double tol = 1e-9 * std::max(1.0, (max - min).norm());
  return p.x() >= min.x() - tol && p.x() <= max.x() + tol && p.y() >= min.y() - tol && p.y() <= max.y() + tol;
}

double tracking_error(const FourBar& f, const std::vector<double>& theta2, const std::vector<Vec2>& targets,
                      std::vector<Vec2>* reached) {
  double e = 0;
  if (reached) reached->clear();
  for (std::size_t j = 0; j < targets.size() && j < theta2.size(); ++j) {
    const auto pose = pose_at(f, theta2[j]);
    if (!pose) return std::numeric_limits<double>::infinity();
    e += (pose->P - targets[j]).squaredNorm();
    if (reached) reached->push_back(pose->P);
  }
  return e;
}

PathResult synthesize_path(const PathTask& t) {
  validate(t);
  Vec2 centre;
  double S = 0;
  Problem p = normalised(t, centre, S);
  const Bounds b = bounds_of(p);
  // Global stage: every restart explores on its own branch and crank direction.
  std::vector<Start> starts = global_stage(p, b, t.budget, t.budget.evaluations * 80 / 100);
  std::sort(starts.begin(), starts.end(), [](const Start& a, const Start& c) { return a.f < c.f; });
  // Local stage: the best five are polished; the first feasible one with the least error wins.
  const std::size_t polished = std::min<std::size_t>(starts.size(), 5);
  long spent = 0;
  for (const Start& s : starts) spent += s.evaluations;
  const long local_budget = (t.budget.evaluations - spent) / static_cast<long>(polished);
  std::optional<PathResult> best;
  std::string why;
  for (std::size_t k = 0; k < starts.size(); ++k) {
    Start& s = starts[k];
    p.branch = s.branch;
    p.direction = s.direction;
    if (k < polished) {
      p.evaluations = 0;
      run_stage(NLOPT_LN_BOBYQA, p, b, s.x, local_budget, t.budget.seed * 7919u + 1000u + static_cast<unsigned>(k));
      spent += p.evaluations;
    }
    PathResult r = result_of(p, s.x, centre, S, t.points);
    const std::string bad = infeasibility(r, t);
    if (!bad.empty()) {
      why = bad;
      continue;
    }
    if (!best || r.error < best->error) best = std::move(r);
    if (k + 1 >= polished && best) break;
  }
  if (!best) throw NoSolution("path generation found no linkage meeting every constraint (" + why + ")");
  best->evaluations = spent;
  best->restarts = t.budget.restarts;
  return *best;
}

}  // namespace gearkit::synth
