// Benchmarks of libgear (Google Benchmark): the inverse involute (target 20M+ evaluations/s)
// and a complete gear-pair table (both gears and the pair, target 1M+ tables/s).
#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/gear/involute.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace gg = gearkit::gear;

namespace {

// Involute values spread over the working range 5..60 deg (every call lands on a different value,
// so the branch predictor and the caches see a realistic mix).
std::vector<double> involute_values() {
  std::vector<double> v(4096);
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double a = (5.0 + 55.0 * static_cast<double>((i * 2654435761u) % v.size()) / v.size()) * std::numbers::pi / 180.0;
    v[i] = gg::involute(a);
  }
  return v;
}

void BM_InverseInvolute(benchmark::State& state) {
  const std::vector<double> values = involute_values();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(gg::inverse_involute(values[i]));
    i = (i + 1) & (values.size() - 1);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}
BENCHMARK(BM_InverseInvolute);

void BM_Involute(benchmark::State& state) {
  double a = 0.1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(gg::involute(a));
    a = a < 1.2 ? a + 1e-4 : 0.1;
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}
BENCHMARK(BM_Involute);

void BM_GearPairTableGivenShifts(benchmark::State& state) {
  gg::GearPairInput in;
  in.z1 = 12;
  in.z2 = 24;
  in.module = 3.0;
  in.x1 = 0.6;
  in.x2 = 0.36;
  in.face_width = 20.0;
  int n = 0;
  for (auto _ : state) {
    in.z2 = 24 + (n++ & 15);  // a different pair each time
    benchmark::DoNotOptimize(gg::compute_gear_pair(in));
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}
BENCHMARK(BM_GearPairTableGivenShifts);

void BM_GearPairTableGivenCentreDistanceBalanced(benchmark::State& state) {
  gg::GearPairInput in;
  in.z1 = 12;
  in.z2 = 24;
  in.module = 3.0;
  in.centre_distance = 56.5;
  in.split = gg::ShiftSplit::balanced_sliding;
  for (auto _ : state) benchmark::DoNotOptimize(gg::compute_gear_pair(in));
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}
BENCHMARK(BM_GearPairTableGivenCentreDistanceBalanced);

}  // namespace

BENCHMARK_MAIN();
