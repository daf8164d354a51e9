// Tests for gearkit/io/output.hpp: outputs committed together or not at all, never over an
// input, through links, keeping permissions, devices written directly, temporaries cleaned up
// (issue 11, items 3 to 6).
#include <gearkit/io/output.hpp>

#include <gearkit/io/error.hpp>
#include <run_gearkit.hpp>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using gearkit::io::InputError;
using gearkit::io::OutputSet;
using gearkit::testing::slurp;

namespace {

void put(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

/// The message of the InputError `f` throws ("" when it throws none).
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// Names in `dir` that are not in `expected` (left-over temporaries).
std::vector<std::string> extra_files(const fs::path& dir, const std::set<std::string>& expected) {
  std::vector<std::string> extra;
  for (const auto& e : fs::directory_iterator(dir))
    if (!expected.count(e.path().filename().string())) extra.push_back(e.path().filename().string());
  return extra;
}

mode_t mode_of(const fs::path& p) {
  struct stat st{};
  ::stat(p.c_str(), &st);
  return st.st_mode & 0777;
}

}  // namespace

TEST(OutputSet, RefusesAnInputEvenThroughASymlinkAndLeavesItIntact) {
  auto dir = gearkit::testing::scratch_dir("output_input");
  put(dir / "model.yaml", "teeth: 20\n");
  fs::create_symlink("model.yaml", dir / "link.yaml");
  gearkit::io::note_input_file((dir / "model.yaml").string());
  std::ostringstream out;
  for (const char* name : {"model.yaml", "link.yaml"}) {
    OutputSet set(out);
    std::string m = error_of([&] { set.add("--output", (dir / name).string(), "report"); });
    EXPECT_NE(m.find("option '--output': cannot write"), std::string::npos) << m;
    EXPECT_NE(m.find("input file"), std::string::npos) << m;
  }
  gearkit::io::forget_input_files();
  EXPECT_EQ(slurp(dir / "model.yaml"), "teeth: 20\n");
  EXPECT_TRUE(extra_files(dir, {"model.yaml", "link.yaml"}).empty());
}

TEST(OutputSet, ABadDestinationLeavesEveryOtherOutputAsItWas) {
  auto dir = gearkit::testing::scratch_dir("output_all_or_nothing");
  put(dir / "c.dxf", "old dxf");
  std::ostringstream out;
  {
    OutputSet set(out);
    set.add("--dxf", (dir / "c.dxf").string(), "new dxf");
    std::string m = error_of([&] { set.add("--svg", (dir / "nodir" / "c.svg").string(), "svg"); });
    EXPECT_NE(m.find("option '--svg'"), std::string::npos) << m;
    EXPECT_NE(m.find("does not exist"), std::string::npos) << m;
  }  // destroyed without commit
  EXPECT_EQ(slurp(dir / "c.dxf"), "old dxf");
  EXPECT_TRUE(extra_files(dir, {"c.dxf"}).empty());
}

TEST(OutputSet, AFailedWriteAtCommitLeavesTheFilesAsTheyWere) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  auto dir = gearkit::testing::scratch_dir("output_full");
  put(dir / "a.txt", "old");
  std::ostringstream out;
  OutputSet set(out);
  set.add("--output", (dir / "a.txt").string(), "new");
  set.add("--svg", "/dev/full", "svg");
  std::string m = error_of([&] { set.commit(); });
  EXPECT_NE(m.find("option '--svg': cannot write '/dev/full'"), std::string::npos) << m;
  EXPECT_EQ(slurp(dir / "a.txt"), "old");
}

TEST(OutputSet, CommitsEveryOutputAndLeavesNoTemporary) {
  auto dir = gearkit::testing::scratch_dir("output_commit");
  put(dir / "a.txt", "old a");
  std::ostringstream out;
  OutputSet set(out);
  set.add("--dxf", (dir / "a.txt").string(), "new a");
  set.add("--svg", (dir / "b.txt").string(), "new b");
  set.add("--output", "-", "report");
  EXPECT_EQ(slurp(dir / "a.txt"), "old a");  // nothing in place before commit()
  EXPECT_EQ(out.str(), "");
  set.commit();
  EXPECT_EQ(slurp(dir / "a.txt"), "new a");
  EXPECT_EQ(slurp(dir / "b.txt"), "new b");
  EXPECT_EQ(out.str(), "report");
  EXPECT_TRUE(extra_files(dir, {"a.txt", "b.txt"}).empty());
}

TEST(OutputSet, StreamedOutputAppearsOnlyAtCommit) {
  auto dir = gearkit::testing::scratch_dir("output_stream");
  put(dir / "sweep.csv", "old");
  std::ostringstream out;
  OutputSet set(out);
  std::ostream& rows = set.stream("--output", (dir / "sweep.csv").string());
  for (int i = 0; i < 20000; ++i) rows << i << "," << i * i << "\n";  // more than one buffer
  EXPECT_EQ(slurp(dir / "sweep.csv"), "old");
  set.commit();
  std::string text = slurp(dir / "sweep.csv");
  EXPECT_EQ(text.substr(0, 8), "0,0\n1,1\n");
  EXPECT_NE(text.find("\n19999,399960001\n"), std::string::npos);
  std::ostream& direct = OutputSet(out).stream("--output", "-");
  EXPECT_EQ(&direct, &out);  // standard output is streamed as it comes
}

