#pragma once
// Runs the gearkit executable from a test and captures its exit status, stdout and stderr.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace gearkit::testing {

struct RunResult {
  int status = -1;  ///< exit status, or 128+signal if killed by a signal
  std::string out;
  std::string err;
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Quotes one word for /bin/sh.
inline std::string shell_quote(const std::string& s) {
  std::string r = "'";
  for (char c : s) {
    if (c == '\'') r += "'\\''";
    else r += c;
  }
  return r + "'";
}

/// A fresh scratch folder under the build tree, removed and recreated. The process id is part
/// of the name because ctest runs several test processes at once.
inline std::filesystem::path scratch_dir(const std::string& name) {
  std::filesystem::path d =
      std::filesystem::path(GEARKIT_BINARY_DIR) / "test-scratch" / (name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

/// Runs `gearkit <args>` with an optional environment prefix ("GEARKIT_PLUGIN_PATH=... "),
/// optional stdin file and optional stdout destination (captured in RunResult::out when empty;
/// "/dev/null" for outputs too large to keep). `args` is already shell-quoted where needed.
inline RunResult run_gearkit(const std::string& args, const std::string& env = "",
                             const std::string& stdin_file = "/dev/null", const std::string& stdout_file = "") {
  static int counter = 0;
  std::filesystem::path dir = std::filesystem::path(GEARKIT_BINARY_DIR) / "test-scratch" / "runs";
  std::filesystem::create_directories(dir);
  std::string stem = std::to_string(::getpid()) + "-" + std::to_string(counter++);
  std::filesystem::path out = dir / (stem + ".out"), err = dir / (stem + ".err");
  std::string cmd = env + " " + shell_quote(GEARKIT_EXE) + " " + args + " < " + shell_quote(stdin_file) + " > " +
                    shell_quote(stdout_file.empty() ? out.string() : stdout_file) + " 2> " + shell_quote(err.string());
  int raw = std::system(cmd.c_str());
  RunResult r;
  if (WIFEXITED(raw)) r.status = WEXITSTATUS(raw);
  else if (WIFSIGNALED(raw)) r.status = 128 + WTERMSIG(raw);
  if (stdout_file.empty()) r.out = slurp(out);
  r.err = slurp(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

/// Number of lines in a text (a trailing newline does not start a new line).
inline int count_lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  if (!s.empty() && s.back() != '\n') ++n;
  return n;
}

}  // namespace gearkit::testing
