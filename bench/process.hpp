#pragma once
// Runs a program as the user would (posix_spawn, standard output to a file or /dev/null) and
// reports its wall time and peak memory: what the process benchmarks measure.
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <vector>

extern char** environ;

namespace gearkit::bench {

struct ProcessRun {
  bool ok = false;          ///< started and exited with status 0
  double seconds = 0.0;     ///< wall time from spawn to exit
  double peak_rss_mb = 0.0; ///< the child's maximum resident set size
};

/// Runs `words` (words[0] an absolute path) with standard output to `stdout_path`.
inline ProcessRun run_process(const std::vector<std::string>& words, const std::string& stdout_path = "/dev/null") {
  std::vector<char*> argv;
  for (const auto& w : words) argv.push_back(const_cast<char*>(w.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, stdout_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  ProcessRun run;
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return run;
  int status = 0;
  struct rusage usage {};
  wait4(pid, &status, 0, &usage);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.peak_rss_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;
  run.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  return run;
}

}  // namespace gearkit::bench