TEST(OutputSet, WritesThroughSymlinksAndKeepsHardLinksAndPermissions) {
  auto dir = gearkit::testing::scratch_dir("output_links");
  put(dir / "target.txt", "old");
  fs::create_symlink("target.txt", dir / "link.txt");
  put(dir / "a.txt", "old");
  fs::create_hard_link(dir / "a.txt", dir / "b.txt");
  put(dir / "private.txt", "old");
  fs::permissions(dir / "private.txt", fs::perms::owner_read | fs::perms::owner_write);
  fs::create_symlink("made-by-link.txt", dir / "dangling.txt");
  std::ostringstream out;
  OutputSet set(out);
  set.add("--output", (dir / "link.txt").string(), "via link");
  set.add("--dxf", (dir / "a.txt").string(), "via hard link");
  set.add("--svg", (dir / "private.txt").string(), "private");
  set.add("--plot", (dir / "dangling.txt").string(), "created");
  set.commit();
  EXPECT_TRUE(fs::is_symlink(dir / "link.txt"));
  EXPECT_EQ(slurp(dir / "target.txt"), "via link");
  EXPECT_EQ(slurp(dir / "b.txt"), "via hard link");
  EXPECT_EQ(fs::hard_link_count(dir / "a.txt"), 2u);
  EXPECT_EQ(mode_of(dir / "private.txt"), 0600u);
  EXPECT_TRUE(fs::is_symlink(dir / "dangling.txt"));
  EXPECT_EQ(slurp(dir / "made-by-link.txt"), "created");
}

TEST(OutputSet, ANewFileGetsTheUsualPermissions) {
  auto dir = gearkit::testing::scratch_dir("output_mode");
  mode_t mask = ::umask(022);
  std::ostringstream out;
  OutputSet set(out);
  set.add("--output", (dir / "new.txt").string(), "x");
  set.commit();
  ::umask(mask);
  EXPECT_EQ(mode_of(dir / "new.txt"), 0644u);  // not mkstemp's 0600
}

TEST(OutputSet, DevicesAreWrittenDirectlyAndNeverReplaced) {
  std::ostringstream out;
  OutputSet set(out);
  set.add("--output", "/dev/null", "discarded");
  set.commit();
  struct stat st{};
  ASSERT_EQ(::stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));  // as root the old writer renamed a regular file over it

  auto dir = gearkit::testing::scratch_dir("output_fifo");
  fs::path fifo = dir / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = slurp(fifo); });
  OutputSet to_fifo(out);
  to_fifo.add("--svg", fifo.string(), "through the pipe");
  to_fifo.commit();
  reader.join();
  EXPECT_EQ(received, "through the pipe");
  EXPECT_TRUE(fs::is_fifo(fifo));
}

TEST(OutputSet, RefusesEmptyNamesFoldersRepeatsAndReadOnlyFiles) {
  auto dir = gearkit::testing::scratch_dir("output_refusals");
  std::ostringstream out;
  OutputSet set(out);
  EXPECT_NE(error_of([&] { set.add("--output", "", "x"); }).find("found an empty name"), std::string::npos);
  EXPECT_NE(error_of([&] { set.add("--svg", dir.string(), "x"); }).find("it is a folder"), std::string::npos);
  EXPECT_NE(error_of([&] { set.add("--svg", (dir / "sub/").string(), "x"); }).find("found a folder name"),
            std::string::npos);
  set.add("--dxf", (dir / "a.dxf").string(), "x");
  EXPECT_NE(error_of([&] { set.add("--svg", (dir / "." / "a.dxf").string(), "x"); }).find("'--dxf' writes the same file"),
            std::string::npos);
  set.add("--output", "-", "report");
  EXPECT_NE(error_of([&] { set.add("--svg", "-", "x"); }).find("standard output already receives the output of '--output'"),
            std::string::npos);
  if (::geteuid() != 0) {  // root may write anything
    put(dir / "ro.txt", "keep");
    fs::permissions(dir / "ro.txt", fs::perms::owner_read);
    EXPECT_NE(error_of([&] { set.add("--plot", (dir / "ro.txt").string(), "x"); }).find("Permission denied"),
              std::string::npos);
  }
}

TEST(OutputSet, RemovesTheTemporariesOfAKilledRunButNotOfARunningOne) {
  auto dir = gearkit::testing::scratch_dir("output_stale");
  pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);  // a process id that no longer runs
  std::string stale = fmt::format(".report.json.{}-abc123{}", child, gearkit::io::kTemporarySuffix);
  std::string live = fmt::format(".report.json.{}-abc123{}", ::getppid(), gearkit::io::kTemporarySuffix);
  put(dir / stale, "half");
  put(dir / live, "being written");
  put(dir / ".report.json.tmp-XXXXXX", "not ours");
  std::ostringstream out;
  OutputSet set(out);
  set.add("--output", (dir / "report.json").string(), "{}");
  set.commit();
  EXPECT_FALSE(fs::exists(dir / stale));
  EXPECT_TRUE(fs::exists(dir / live));
  EXPECT_TRUE(fs::exists(dir / ".report.json.tmp-XXXXXX"));
}
