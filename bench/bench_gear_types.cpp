// Benchmarks of libgear's other gear types (Google Benchmark): a complete worm table
// (compute_worm: geometry, kinematics, friction from the sliding velocity, efficiencies, checks;
// target 1M+ tables/s), the worm forces on it, and the rack-and-pinion and crossed helical tables.
#include <gearkit/gear/crossed_helical.hpp>
#include <gearkit/gear/rack_pinion.hpp>
#include <gearkit/gear/worm.hpp>

#include <benchmark/benchmark.h>

namespace gg = gearkit::gear;

namespace {

gg::WormInput worm_input() {
  gg::WormInput in;
  in.z1 = 2;
  in.z2 = 41;
  in.m_x = 4.0;
  in.q = 10.0;
  in.centre_distance = 103.0;
  in.n1 = 1450.0;
  return in;
}

void BM_WormTable(benchmark::State& state) {
  gg::WormInput in = worm_input();
  int i = 0;
  for (auto _ : state) {
    const int k = i++ & 7;  // a different table each time, x2 = 0.25 for each
    in.z2 = 41 + k;
    in.centre_distance = 103.0 + 2.0 * k;
    benchmark::DoNotOptimize(gg::compute_worm(in));
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}
BENCHMARK(BM_WormTable);

void BM_WormForces(benchmark::State& state) {
  const gg::WormResult w = gg::compute_worm(worm_input());
  double T = 10.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(gg::worm_forces(w, T, true, true));
    T = T < 100.0 ? T + 0.5 : 10.0;
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}
BENCHMARK(BM_WormForces);

void BM_RackPinionTable(benchmark::State& state) {
  gg::RackPinionInput in;
  in.z1 = 18;
  in.m_n = 2.0;
  in.x1 = 0.2;
  in.face_width = 20.0;
  in.travel = 500.0;
  for (auto _ : state) benchmark::DoNotOptimize(gg::compute_rack_pinion(in));
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}
BENCHMARK(BM_RackPinionTable);

void BM_CrossedHelicalTable(benchmark::State& state) {
  gg::CrossedHelicalInput in;
  in.z1 = 15;
  in.z2 = 24;
  in.m_n = 3.0;
  in.beta1 = 0.35;
  in.beta2 = 0.52;
  in.n1 = 1000.0;
  for (auto _ : state) benchmark::DoNotOptimize(gg::compute_crossed_helical(in));
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}
BENCHMARK(BM_CrossedHelicalTable);

}  // namespace

BENCHMARK_MAIN();
