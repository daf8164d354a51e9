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
  expect_bad_input(run_gearkit("plugins --format xml"), "option '--format': expected text, json, csv or md");
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

  // A folder with plugins built wrongly: each named on stderr; the rest keeps working.
  auto all = run_gearkit("hello-test", "GEARKIT_PLUGIN_PATH=" + shell_quote(kTestPlugins));
  EXPECT_EQ(all.status, 0);
  EXPECT_NE(all.err.find("test-wrong_api.so"), std::string::npos) << all.err;
  EXPECT_NE(all.err.find("test-missing_symbol.so"), std::string::npos) << all.err;
  auto listing = run_gearkit("plugins --format json", "GEARKIT_PLUGIN_PATH=" + shell_quote(kTestPlugins));
  EXPECT_EQ(listing.status, 2);  // `gearkit plugins` says loudly that something failed to load
  EXPECT_EQ(nlohmann::json::parse(listing.out)["errors"].size(), 2u);
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
