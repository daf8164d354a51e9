// Kinematics solver benchmarks (docs/kin.md, "Performance"):
//  - a four-bar (crank 40, coupler 120, rocker 80, ground 100 mm) swept over 3600 crank angles
//    with positions, velocities and accelerations through kin::sweep, the path `gearkit kin
//    --sweep` takes (samples stored, branch and dead-point checks, extremes bookkeeping);
//  - the same sweep solved for positions only by SolveSpace's libslvs (when found), with its
//    own convergence tolerance (1e-8 mm); gearkit runs at 1e-11 m = 1e-8 mm for parity;
//  - a chain of N coupled four-bars (each rocker is the next crank), N = 1, 10, 100, 1000, swept
//    like the four-bar: time per position grows linearly with N thanks to the sparse LU (KLU).
#include <gearkit/kin/dof.hpp>
#include <gearkit/kin/model.hpp>
#include <gearkit/kin/solve.hpp>
#include <gearkit/kin/sweep.hpp>

#include <benchmark/benchmark.h>

#include "mechanisms.hpp"

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

// The chain of n four-bars of the solver tests (tests/kin/mechanisms.hpp): loop k has its
// ground pivots at x = 0.1 k and 0.1 (k + 1) m; its crank is the rocker of loop k - 1 (for
// k > 0), driven at the first crank. chain(1) is the plain four-bar.
Model chain(int n) { return testing::four_bar_chain({kA, kB, kC, kD}, n); }

SolverOptions parity_tolerance() {
  SolverOptions o;
  o.tolerance = 1e-11;  // m: 1e-8 mm, SolveSpace's convergence tolerance
  return o;
}

// The benchmark sweep: kPositions crank angles over one turn, at the parity tolerance.
SweepOptions full_turn() {
  SweepOptions o;
  o.start = 0.0;
  o.end = 2 * M_PI * (kPositions - 1) / kPositions;
  o.step = 2 * M_PI / kPositions;
  o.solver = parity_tolerance();
  return o;
}

// Items and the ns_per_position counter for `positions` positions per iteration.
void count_positions(benchmark::State& state, int positions) {
  state.SetItemsProcessed(state.iterations() * positions);
  state.counters["ns_per_position"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * positions, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_FourBarSweep_gearkit(benchmark::State& state) {
  const Model m = chain(1);
  Data data(m);
  const SweepOptions o = full_turn();
  std::size_t samples = 0;
  for (auto _ : state) {
    const SweepResult r = sweep(m, data, o);
    samples = r.samples.size();
    benchmark::DoNotOptimize(r.samples.back().qdd(8));
  }
  if (samples != kPositions) state.SkipWithError("sweep did not complete");
  count_positions(state, kPositions);
}
BENCHMARK(BM_FourBarSweep_gearkit)->Unit(benchmark::kMillisecond);

// The same sweep into one SweepResult kept across sweeps (kin::sweep's second form): the
// samples' storage is reused, so no allocation per position.
void BM_FourBarSweepInto_gearkit(benchmark::State& state) {
  const Model m = chain(1);
  Data data(m);
  const SweepOptions o = full_turn();
  SweepResult r;
  for (auto _ : state) {
    sweep(m, data, o, r);
    benchmark::DoNotOptimize(r.samples.back().qdd(8));
  }
  if (r.samples.size() != kPositions) state.SkipWithError("sweep did not complete");
  count_positions(state, kPositions);
}
BENCHMARK(BM_FourBarSweepInto_gearkit)->Unit(benchmark::kMillisecond);

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
  count_positions(state, kPositions);
}
BENCHMARK(BM_FourBarSweep_slvs)->Unit(benchmark::kMillisecond);
#endif

// Chain of N four-bars swept through kin::sweep like the single four-bar: 36 positions per
// iteration (crank steps of 1 deg), positions, velocities and accelerations.
void BM_FourBarChain(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Model m = chain(n);
  Data data(m);
  constexpr int kSteps = 36;
  SweepOptions o;
  o.start = 0.0;
  o.step = M_PI / 180.0;
  o.end = o.step * (kSteps - 1);
  o.solver = parity_tolerance();
  const Eigen::VectorXd drawn = data.q;
  for (auto _ : state) {
    data.q = drawn;
    const SweepResult r = sweep(m, data, o);
    if (r.samples.size() != kSteps) state.SkipWithError("chain sweep did not complete");
    benchmark::DoNotOptimize(r.samples.back().qdd(0));
  }
  count_positions(state, kSteps);
  state.counters["coordinates"] = m.coordinates();
}
BENCHMARK(BM_FourBarChain)->Arg(1)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

// The mobility and redundancy analysis (kin::dof: Gruebler, rank of Phi_q by SuiteSparseQR,
// redundant rows) of a chain of N four-bars at its assembled start, as `gearkit kin` runs it once
// per model (issue 13 item 2: near-linear in N up to 10,000 loops).
void BM_ChainDof(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Model m = chain(n);
  Data data(m);
  solve_position(m, data, 0.0);
  for (auto _ : state) {
    const DofReport r = dof(m, data);
    if (r.dof != 1) state.SkipWithError("a chain of four-bars has one degree of freedom");
    benchmark::DoNotOptimize(r.rank);
  }
  state.counters["coordinates"] = m.coordinates();
  state.counters["us_per_loop"] =
      benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_ChainDof)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
