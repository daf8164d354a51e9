// Benchmark of libgear's bevel pair (Google Benchmark): a complete bevel table (cones, depths,
// both gears' diameters and distances, virtual gears, contact ratio, undercut limits) and the
// forces; issue 28's target is 1M+ tables/s.
#include <gearkit/gear/bevel.hpp>

#include <benchmark/benchmark.h>

#include <numbers>

namespace gg = gearkit::gear;

namespace {

// Straight (KHK's Gleason example) and spiral pairs at several tooth counts, so that every call
// computes a different table.
void BM_BevelTable(benchmark::State& state) {
  gg::BevelPairInput in;
  in.m_et = 3.0;
  in.b = 18.0;
  if (state.range(0) == 1) {
    in.type = gg::BevelType::spiral;
    in.beta_m = 35.0 * std::numbers::pi / 180.0;
  }
  int i = 0;
  for (auto _ : state) {
    in.z1 = 20 + (i & 7);
    in.z2 = 40 + (i & 15);
    benchmark::DoNotOptimize(gg::compute_bevel_pair(in));
    ++i;
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
  state.SetLabel(state.range(0) == 1 ? "spiral" : "straight");
}
BENCHMARK(BM_BevelTable)->Arg(0)->Arg(1);

void BM_BevelForces(benchmark::State& state) {
  gg::BevelPairInput in;
  in.z1 = 13;
  in.z2 = 39;
  in.m_et = 4.0;
  in.b = 18.0;
  in.type = gg::BevelType::spiral;
  in.beta_m = 35.0 * std::numbers::pi / 180.0;
  const gg::BevelPairResult table = gg::compute_bevel_pair(in);
  double T = 100.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(gg::bevel_forces(in, table, {T, 1, gg::Rotation::cw}));
    T = T < 200.0 ? T + 0.5 : 100.0;
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}
BENCHMARK(BM_BevelForces);

}  // namespace

BENCHMARK_MAIN();
