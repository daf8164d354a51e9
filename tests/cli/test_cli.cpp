// End-to-end tests of the gearkit executable: exit status (0 ok, 2 bad input, 1 internal),
// one clear line on stderr for bad input, plugin discovery.
#include <run_gearkit.hpp>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using gearkit::testing::count_lines;
using gearkit::testing::run_gearkit;
using gearkit::testing::shell_quote;

namespace {
const std::string kTestPlugins = GEARKIT_TEST_PLUGIN_DIR;

// Bad input: status 2, exactly one line on stderr containing `part`, no backtrace.
void expect_bad_input(const gearkit::testing::RunResult& r, const std::string& part) {
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("terminate"), std::string::npos);
}
}  // namespace

TEST(Cli, VersionAndHelp) {
  auto v = run_gearkit("--version");
  EXPECT_EQ(v.status, 0);
  EXPECT_EQ(v.out.rfind("gearkit ", 0), 0u);
  auto h = run_gearkit("--help");
  EXPECT_EQ(h.status, 0);
  for (const char* cmd : {"gear", "train", "cam", "kin", "plugins", "demo"})
    EXPECT_NE(h.out.find(std::string("  ") + cmd + " "), std::string::npos) << cmd;
}

TEST(Cli, EveryCommandHasHelp) {
  for (const char* cmd : {"gear", "train", "cam", "kin", "plugins", "demo"}) {
    auto r = run_gearkit(std::string(cmd) + " --help");
    EXPECT_EQ(r.status, 0) << cmd << ": " << r.err;
    EXPECT_NE(r.out.find("usage: gearkit"), std::string::npos) << cmd;
    auto via_help = run_gearkit(std::string("help ") + cmd);
    EXPECT_EQ(via_help.out, r.out) << cmd;
  }
}

TEST(Cli, UsageErrors) {
  expect_bad_input(run_gearkit("frobnicate"), "unknown command 'frobnicate'");
  expect_bad_input(run_gearkit(""), "expected a command");
  expect_bad_input(run_gearkit("--bogus plugins"), "bogus");
  expect_bad_input(run_gearkit("plugins --format"), "format");
  expect_bad_input(run_gearkit("plugins --format xml"), "option '--format': expected text, json, csv, md or html");
  expect_bad_input(run_gearkit("plugins --no-such-option"), "no-such-option");
  expect_bad_input(run_gearkit("--plugin /nonexistent.so plugins"), "/nonexistent.so");
}

TEST(Cli, PluginsListsTheThreeDomainPlugins) {
  auto r = run_gearkit("plugins --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  std::map<std::string, nlohmann::json> by_name;
  for (const auto& p : j["plugins"]) by_name[p["name"]] = p;
  ASSERT_TRUE(by_name.count("gear") && by_name.count("train") && by_name.count("cam")) << r.out;
  EXPECT_EQ(by_name["gear"]["commands"][0], "gear");
  EXPECT_EQ(by_name["gear"]["element_types"][0], "gear_mesh");
  EXPECT_EQ(by_name["train"]["commands"][0], "train");
  EXPECT_EQ(by_name["cam"]["commands"][0], "cam");
  EXPECT_FALSE(by_name["gear"]["version"].get<std::string>().empty());
  EXPECT_TRUE(j["errors"].empty());
}

TEST(Cli, PluginPathLoadsAPluginAndReportsBrokenOnes) {
  std::string env = "GEARKIT_PLUGIN_PATH=" + shell_quote(kTestPlugins + "/test-good.so");
  auto r = run_gearkit("hello-test x y", env);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "hello from test plugin x y\n");
  EXPECT_TRUE(r.err.empty()) << r.err;

  // A folder with a good plugin and two broken ones: each broken one costs every other command
  // exactly one warning line, and the rest keeps working.
  const auto dir = gearkit::testing::scratch_dir("cli_plugin_path");
  for (const char* name : {"good", "wrong_api", "builtin_command"})
    std::filesystem::copy_file(kTestPlugins + "/test-" + name + ".so", dir / (std::string(name) + ".so"));
  const std::string path = "GEARKIT_PLUGIN_PATH=" + shell_quote(dir.string());
  auto all = run_gearkit("hello-test", path);
  EXPECT_EQ(all.status, 0);
  EXPECT_EQ(all.out, "hello from test plugin\n");
  EXPECT_EQ(gearkit::testing::count_lines(all.err), 2) << all.err;
  EXPECT_EQ(all.err.rfind("gearkit: warning: plugin '", 0), 0u) << all.err;
  EXPECT_NE(all.err.find("builtin_command.so': registers the command 'kin', which is built into gearkit (not loaded)\n"),
            std::string::npos) << all.err;
  EXPECT_NE(all.err.find("wrong_api.so': built for plugin API version"), std::string::npos) << all.err;

  // Built-ins always win: `kin` is gearkit's own.
  auto kin = run_gearkit("kin --help", path);
  EXPECT_EQ(kin.status, 0);
  EXPECT_NE(kin.out.find("gearkit kin options"), std::string::npos) << kin.out;

  // `gearkit plugins` names every failure with its reason and exits 2, one line per failure on
  // stderr (the last one a reason).
  auto listing = run_gearkit("plugins --format json", path);
  EXPECT_EQ(listing.status, 2);
  const auto j = nlohmann::json::parse(listing.out);
  ASSERT_EQ(j["errors"].size(), 2u);
  EXPECT_NE(j["errors"][0]["reason"].get<std::string>().find("built into gearkit"), std::string::npos);
  int good = 0;
  for (const auto& p : j["plugins"]) good += p["name"] == "test-good";
  EXPECT_EQ(good, 1);
  EXPECT_EQ(gearkit::testing::count_lines(listing.err), 2) << listing.err;
  const std::string last = listing.err.substr(listing.err.rfind('\n', listing.err.size() - 2) + 1);
  EXPECT_EQ(last.rfind("gearkit: plugin '", 0), 0u) << last;
  EXPECT_NE(last.find("wrong_api.so': built for plugin API version"), std::string::npos) << last;
  auto text = run_gearkit("plugins", path);
  EXPECT_NE(text.out.find("Failed to load"), std::string::npos) << text.out;
}

