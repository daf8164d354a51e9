// Cold start of the gearkit executable, plugin loading included: the wall time of
// `gearkit plugins` (process start, dynamic linking, discovery and loading of every plugin,
// the report) and, for comparison, `gearkit --version` (which loads no plugin).
// Target (issue 2): under 20 ms median for `gearkit plugins`.
#include "spawn_process.hpp"

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

namespace {

void run_once(benchmark::State& state, const std::vector<std::string>& words) {
  if (!gearkit::bench::run_process(words).ok) state.SkipWithError("gearkit failed");
}

void BM_ColdStart_Plugins(benchmark::State& state) {
  for (auto _ : state) run_once(state, {GEARKIT_EXE, "plugins"});
}
BENCHMARK(BM_ColdStart_Plugins)->Unit(benchmark::kMillisecond)->UseRealTime()->Repetitions(5)
    ->ReportAggregatesOnly(true);

void BM_ColdStart_Version(benchmark::State& state) {
  for (auto _ : state) run_once(state, {GEARKIT_EXE, "--version"});
}
BENCHMARK(BM_ColdStart_Version)->Unit(benchmark::kMillisecond)->UseRealTime()->Repetitions(5)
    ->ReportAggregatesOnly(true);

}  // namespace

BENCHMARK_MAIN();
