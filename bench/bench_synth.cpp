// Linkage synthesis (libsynth, `gearkit synth`). Targets (issue 19): three-position synthesis
// under 1 ms; a 10-point path-generation optimisation under 2 s, with the achieved error
// reported. The whole process is timed too: `gearkit synth path` on the ten-point ellipse
// (start-up, plugin loading, synthesis, the solver check, the report), with its peak memory.
#include <gearkit/synth/function_generation.hpp>
#include <gearkit/synth/motion_generation.hpp>
#include <gearkit/synth/path_generation.hpp>

#include "spawn_process.hpp"
#include "synth_test_support.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace gs = gearkit::synth;

namespace {

constexpr double deg = std::numbers::pi / 180;

// examples/synthesis/three_positions.yaml: the coupler line C D in three positions.
std::vector<gs::Pose> three_poses() {
  return {gs::pose_from_points({0, 0}, {0.06, 0.02}), gs::pose_from_points({0.05, 0.06}, {0.11, 0.062}),
          gs::pose_from_points({0.11, 0.08}, {0.16, 0.05})};
}

// Ground pivots from the moving pivots (circumcentres), the four-bar assembled and checked for
// branch, order and Grashof defects, transmission angle over the travel.
void BM_ThreePosition_MovingPivots(benchmark::State& state) {
  const auto poses = three_poses();
  for (auto _ : state) {
    const gs::MotionCandidate c = gs::four_bar_from_dyads(poses, gs::dyad_from_moving_pivot(poses, {0, 0}),
                                                          gs::dyad_from_moving_pivot(poses, {0.06, 0.02}), false);
    benchmark::DoNotOptimize(c.transmission.min);
  }
}
BENCHMARK(BM_ThreePosition_MovingPivots)->Unit(benchmark::kMicrosecond);

// Norton's analytical form with free choices beta2, beta3, gamma2, gamma3.
void BM_ThreePosition_Rotations(benchmark::State& state) {
  const auto poses = three_poses();
  for (auto _ : state) {
    const gs::MotionCandidate c = gs::four_bar_from_dyads(poses, gs::dyad_from_rotations(poses, -20 * deg, -60 * deg),
                                                          gs::dyad_from_rotations(poses, 30 * deg, 70 * deg), false);
    benchmark::DoNotOptimize(c.transmission.min);
  }
}
BENCHMARK(BM_ThreePosition_Rotations)->Unit(benchmark::kMicrosecond);

// Every free choice searched (16 x 16 moving pivots, all pairs): no target, for the record.
void BM_ThreePosition_Search(benchmark::State& state) {
  const auto poses = three_poses();
  for (auto _ : state) benchmark::DoNotOptimize(gs::best_three_position(poses, 16, 10, false).transmission.min);
}
BENCHMARK(BM_ThreePosition_Search)->Unit(benchmark::kMillisecond);

// Freudenstein's three precision points and 201 structural-error samples (log10 over [1, 2]).
void BM_FunctionGeneration_Log10(benchmark::State& state) {
  const gs::FunctionTask t = gs::testing::log10_task();
  for (auto _ : state) benchmark::DoNotOptimize(gs::synthesize_function(t).max_error);
}
BENCHMARK(BM_FunctionGeneration_Log10)->Unit(benchmark::kMicrosecond);

// The ten-point ellipse of the path-synthesis benchmark, default budget (300 000 evaluations,
// 16 restarts); the seed is the repetition number, so the repetitions show the spread. The
// targets are those of examples/synthesis/path_ellipse.yaml, bit for bit (the published rounded
// coordinates, converted as the command converts mm): seed 1 here is `gearkit synth path
// examples/synthesis/path_ellipse.yaml` (docs/benchmarks.md).
void BM_Path_TenPointEllipse(benchmark::State& state) {
  gs::PathTask t;
  t.points = gs::testing::published_ellipse_points();
  static unsigned seed = 0;
  t.budget.seed = ++seed;
  gs::PathResult r;
  for (auto _ : state) r = gs::synthesize_path(t);
  state.counters["error_mm2"] = r.error * 1e6;
  state.counters["max_distance_mm"] = r.max_distance * 1e3;
  state.counters["seed"] = t.budget.seed;
}
BENCHMARK(BM_Path_TenPointEllipse)->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(8);

// `gearkit synth path examples/synthesis/path_ellipse.yaml`, the whole process; peak memory of
// the children (ru_maxrss of RUSAGE_CHILDREN: the largest child so far).
void BM_Process_SynthPath(benchmark::State& state) {
  const std::string file = std::string(GEARKIT_SOURCE_DIR) + "/examples/synthesis/path_ellipse.yaml";
  long max_rss_kb = 0;
  for (auto _ : state) {
    const gearkit::bench::ProcessRun run = gearkit::bench::run_process({GEARKIT_EXE, "synth", "path", file});
    if (!run.ok) state.SkipWithError("gearkit synth failed");
    max_rss_kb = std::max(max_rss_kb, run.max_rss_kb);
  }
  state.counters["max_rss_MB"] = static_cast<double>(max_rss_kb) / 1024;
}
BENCHMARK(BM_Process_SynthPath)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1)->Repetitions(3);

}  // namespace

BENCHMARK_MAIN();
