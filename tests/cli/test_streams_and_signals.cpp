// The start-up and end guarantees of docs/cli.md ("Output files") that a command's own code never
// sees (issue 26, section 2): standard streams the caller closed, signals that end a run while
// its temporaries exist, and an unusable TMPDIR for `demo`.
#include <run_gearkit.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using gearkit::testing::run_gearkit;
using gearkit::testing::shell_quote;
using gearkit::testing::slurp;

namespace {

const fs::path kExamples = fs::path(GEARKIT_SOURCE_DIR) / "examples";

std::string q(const fs::path& p) { return shell_quote(p.string()); }

/// Runs a shell command line and returns its exit status (128 + signal if killed).
int shell(const std::string& command) {
  const int raw = std::system(command.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
}

/// The temporaries an OutputSet leaves in `dir` (".NAME.PID-xxxxxx.gearkit-tmp").
std::vector<std::string> temporaries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().ends_with(".gearkit-tmp")) names.push_back(e.path().filename().string());
  return names;
}

/// Starts gearkit with `args`, standard output on `stdout_fd`, stdin and stderr on /dev/null,
/// the four signals at their default action except `ignored` (SIG_IGN, as nohup sets it).
pid_t start_gearkit(const std::vector<std::string>& args, int stdout_fd, int ignored = 0) {
  const pid_t pid = ::fork();
  if (pid != 0) return pid;
  const int null = ::open("/dev/null", O_RDWR);
  ::dup2(null, 0);
  ::dup2(stdout_fd, 1);
  ::dup2(null, 2);
  for (int fd = 3; fd < 1024; ++fd) ::close(fd);  // the pipe's read end above all: else no SIGPIPE
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) std::signal(sig, sig == ignored ? SIG_IGN : SIG_DFL);
  std::vector<char*> argv{const_cast<char*>(GEARKIT_EXE)};
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  ::execv(GEARKIT_EXE, argv.data());
  ::_exit(127);
}

