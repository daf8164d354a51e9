#pragma once
// Runs a program as its own process (posix_spawn, stdout to /dev/null) and waits for it: the
// whole-process benchmarks (start-up, dynamic linking, plugin loading, the work, the report).
// Shared by bench_cold_start, bench_synth and bench_cam.
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <string>
#include <vector>

extern char** environ;

namespace gearkit::bench {

/// What one run of a process took.
struct ProcessRun {
  bool ok = false;         ///< started, and exited with status 0
  double cpu_s = 0;        ///< user + system CPU time of the child [s]
  long max_rss_kb = 0;     ///< its peak resident memory [KiB]
};

inline ProcessRun run_process(const std::vector<std::string>& words) {
  std::vector<char*> argv;
  for (const auto& w : words) argv.push_back(const_cast<char*>(w.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int started = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ProcessRun run;
  if (started != 0) return run;
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  run.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  run.cpu_s = usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  run.max_rss_kb = usage.ru_maxrss;
  return run;
}

}  // namespace gearkit::bench
