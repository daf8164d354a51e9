// Cold start of the gearkit executable, plugin loading included: the wall time of
// `gearkit plugins` (process start, dynamic linking, discovery and loading of every plugin,
// the report) and, for comparison, `gearkit --version` (which loads no plugin).
// Target (issue 2): under 20 ms median for `gearkit plugins`.
#include <benchmark/benchmark.h>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <string>
#include <vector>

extern char** environ;

namespace {

void run_once(benchmark::State& state, const std::vector<std::string>& words) {
  std::vector<char*> argv;
  for (const auto& w : words) argv.push_back(const_cast<char*>(w.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  if (posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ) != 0) {
    state.SkipWithError("cannot start gearkit");
    return;
  }
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) state.SkipWithError("gearkit failed");
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
