// libtrain benchmarks (issue 4): a compound train of 100 epicyclic stages solved exactly, and
// the synthesis of a two-stage coaxial reducer over tooth counts 12..150 to a 1e-6 tolerance.
#include <gearkit/train/kinematics.hpp>
#include <gearkit/train/synthesis.hpp>
#include <gearkit/train/torques.hpp>

#include <benchmark/benchmark.h>

#include <string>

namespace gt = gearkit::train;

namespace {

// Stage k: sun on the previous stage's carrier (stage 0: the input shaft), planets on carrier k,
// ring k held. Tooth counts vary from stage to stage so the exact ratio is a large fraction.
gt::TrainModel chained_planetary_stages(int stages) {
  gt::TrainDescription d;
  d.members.push_back({"in", "ground", 1});
  std::string previous = "in";
  for (int k = 0; k < stages; ++k) {
    const std::string tag = std::to_string(k);
    d.members.push_back({"c" + tag, "ground", 1});
    d.members.push_back({"r" + tag, "ground", 1});
    d.members.push_back({"p" + tag, "c" + tag, 3});
    const int zs = 18 + k % 7, zp = 20 + k % 5;
    d.gears.push_back({"s" + tag, previous, zs, gt::GearKind::external, std::nullopt, 0.0});
    d.gears.push_back({"pp" + tag, "p" + tag, zp, gt::GearKind::external, std::nullopt, 0.0});
    d.gears.push_back({"rr" + tag, "r" + tag, zs + 2 * zp, gt::GearKind::internal, std::nullopt, 0.0});
    d.meshes.push_back({"", "s" + tag, "pp" + tag, "c" + tag, 1.0});
    d.meshes.push_back({"", "pp" + tag, "rr" + tag, "c" + tag, 1.0});
    previous = "c" + tag;
  }
  return gt::make_train_model(d);
}

std::vector<gt::Condition> held_rings(const gt::TrainModel& model, int stages) {
  std::vector<gt::Condition> c;
  for (int k = 0; k < stages; ++k)
    c.push_back({gt::Condition::Kind::fix, *model.find_member("r" + std::to_string(k)), gt::ground, "fix"});
  c.push_back({gt::Condition::Kind::input, *model.find_member("in"), gt::ground, "input"});
  return c;
}

void BM_Solve100EpicyclicStagesExactly(benchmark::State& state) {
  const int stages = static_cast<int>(state.range(0));
  const gt::TrainModel model = chained_planetary_stages(stages);
  const auto conditions = held_rings(model, stages);
  const gt::MemberId out = *model.find_member("c" + std::to_string(stages - 1));
  const gt::MemberId in = *model.find_member("in");
  for (auto _ : state) {
    const gt::SpeedSolution s = gt::solve_speeds(model, conditions);
    benchmark::DoNotOptimize(s.speeds[out].per_input[0]);
  }
  const auto ratio = gt::speed_ratio(gt::solve_speeds(model, conditions), out, in);
  state.counters["members"] = static_cast<double>(model.member_count());
  state.counters["ratio_denominator_digits"] = static_cast<double>(boost::multiprecision::denominator(*ratio).str().size());
}
BENCHMARK(BM_Solve100EpicyclicStagesExactly)->Arg(10)->Arg(100)->Unit(benchmark::kMicrosecond);

void BM_Torques100EpicyclicStagesExactly(benchmark::State& state) {
  const int stages = static_cast<int>(state.range(0));
  const gt::TrainModel model = chained_planetary_stages(stages);
  const auto conditions = held_rings(model, stages);
  const gt::MemberId out = *model.find_member("c" + std::to_string(stages - 1));
  for (auto _ : state) {
    const gt::TorqueSolution t = gt::solve_torques(model, conditions, out, *model.find_member("in"));
    benchmark::DoNotOptimize(t);
  }
}
BENCHMARK(BM_Torques100EpicyclicStagesExactly)->Arg(100)->Unit(benchmark::kMicrosecond);

// OTM 2015 problem 3 data with the pinion left free: every z1..z4 in 12..150.
void BM_SynthesiseCoaxialReducer(benchmark::State& state) {
  gt::CoaxialReducerSpec spec;
  spec.module_1_mm = 6;
  spec.module_2_mm = 5;
  spec.target_ratio = gt::Rational(1, 16);
  spec.tolerance = 1e-6;
  spec.z_min = 12;
  spec.z_max = 150;
  spec.max_results = 1000000;
  std::size_t found = 0;
  for (auto _ : state) {
    const auto candidates = gt::synthesise_coaxial_reducer(spec);
    found = candidates.size();
    benchmark::DoNotOptimize(candidates);
  }
  state.counters["candidates"] = static_cast<double>(found);
}
BENCHMARK(BM_SynthesiseCoaxialReducer)->Unit(benchmark::kMillisecond);

void BM_SynthesisePlanetary(benchmark::State& state) {
  gt::PlanetarySpec spec;
  spec.target_ratio = gt::Rational(2, 9);
  spec.tolerance = 1e-6;
  spec.planets = 3;
  spec.max_results = 1000000;
  for (auto _ : state) benchmark::DoNotOptimize(gt::synthesise_planetary(spec));
}
BENCHMARK(BM_SynthesisePlanetary)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
