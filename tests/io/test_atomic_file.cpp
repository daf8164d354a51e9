// Tests for gearkit/io/atomic_file.hpp: a failed write leaves nothing behind.
#include <gearkit/io/atomic_file.hpp>

#include <gearkit/io/error.hpp>
#include <run_gearkit.hpp>

#include <gtest/gtest.h>

#include <filesystem>

namespace fs = std::filesystem;
using gearkit::io::InputError;
using gearkit::io::write_file_atomic;

TEST(AtomicFile, WritesAndReplaces) {
  auto dir = gearkit::testing::scratch_dir("atomic");
  auto p = dir / "a.txt";
  write_file_atomic(p.string(), "first", "--output");
  EXPECT_EQ(gearkit::testing::slurp(p), "first");
  write_file_atomic(p.string(), "second", "--output");
  EXPECT_EQ(gearkit::testing::slurp(p), "second");
  int files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1);  // no temporary left
}

TEST(AtomicFile, MissingFolderIsAnOptionError) {
  auto dir = gearkit::testing::scratch_dir("atomic2");
  try {
    write_file_atomic((dir / "nope" / "a.dxf").string(), "x", "--dxf");
    FAIL();
  } catch (const InputError& e) {
    std::string m = e.what();
    EXPECT_EQ(m.rfind("option '--dxf': cannot write", 0), 0u) << m;
    EXPECT_NE(m.find("does not exist"), std::string::npos) << m;
  }
  EXPECT_FALSE(fs::exists(dir / "nope"));
}

TEST(AtomicFile, DirectoryAsTargetIsRefusedAndUntouched) {
  auto dir = gearkit::testing::scratch_dir("atomic3");
  EXPECT_THROW(write_file_atomic(dir.string(), "x", "--svg"), InputError);
  EXPECT_TRUE(fs::is_directory(dir));
  EXPECT_TRUE(fs::is_empty(dir));
}
