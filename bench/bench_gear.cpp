// Benchmarks of libgear (Google Benchmark): the inverse involute (target 20M+ evaluations/s)
// and a complete gear-pair table (both gears and the pair, target 1M+ tables/s).
#include <gearkit/gear/accuracy.hpp>
#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/gear/inspection.hpp>
#include <gearkit/gear/involute.hpp>
#include <gearkit/gear/rating.hpp>
#include <gearkit/gear/sizing.hpp>

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

// ISO/TR 6336-30 example 1 with every factor computed (K_v, K_Hbeta by method C, K_Halpha from
// the ISO 1328 grade 5 tolerances), both gears, life; target 100 000 ratings/s.
gg::GearPairInput rated_pair() {
  gg::GearPairInput in;
  in.z1 = 17;
  in.z2 = 103;
  in.module = 8.0;
  in.helix_angle = 15.8 * std::numbers::pi / 180.0;
  in.face_width = 100.0;
  in.h_fP = 1.4;
  in.rho_fP = 0.39;
  in.x1 = 0.145;
  return in;
}

gg::RatingInput rated_load() {
  gg::RatingInput r;
  r.T_1 = 9000.0;
  r.n_1 = 360.0;
  r.material = {gg::material_by_name("18CrNiMo7-6"), gg::material_by_name("18CrNiMo7-6")};
  r.life_h = 50000.0;
  r.quality = 5;
  return r;
}

void BM_RatingIso6336(benchmark::State& state) {
  const gg::GearPairInput in = rated_pair();
  const gg::GearPairResult table = gg::compute_gear_pair(in);
  gg::RatingInput load = rated_load();
  int n = 0;
  for (auto _ : state) {
    load.T_1 = 9000.0 + (n++ & 15);  // a different load each time
    benchmark::DoNotOptimize(gg::rate_gear_pair(in, table, load));
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}
BENCHMARK(BM_RatingIso6336);

void BM_TableAndRatingIso6336(benchmark::State& state) {
  gg::GearPairInput in = rated_pair();
  const gg::RatingInput load = rated_load();
  int n = 0;
  for (auto _ : state) {
    in.z2 = 103 + (n++ & 15);  // a different pair each time: the table and the rating
    benchmark::DoNotOptimize(gg::rate_gear_pair(in, gg::compute_gear_pair(in), load));
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}
BENCHMARK(BM_TableAndRatingIso6336);

void BM_SizingDefaultSearch(benchmark::State& state) {
  gg::SizingInput s;
  s.load = rated_load();
  s.load.T_1 = 500.0;
  s.load.n_1 = 1450.0;
  s.load.quality = 6;
  s.ratio = 3.5;
  for (auto _ : state) benchmark::DoNotOptimize(gg::size_gear_pair(s));
}
BENCHMARK(BM_SizingDefaultSearch)->Unit(benchmark::kMillisecond);

// All ISO 1328-1:2013 flank tolerances of one gear (nine formulas, rounding, scope checks).
void BM_FlankTolerances(benchmark::State& state) {
  gg::ToleranceInput in;
  in.d = 120.0;
  in.m_n = 3.0;
  in.b = 30.0;
  in.z = 40;
  in.grade = 7;
  int n = 0;
  for (auto _ : state) {
    in.grade = 1 + (n++ % 11);
    benchmark::DoNotOptimize(gg::flank_tolerances(in));
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}
BENCHMARK(BM_FlankTolerances);

// The inspection data of a pair on top of its table (tolerances, ISO/TR 10064-2 allowances, W_k
// and M_d limits, pin ranges by bisection, backlash range); state.range(0) = 1 adds an operating
// temperature (a second thermal state).
void BM_Inspection(benchmark::State& state) {
  gg::GearPairInput in;
  in.z1 = 20;
  in.z2 = 40;
  in.module = 3.0;
  in.face_width = 30.0;
  const gg::GearPairResult table = gg::compute_gear_pair(in);
  gg::InspectionInput ii;
  ii.grade = {7, 7};
  if (state.range(0) == 1) ii.T_gears = 70.0;
  for (auto _ : state) benchmark::DoNotOptimize(gg::compute_inspection(in, table, ii));
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}
BENCHMARK(BM_Inspection)->Arg(0)->Arg(1);

}  // namespace

BENCHMARK_MAIN();