/// The wait status of `pid`, killed (SIGKILL) if it has not ended within 20 s: a test must not hang.
int wait_for_end(pid_t pid) {
  int status = 0;
  for (int i = 0; i < 4000; ++i) {
    if (::waitpid(pid, &status, WNOHANG) == pid) return status;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ::kill(pid, SIGKILL);
  ::waitpid(pid, &status, 0);
  ADD_FAILURE() << "gearkit did not end within 20 s";
  return status;
}

/// Waits (at most 10 s) until `dir` holds a temporary; false if the process ended first.
bool wait_for_temporary(const fs::path& dir, pid_t pid) {
  for (int i = 0; i < 2000; ++i) {
    if (!temporaries(dir).empty()) return true;
    int status = 0;
    if (::waitpid(pid, &status, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ::kill(pid, SIGKILL);
  ::waitpid(pid, nullptr, 0);
  return false;
}

/// A sweep long enough (3.6 million positions) to be running when the signal comes.
std::vector<std::string> long_sweep(const fs::path& dir) {
  return {"kin", (kExamples / "mechanisms" / "four_bar.yaml").string(), "--sweep", "0:360:0.0001",
          "--plot", (dir / "p.svg").string(), "--output", (dir / "report.txt").string()};
}

}  // namespace

// `gearkit train FILE --svg t.svg >&-` appended the text report to t.svg: the file opened first got
// descriptor 1. Now descriptors 0 to 2 are /dev/null when closed, and each file holds its own.
TEST(StandardStreams, ClosedStreamsNeverReceiveAnOutputFile) {
  const auto dir = gearkit::testing::scratch_dir("closed_streams");
  const fs::path train = kExamples / "trains" / "simple_planetary.yaml";
  const fs::path cam = kExamples / "cams" / "translating_roller_cycloidal.yaml";
  const fs::path kin = kExamples / "mechanisms" / "four_bar.yaml";
  const std::string exe = shell_quote(GEARKIT_EXE);
  EXPECT_EQ(shell("exec " + exe + " train " + q(train) + " --svg " + q(dir / "t.svg") + " >&-"), 0);
  EXPECT_EQ(shell("exec " + exe + " cam " + q(cam) + " --dxf " + q(dir / "c.dxf") + " --csv " + q(dir / "c.csv") +
                  " <&- >&- 2>&-"),
            0);
  EXPECT_EQ(shell("exec " + exe + " kin " + q(kin) + " --sweep 0:360:10 --plot " + q(dir / "k.svg") + " >&-"), 0);
  // Each file is exactly its own document: it starts as one and holds no report line.
  const std::string t = slurp(dir / "t.svg"), c = slurp(dir / "c.dxf"), csv = slurp(dir / "c.csv"),
                    k = slurp(dir / "k.svg");
  EXPECT_EQ(t.rfind("<?xml", 0), 0u) << t.substr(0, 80);
  EXPECT_EQ(k.rfind("<?xml", 0), 0u) << k.substr(0, 80);
  EXPECT_EQ(c.rfind("  0\nSECTION", 0), 0u) << c.substr(0, 80);
  EXPECT_EQ(csv.find("Warnings"), std::string::npos);
  for (const std::string* s : {&t, &k}) {
    EXPECT_EQ(s->find("Warnings"), std::string::npos);
    EXPECT_EQ(s->substr(s->size() - 7), "</svg>\n");
  }
  // A bad input with every stream closed: status 2, and the drawing not written at all.
  EXPECT_EQ(shell("exec " + exe + " train " + q(train) + " --svg " + q(dir / "bad.svg") + " --fix nothing <&- >&- 2>&-"),
            2);
  EXPECT_FALSE(fs::exists(dir / "bad.svg"));
}

// SIGINT, SIGTERM and SIGHUP left `.NAME.PID-xxxxxx.gearkit-tmp` files of up to 52 MB. Now the
// temporaries are removed and the process still ends by the signal (a shell sees 128 + signal).
TEST(Signals, EveryCatchableSignalRemovesTheTemporaries) {
  for (int sig : {SIGTERM, SIGINT, SIGHUP}) {
    const auto dir = gearkit::testing::scratch_dir("signal_" + std::to_string(sig));
    const int null = ::open("/dev/null", O_WRONLY);
    const pid_t pid = start_gearkit(long_sweep(dir), null);
    ::close(null);
    ASSERT_TRUE(wait_for_temporary(dir, pid)) << "signal " << sig << ": no temporary seen while running";
    ::kill(pid, sig);
    const int status = wait_for_end(pid);
    EXPECT_TRUE(WIFSIGNALED(status)) << "signal " << sig << ": status " << status;
    if (WIFSIGNALED(status)) {
      EXPECT_EQ(WTERMSIG(status), sig);
    }
    EXPECT_TRUE(temporaries(dir).empty()) << "signal " << sig << " left " << temporaries(dir).front();
    EXPECT_FALSE(fs::exists(dir / "p.svg"));
    EXPECT_FALSE(fs::exists(dir / "report.txt"));
  }
}

// `gearkit kin ... --plot p.svg | head -1`: the reader goes away, the next write raises SIGPIPE
// (status 141 in a shell, as before), and no temporary is left.
TEST(Signals, AClosedPipeEndsTheRunBySigpipeWithoutTemporaries) {
  const auto dir = gearkit::testing::scratch_dir("signal_pipe");
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  std::vector<std::string> args = long_sweep(dir);
  args.resize(args.size() - 2);  // the report to the pipe
  const pid_t pid = start_gearkit(args, fds[1]);
  ::close(fds[1]);
  char first[64];
  ASSERT_GT(::read(fds[0], first, sizeof first), 0);  // the first bytes of the report: running
  ASSERT_FALSE(temporaries(dir).empty());             // the plot's temporary exists meanwhile
  ::close(fds[0]);
  const int status = wait_for_end(pid);
  ASSERT_TRUE(WIFSIGNALED(status)) << status;
  EXPECT_EQ(WTERMSIG(status), SIGPIPE);
  EXPECT_TRUE(temporaries(dir).empty());
  EXPECT_FALSE(fs::exists(dir / "p.svg"));
}

// A signal the caller ignores (nohup ignores SIGHUP) stays ignored: the run goes on.
TEST(Signals, AnIgnoredSignalStaysIgnored) {
  const auto dir = gearkit::testing::scratch_dir("signal_ignored");
  const int null = ::open("/dev/null", O_WRONLY);
  const pid_t pid = start_gearkit(long_sweep(dir), null, SIGHUP);
  ::close(null);
  ASSERT_TRUE(wait_for_temporary(dir, pid));
  ::kill(pid, SIGHUP);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  int status = 0;
  EXPECT_EQ(::waitpid(pid, &status, WNOHANG), 0) << "ended by an ignored SIGHUP";
  ::kill(pid, SIGTERM);
  wait_for_end(pid);
  EXPECT_TRUE(temporaries(dir).empty());
}

// `gearkit demo` failed with "internal error: filesystem error: temp_directory_path" (status 1)
// for a TMPDIR that is relative, missing or a file. It now says so in a warning and uses /tmp.
TEST(DemoTemporaryFolder, AnUnusableTmpdirFallsBackToTmp) {
  const auto dir = gearkit::testing::scratch_dir("demo_tmpdir");
  const fs::path file = dir / "a-file";
  std::ofstream(file) << "x";
  struct Case {
    std::string tmpdir, why;
  };
  const std::vector<Case> cases{{"", ""}, {"relative/tmp", "is not an absolute path"},
                                 {(dir / "missing").string(), "is missing"}, {file.string(), "is not a folder"}};
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Case& c = cases[i];
    const fs::path out = dir / ("out" + std::to_string(i));
    const auto r = run_gearkit("demo --output " + q(out), "TMPDIR=" + shell_quote(c.tmpdir));
    EXPECT_EQ(r.status, 0) << c.tmpdir << ": " << r.err;
    EXPECT_TRUE(fs::exists(out / "cam.dxf")) << c.tmpdir;
    if (c.why.empty()) {
      EXPECT_TRUE(r.err.empty()) << r.err;  // an empty TMPDIR is an unset one
    } else {
      // One warning line; the value is quoted (cut at 60 characters, as every value in a message).
      EXPECT_EQ(gearkit::testing::count_lines(r.err), 1) << r.err;
      EXPECT_EQ(r.err.rfind("gearkit: warning: TMPDIR '" + c.tmpdir.substr(0, 40), 0), 0u) << r.err;
      EXPECT_TRUE(r.err.ends_with("' " + c.why + "; demo uses /tmp\n")) << r.err;
    }
  }
}
