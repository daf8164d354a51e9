// Out of memory is an internal failure reported in one line with status 1, never an abort or a
// crash (issue 11, item 8). Found here: nlohmann::json's destructor allocating while a
// std::bad_alloc unwinds (abort, status 134), the same destructor reading a half-built array
// (segmentation fault at 40 MB), and CLN's static constructors failing before main() (abort at
// 26 MB, before GiNaC moved into the kin --equations module).
#include <run_gearkit.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using gearkit::testing::run_gearkit;
using gearkit::testing::shell_quote;

namespace {

struct Outcomes {
  int out_of_memory = 0;
  int completed = 0;
};

// Runs `gearkit kin FILE --sweep SWEEP --format json` under address-space limits from `low_kb`
// to `high_kb`.
Outcomes run_at_limits(const std::string& file, const std::string& sweep, int low_kb, int high_kb, int step_kb) {
  const std::string args = "kin " + shell_quote(file) + " --sweep " + sweep + " --format json";
  Outcomes n;
  bool main_ran = false;  // gearkit's own code ran at a lower limit
  for (int kb = low_kb; kb <= high_kb; kb += step_kb) {
    const auto r = run_gearkit(args, "ulimit -v " + std::to_string(kb) + ";");
    if (r.status == 0) {
      ++n.completed;
      continue;
    }
    // Below what the dynamic loader needs to map the libraries it refuses before gearkit runs.
    if (r.status == 127 && r.err.find("error while loading shared libraries") != std::string::npos) continue;
    // Just above that, a system library's constructor may fail before main(): libgfortran's
    // (pulled in by SuiteSparse's LAPACK) recurses in its own error handler when calloc fails
    // and overflows the stack. Nothing of gearkit has run (no line of it on stderr) and no
    // higher limit may show it.
    if (!main_ran && r.err.find("gearkit") == std::string::npos) continue;
    main_ran = true;
    ++n.out_of_memory;
    EXPECT_EQ(r.status, 1) << kb << " KB: " << r.err;
    // A plugin that cannot be mapped at the tightest limits is a warning line before the reason.
    const std::string last = "gearkit: internal error: out of memory\n";
    EXPECT_TRUE(r.err.size() >= last.size() && r.err.substr(r.err.size() - last.size()) == last) << kb << " KB: " << r.err;
    for (std::size_t line = 0; line < r.err.size(); line = r.err.find('\n', line) + 1)
      EXPECT_EQ(r.err.compare(line, 9, "gearkit: "), 0) << r.err;
  }
  return n;
}

}  // namespace

// From about what the dynamic loader needs to map the libraries to above the run's needs, so
// that every allocation site fails at one of the limits: the four-bar's streamed sweep (whose
// memory does not grow with its length) in 256 KB steps, and a 1000-loop chain (6003
// coordinates: the mobility analysis and the sparse factorisations allocate most) in 2 MB steps.
TEST(OutOfMemory, IsOneLineAndStatusOneAtEveryLimit) {
#ifdef GEARKIT_SANITIZED
  GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: ulimit -v cannot apply";
#endif
  const std::string four_bar = std::string(GEARKIT_SOURCE_DIR) + "/examples/mechanisms/four_bar.yaml";
  const Outcomes fine = run_at_limits(four_bar, "0:360:0.1", 18 * 1024, 36 * 1024, 256);
  EXPECT_GT(fine.out_of_memory, 0);  // the smallest limits do run out
  EXPECT_GT(fine.completed, 0);      // and the largest do not
  const std::filesystem::path chain = gearkit::testing::scratch_dir("out-of-memory") / "chain.yaml";
  std::ofstream(chain) << run_gearkit("kin --example chain:1000").out;
  const Outcomes large = run_at_limits(chain.string(), "0:4:1", 24 * 1024, 90 * 1024, 2 * 1024);
  EXPECT_GT(large.out_of_memory, 0);
  EXPECT_GT(large.completed, 0);
}
