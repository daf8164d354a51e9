// `gearkit kin` as users run it (issue 13): the whole process - start-up, plugins, reading the
// model, the solver, the streamed report - for a four-bar sweep of 36,000 positions with
// velocities and accelerations, as CSV and as JSON, against SolveSpace's libslvs driven from C
// for positions only (bench/peers/slvs_four_bar.c) in the same run; and the peak memory of a
// 1,000,000-position sweep, which must not grow with the sweep (goal <= 50 MB).
// Goals: CSV <= 2 us and JSON <= 3 us per position, i.e. >= 10x the libslvs process.
#include "process.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using gearkit::bench::run_process;

// The four-bar of bench_kin (Norton's crank-rocker: crank 40, coupler 120, rocker 80, ground
// 100 mm) with the outputs of examples/mechanisms/four_bar.yaml and no loads: kinematics only.
constexpr const char* kFourBar = R"(mechanism: four-bar for the process benchmark
ground:
  O2: [0, 0]
  O4: [100, 0]
links:
  crank: {points: {O2: [0, 0], A: [40, 0]}, angle: 40 deg}
  coupler: {points: {A: [0, 0], B: [120, 0], C: [60, 30]}, angle: 20 deg}
  rocker: {points: {O4: [0, 0], B: [80, 0]}, angle: 75 deg}
joints:
  - {name: O2, type: revolute, at: [crank.O2, ground.O2]}
  - {name: A, type: revolute, at: [crank.A, coupler.A]}
  - {name: B, type: revolute, at: [coupler.B, rocker.B]}
  - {name: O4, type: revolute, at: [rocker.O4, ground.O4]}
drivers:
  - {name: theta2, type: angle, link: crank, speed: 25 rad/s}
outputs:
  - {name: theta4, type: angle, link: rocker}
  - {name: Cx, type: x, point: coupler.C}
  - {name: Cy, type: y, point: coupler.C}
)";

const fs::path& model_file() {
  static const fs::path path = [] {
    const fs::path dir = fs::temp_directory_path() / ("gearkit-bench-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "four_bar.yaml") << kFourBar;
    return dir / "four_bar.yaml";
  }();
  return path;
}

std::map<std::string, std::vector<double>> us_per_position;  // per benchmark, every repetition

void measure(benchmark::State& state, const std::string& name, const std::vector<std::string>& words, long positions) {
  double peak = 0, seconds = 0;
  for (auto _ : state) {
    const gearkit::bench::ProcessRun run = run_process(words);
    if (!run.ok) {
      state.SkipWithError(("failed: " + words[0]).c_str());
      return;
    }
    state.SetIterationTime(run.seconds);
    us_per_position[name].push_back(run.seconds / static_cast<double>(positions) * 1e6);
    peak = std::max(peak, run.peak_rss_mb);
    seconds += run.seconds;
  }
  state.counters["us_per_position"] = seconds / static_cast<double>(state.iterations()) / static_cast<double>(positions) * 1e6;
  state.counters["peak_rss_MB"] = peak;
}

// 36,000 positions: 0 to 359.99 deg in 0.01 deg steps.
std::vector<std::string> kin(const std::string& format, const std::string& sweep = "0:359.99:0.01") {
  return {GEARKIT_EXE, "kin", model_file().string(), "--sweep", sweep, "--format", format};
}

void BM_Process_kin_csv(benchmark::State& state) { measure(state, "kin csv", kin("csv"), 36000); }
void BM_Process_kin_json(benchmark::State& state) { measure(state, "kin json", kin("json"), 36000); }
void BM_Process_slvs(benchmark::State& state) { measure(state, "slvs", {GEARKIT_SLVS_PEER, "36000"}, 36000); }
// Memory independent of the length: a million positions (0.00036 deg steps).
void BM_Process_kin_csv_1e6(benchmark::State& state) { measure(state, "kin csv 1e6", kin("csv", "0:359.99964:0.00036"), 1000000); }
void BM_Process_kin_json_1e6(benchmark::State& state) { measure(state, "kin json 1e6", kin("json", "0:359.99964:0.00036"), 1000000); }

// Interleaved repetitions: the three processes of one comparison meet the same machine state.
BENCHMARK(BM_Process_kin_csv)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(3)->Repetitions(7);
BENCHMARK(BM_Process_kin_json)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(3)->Repetitions(7);
BENCHMARK(BM_Process_slvs)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(3)->Repetitions(7);
BENCHMARK(BM_Process_kin_csv_1e6)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(1);
BENCHMARK(BM_Process_kin_json_1e6)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(1);

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  const double slvs = median(us_per_position["slvs"]);
  std::printf("\nmedian us per position (same run):\n");
  for (const auto& [name, values] : us_per_position)
    std::printf("  %-14s %8.3f us%s\n", name.c_str(), median(values),
                slvs > 0 && name != "slvs" ? (" = libslvs / " + std::to_string(slvs / median(values))).c_str() : "");
  fs::remove_all(model_file().parent_path());
  return 0;
}
