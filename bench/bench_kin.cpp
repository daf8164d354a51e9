// Kinematics solver benchmarks (docs/kin.md, "Performance"):
//  - a four-bar (crank 40, coupler 120, rocker 80, ground 100 mm) swept over 3600 crank angles
//    with positions, velocities and accelerations, through kin::sweep (the product path) and
//    through a bare predictor + solve_position/velocity/acceleration loop;
//  - the same sweep solved for positions only by SolveSpace's libslvs (when found), with its
//    own convergence tolerance (1e-8 mm); gearkit runs at 1e-11 m = 1e-8 mm for parity;
//  - a chain of N coupled four-bars (each rocker is the next crank), N = 10, 100, 1000, per
//    position: near-linear growth thanks to the sparse LU.
#include <gearkit/kin/model.hpp>
#include <gearkit/kin/solve.hpp>
#include <gearkit/kin/sweep.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <string>

#ifdef GEARKIT_HAVE_SLVS
#include <slvs.h>
#endif

namespace {

using namespace gearkit::kin;

constexpr double kA = 0.040, kB = 0.120, kC = 0.080, kD = 0.100;
constexpr int kPositions = 3600;

Body link(const std::string& name, double length, double angle, Eigen::Vector2d at) {
  Body b;
  b.name = name;
  b.points = {{"p0", {0, 0}}, {"p1", {length, 0}}};
  b.angle_guess = angle;
  b.position_guess = at;
  return b;
}

// Chain of n four-bars: four-bar k has ground pivots at x = 0.1 k and 0.1 (k + 1); its crank is
// the rocker of four-bar k - 1 (for k > 0), driven at the first crank.
Model chain(int n) {
  Model m;
  Eigen::Vector2d a(kA, 0);
  int crank = m.add_body(link("crank", kA, 0.0, {0, 0}));
  m.add_constraint("O0", std::make_shared<Revolute>(BodyPoint{crank, {0, 0}}, BodyPoint{kGround, {0, 0}}));
  // Drawn configuration of the first loop at crank angle 0 (B above the ground line).
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector2d o2(kD * k, 0), o4(kD * (k + 1), 0);
    // Crank end A of this loop: the crank's (or previous rocker's) point at distance kA.
    const Eigen::Vector2d A = o2 + a;
    const double d = (o4 - A).norm();
    const double beta = std::acos((kB * kB + d * d - kC * kC) / (2 * kB * d));
    const double theta3 = std::atan2((o4 - A).y(), (o4 - A).x()) + beta;
    const Eigen::Vector2d B = A + kB * Eigen::Vector2d(std::cos(theta3), std::sin(theta3));
    const double theta4 = std::atan2((B - o4).y(), (B - o4).x());
    const int coupler = m.add_body(link("coupler" + std::to_string(k), kB, theta3, A));
    Body r = link("rocker" + std::to_string(k), kC, theta4, o4);
    r.points.push_back({"next", {kA, 0}});
    const int rocker = m.add_body(r);
    m.add_constraint("A" + std::to_string(k), std::make_shared<Revolute>(BodyPoint{crank, {kA, 0}}, BodyPoint{coupler, {0, 0}}));
    m.add_constraint("B" + std::to_string(k), std::make_shared<Revolute>(BodyPoint{coupler, {kB, 0}}, BodyPoint{rocker, {kC, 0}}));
    m.add_constraint("O" + std::to_string(k + 1), std::make_shared<Revolute>(BodyPoint{rocker, {0, 0}}, BodyPoint{kGround, o4}));
    crank = rocker;  // the next loop's crank is this rocker (its point "next" at kA)
    a = Eigen::Vector2d(kA * std::cos(theta4), kA * std::sin(theta4));
  }
  const int drv = m.add_constraint("input", std::make_shared<AngleDriver>(0, kGround, Motion{1.0, 0.0}));
  m.set_driver(drv, DriverQuantity::angle, 0.0);
  return m;
}

SolverOptions parity_tolerance() {
  SolverOptions o;
  o.tolerance = 1e-11;  // m: 1e-8 mm, SolveSpace's convergence tolerance
  return o;
}

