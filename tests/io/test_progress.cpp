// Tests for gearkit/io/progress.hpp: quiet unless stdout and stderr are terminals.
#include <gearkit/io/progress.hpp>

#include <gtest/gtest.h>

#include <unistd.h>

TEST(Progress, QuietWhenNotOnATerminalOrEmpty) {
  gearkit::io::Progress none("sweep", 0);
  EXPECT_FALSE(none.enabled());
  gearkit::io::Progress p("sweep", 100);
  EXPECT_EQ(p.enabled(), ::isatty(STDOUT_FILENO) && ::isatty(STDERR_FILENO));
  p.update(50);  // must not write anything when disabled (ctest captures output through pipes)
  p.update(100);
}
