// Out of memory is an internal failure reported in one line with status 1, never an abort
// (issue 11, item 8). The report of a sweep is built in nlohmann::json, whose destructor
// allocates while a std::bad_alloc unwinds: without the reserve main() releases, that second
// failure called std::terminate and the process aborted with status 134.
#include <run_gearkit.hpp>

#include <gtest/gtest.h>

#include <filesystem>

using gearkit::testing::run_gearkit;
using gearkit::testing::shell_quote;

TEST(OutOfMemory, IsOneLineAndStatusOneAtEveryLimit) {
#ifdef GEARKIT_SANITIZED
  GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: ulimit -v cannot apply";
#endif
  const std::string args = "kin " + shell_quote(std::string(GEARKIT_SOURCE_DIR) + "/examples/mechanisms/four_bar.yaml") +
                           " --sweep 0:360:0.1 --format json";
  int out_of_memory = 0;
  // From below the start-up footprint to well above the sweep's needs, in 5 MB steps: every
  // allocation site of the run fails at one of them.
  int completed = 0;
  for (int mb = 30; mb <= 180; mb += 5) {
    const auto r = run_gearkit(args, "ulimit -v " + std::to_string(mb * 1024) + ";");
    if (r.status == 0) {
      ++completed;
      continue;
    }
    ++out_of_memory;
    EXPECT_EQ(r.status, 1) << mb << " MB: " << r.err;
    // A plugin that cannot be mapped at the tightest limits is a warning line before the reason.
    const std::string last = "gearkit: internal error: out of memory\n";
    ASSERT_GE(r.err.size(), last.size()) << mb << " MB: " << r.err;
    EXPECT_EQ(r.err.substr(r.err.size() - last.size()), last) << mb << " MB";
    for (std::size_t line = 0; line < r.err.size(); line = r.err.find('\n', line) + 1)
      EXPECT_EQ(r.err.compare(line, 9, "gearkit: "), 0) << r.err;
  }
  EXPECT_GT(out_of_memory, 0);  // the smallest limits do run out
  EXPECT_GT(completed, 0);      // and the largest do not
}