TEST(Cli, OutputFileIsWrittenAtomically) {
  auto dir = gearkit::testing::scratch_dir("cli_output");
  auto r = run_gearkit("plugins --format md --output " + shell_quote((dir / "p.md").string()));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.out.empty());
  EXPECT_NE(gearkit::testing::slurp(dir / "p.md").find("| plugin |"), std::string::npos);
  auto bad = run_gearkit("plugins --output " + shell_quote((dir / "missing" / "p.md").string()));
  expect_bad_input(bad, "option '--output': cannot write");
  EXPECT_FALSE(std::filesystem::exists(dir / "missing"));
}

// Issue 26, section 2: a plugin in a folder anyone may write (or a file anyone may write) was
// loaded silently and its constructor ran. It is now skipped with one warning line naming the
// file and why (ssh refuses such keys alike); given with --plugin it is an error. A relative
// entry of GEARKIT_PLUGIN_PATH, which would load what the working folder holds, is ignored.
TEST(Cli, PluginsOthersCanWriteAreNotLoaded) {
  const auto dir = gearkit::testing::scratch_dir("cli_plugin_modes");
  const std::filesystem::path open_folder = dir / "open", safe = dir / "safe";
  std::filesystem::create_directories(open_folder);
  std::filesystem::create_directories(safe);
  std::filesystem::copy_file(kTestPlugins + "/test-good.so", open_folder / "good.so");
  std::filesystem::copy_file(kTestPlugins + "/test-good.so", safe / "good.so");
  std::filesystem::permissions(open_folder, std::filesystem::perms::all);  // 0777, as in the issue
  std::filesystem::permissions(safe, static_cast<std::filesystem::perms>(0755));

  auto r = run_gearkit("hello-test", "GEARKIT_PLUGIN_PATH=" + shell_quote(open_folder.string()));
  EXPECT_EQ(r.status, 2);  // the command does not exist without the plugin
  EXPECT_NE(r.err.find("gearkit: warning: plugin '" + (open_folder / "good.so").string() + "': its folder '" +
                       open_folder.string() + "' is writable by everyone (mode 0777)"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("(not loaded)\n"), std::string::npos) << r.err;

  // A file writable by its group (0664) in a safe folder: the same, naming the file.
  std::filesystem::permissions(safe / "good.so", static_cast<std::filesystem::perms>(0664));
  auto gear = run_gearkit("gear --z1 12 --z2 24 --module 3", "GEARKIT_PLUGIN_PATH=" + shell_quote(safe.string()));
  EXPECT_EQ(gear.status, 0) << gear.err;  // other commands keep working, with one warning line
  EXPECT_EQ(gearkit::testing::count_lines(gear.err), 1) << gear.err;
  EXPECT_NE(gear.err.find("the file '" + (safe / "good.so").string() + "' is writable by its group (mode 0664)"),
            std::string::npos)
      << gear.err;
  auto given = run_gearkit("--plugin " + shell_quote((safe / "good.so").string()) + " hello-test");
  EXPECT_EQ(given.status, 2);
  EXPECT_EQ(gearkit::testing::count_lines(given.err), 1) << given.err;
  EXPECT_EQ(given.err.rfind("gearkit: option '--plugin': plugin '", 0), 0u) << given.err;
  EXPECT_NE(given.err.find("is writable by its group"), std::string::npos) << given.err;

  // Once only the owner may write, the same file loads.
  std::filesystem::permissions(safe / "good.so", static_cast<std::filesystem::perms>(0755));
  auto ok = run_gearkit("hello-test", "GEARKIT_PLUGIN_PATH=" + shell_quote(safe.string()));
  EXPECT_EQ(ok.status, 0) << ok.err;
  EXPECT_TRUE(ok.err.empty()) << ok.err;

  // A relative entry is ignored with a warning, even where it names a good plugin.
  auto relative = run_gearkit("hello-test", "cd " + shell_quote(dir.string()) + " && GEARKIT_PLUGIN_PATH=safe");
  EXPECT_EQ(relative.status, 2);
  EXPECT_NE(relative.err.find("gearkit: warning: plugin 'safe': a relative entry of the plugin path is ignored"),
            std::string::npos)
      << relative.err;
}