void BM_FourBarSweep_gearkit(benchmark::State& state) {
  const Model m = chain(1);
  Data data(m);
  SweepOptions o;
  o.start = 0.0;
  o.end = 2 * M_PI * (kPositions - 1) / kPositions;
  o.step = 2 * M_PI / kPositions;
  o.solver = parity_tolerance();
  std::size_t samples = 0;
  for (auto _ : state) {
    const SweepResult r = sweep(m, data, o);
    samples = r.samples.size();
    benchmark::DoNotOptimize(r.samples.back().qdd(8));
  }
  if (samples != kPositions) state.SkipWithError("sweep did not complete");
  state.SetItemsProcessed(state.iterations() * kPositions);
  state.counters["ns_per_position"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * kPositions, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_FourBarSweep_gearkit)->Unit(benchmark::kMillisecond);

// The bare loop: second-order prediction along dq/dtheta (its change since the previous
// position gives the curvature), then position, velocity and acceleration.
void BM_FourBarLoop_gearkit(benchmark::State& state) {
  const Model m = chain(1);
  Data data(m);
  const SolverOptions tol = parity_tolerance();
  const double h = 2 * M_PI / kPositions;
  Eigen::VectorXd dq = Eigen::VectorXd::Zero(m.coordinates()), dq_previous = dq;
  for (auto _ : state) {
    data.inputs(0) = 0.0;
    solve_position(m, data, 0.0, tol);
    for (int k = 0; k < kPositions; ++k) {
      data.inputs(0) = k * h;
      if (k > 1) data.q += dq * h + 0.5 * (dq - dq_previous) * h;
      else if (k == 1) data.q += dq * h;
      if (!solve_position(m, data, 0.0, tol).converged) state.SkipWithError("not converged");
      solve_velocity(m, data);
      solve_acceleration(m, data);
      dq_previous = dq;
      dq = input_sensitivity(m, data, 0);
    }
    benchmark::DoNotOptimize(data.qdd(8));
  }
  state.SetItemsProcessed(state.iterations() * kPositions);
  state.counters["ns_per_position"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * kPositions, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_FourBarLoop_gearkit)->Unit(benchmark::kMillisecond);

#ifdef GEARKIT_HAVE_SLVS
// SolveSpace: group 1 holds the workplane, the ground pivots and the crank end A (moved to the
// crank angle before each solve); group 2 the free point B with |AB| = b and |O4 B| = c.
// Lengths in mm as SolveSpace expects. Positions only: libslvs has no velocity analysis.
void BM_FourBarSweep_slvs(benchmark::State& state) {
  std::vector<Slvs_Param> param;
  std::vector<Slvs_Entity> entity;
  std::vector<Slvs_Constraint> constraint;
  const Slvs_hGroup g1 = 1, g2 = 2;
  param.push_back(Slvs_MakeParam(1, g1, 0.0));
  param.push_back(Slvs_MakeParam(2, g1, 0.0));
  param.push_back(Slvs_MakeParam(3, g1, 0.0));
  entity.push_back(Slvs_MakePoint3d(101, g1, 1, 2, 3));
  double qw, qx, qy, qz;
  Slvs_MakeQuaternion(1, 0, 0, 0, 1, 0, &qw, &qx, &qy, &qz);
  param.push_back(Slvs_MakeParam(4, g1, qw));
  param.push_back(Slvs_MakeParam(5, g1, qx));
  param.push_back(Slvs_MakeParam(6, g1, qy));
  param.push_back(Slvs_MakeParam(7, g1, qz));
  entity.push_back(Slvs_MakeNormal3d(102, g1, 4, 5, 6, 7));
  entity.push_back(Slvs_MakeWorkplane(200, g1, 101, 102));
  const Slvs_hEntity wp = 200;
  param.push_back(Slvs_MakeParam(11, g1, kD * 1000));  // O4
  param.push_back(Slvs_MakeParam(12, g1, 0.0));
  entity.push_back(Slvs_MakePoint2d(301, g1, wp, 11, 12));
  param.push_back(Slvs_MakeParam(13, g1, kA * 1000));  // A (moved per position)
  param.push_back(Slvs_MakeParam(14, g1, 0.0));
  entity.push_back(Slvs_MakePoint2d(302, g1, wp, 13, 14));
  param.push_back(Slvs_MakeParam(15, g2, 136.7));  // B, free; start near the drawn branch
  param.push_back(Slvs_MakeParam(16, g2, 71.1));
  entity.push_back(Slvs_MakePoint2d(303, g2, wp, 15, 16));
  constraint.push_back(Slvs_MakeConstraint(1, g2, SLVS_C_PT_PT_DISTANCE, wp, kB * 1000, 302, 303, 0, 0));
  constraint.push_back(Slvs_MakeConstraint(2, g2, SLVS_C_PT_PT_DISTANCE, wp, kC * 1000, 301, 303, 0, 0));
  std::vector<Slvs_hConstraint> failed(constraint.size());
  Slvs_System sys{};
  sys.param = param.data();
  sys.params = static_cast<int>(param.size());
  sys.entity = entity.data();
  sys.entities = static_cast<int>(entity.size());
  sys.constraint = constraint.data();
  sys.constraints = static_cast<int>(constraint.size());
  sys.failed = failed.data();
  sys.faileds = static_cast<int>(failed.size());
  const double h = 2 * M_PI / kPositions;
  for (auto _ : state) {
    for (int k = 0; k < kPositions; ++k) {
      param[9].val = kA * 1000 * std::cos(k * h);  // params 13, 14
      param[10].val = kA * 1000 * std::sin(k * h);
      Slvs_Solve(&sys, g2);
      if (sys.result != SLVS_RESULT_OKAY) state.SkipWithError("libslvs did not converge");
    }
    benchmark::DoNotOptimize(param[11].val);
  }
  state.SetItemsProcessed(state.iterations() * kPositions);
  state.counters["ns_per_position"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * kPositions, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_FourBarSweep_slvs)->Unit(benchmark::kMillisecond);
#endif

// Chain of N four-bars: 36 positions per iteration (crank steps of 1 deg), positions,
// velocities and accelerations.
void BM_FourBarChain(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Model m = chain(n);
  Data data(m);
  if (!solve_position(m, data, 0.0).converged) {
    state.SkipWithError("chain does not assemble");
    return;
  }
  const int steps = 36;
  const double h = M_PI / 180.0;
  Eigen::VectorXd dq = input_sensitivity(m, data, 0);
  for (auto _ : state) {
    for (int k = 0; k < steps; ++k) {
      data.inputs(0) += h;
      data.q += dq * h;
      if (!solve_position(m, data, 0.0).converged) state.SkipWithError("not converged");
      solve_velocity(m, data);
      solve_acceleration(m, data);
      dq = input_sensitivity(m, data, 0);
    }
  }
  state.SetItemsProcessed(state.iterations() * steps);
  state.counters["coordinates"] = m.coordinates();
  state.counters["us_per_position"] = benchmark::Counter(static_cast<double>(state.iterations()) * steps * 1e-6,
                                                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_FourBarChain)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
