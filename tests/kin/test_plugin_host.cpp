// Tests for gearkit/kin/plugin_host.hpp: loading good and bad plugin files.
#include <gearkit/kin/plugin_host.hpp>

#include <run_gearkit.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using gearkit::kin::kPluginApiVersion;
using gearkit::kin::PluginError;
using gearkit::kin::PluginHost;

namespace {
const fs::path kDir = GEARKIT_TEST_PLUGIN_DIR;

std::string load_error(PluginHost& host, const fs::path& f) {
  try {
    host.load(f);
  } catch (const PluginError& e) {
    EXPECT_EQ(e.file(), f);
    return e.what();
  }
  return "";
}
}  // namespace

TEST(PluginHost, LoadsAGoodPluginAndRunsItsCommand) {
  PluginHost host;
  host.load(kDir / "test-good.so");
  ASSERT_EQ(host.plugins().size(), 1u);
  const auto& p = host.plugins().front();
  EXPECT_EQ(p.name, "test-good");
  EXPECT_EQ(p.version, "9.8.7");
  EXPECT_EQ(p.commands, std::vector<std::string>{"hello-test"});
  EXPECT_EQ(p.element_types, std::vector<std::string>{"test_element"});
  ASSERT_NE(host.find_element_type("test_element"), nullptr);
  const auto* cmd = host.find_command("hello-test");
  ASSERT_NE(cmd, nullptr);
  std::ostringstream out, err;
  gearkit::kin::CommandContext ctx{{"a", "b"}, out, err};
  EXPECT_EQ(cmd->run(ctx), 0);
  EXPECT_EQ(out.str(), "hello from test plugin a b\n");
}

TEST(PluginHost, RejectsAnotherApiVersionNamingTheFile) {
  PluginHost host;
  std::string msg = load_error(host, kDir / "test-wrong_api.so");
  EXPECT_NE(msg.find("test-wrong_api.so"), std::string::npos) << msg;
  // tests/plugins/wrong_api.cpp declares the host's version + 41.
  EXPECT_NE(msg.find("built for plugin API version " + std::to_string(kPluginApiVersion + 41) + ", this gearkit needs version " +
                     std::to_string(kPluginApiVersion)),
            std::string::npos)
      << msg;
  EXPECT_TRUE(host.plugins().empty());
}

TEST(PluginHost, RejectsAMissingSymbol) {
  PluginHost host;
  std::string msg = load_error(host, kDir / "test-missing_symbol.so");
  EXPECT_NE(msg.find("missing symbol 'gearkit_plugin_register'"), std::string::npos) << msg;
}

TEST(PluginHost, RejectsMissingAndBrokenFiles) {
  PluginHost host;
  EXPECT_NE(load_error(host, kDir / "no-such-plugin.so").find("no such file"), std::string::npos);
  auto scratch = gearkit::testing::scratch_dir("plugin_host");
  std::ofstream(scratch / "broken.so") << "this is not an ELF file\n";
  std::string msg = load_error(host, scratch / "broken.so");
  EXPECT_NE(msg.find("broken.so"), std::string::npos);
  EXPECT_NE(msg.find("not a loadable plugin module"), std::string::npos) << msg;
  EXPECT_NE(load_error(host, scratch).find("is a directory"), std::string::npos);
}

TEST(PluginHost, RefusesADuplicateCommand) {
  auto scratch = gearkit::testing::scratch_dir("plugin_host_dup");
  fs::copy_file(kDir / "test-good.so", scratch / "copy-of-good.so");
  PluginHost host;
  host.load(kDir / "test-good.so");
  std::string msg = load_error(host, scratch / "copy-of-good.so");
  EXPECT_NE(msg.find("command 'hello-test' is already registered"), std::string::npos) << msg;
  EXPECT_EQ(host.plugins().size(), 1u);
}

TEST(PluginHost, LoadAllScansFoldersAndCollectsErrors) {
  PluginHost host;
  auto errors = host.load_all({kDir, "/nonexistent/folder"});
  EXPECT_EQ(host.plugins().size(), 1u);  // only the good one
  ASSERT_EQ(errors.size(), 2u);          // wrong API and missing symbol, each naming its file
  EXPECT_NE(std::string(errors[0].what()).find("test-missing_symbol.so"), std::string::npos);
  EXPECT_NE(std::string(errors[1].what()).find("test-wrong_api.so"), std::string::npos);
}

TEST(PluginHost, DefaultLocationsHonourTheEnvironment) {
  ::setenv("GEARKIT_PLUGIN_PATH", "/a:/b/c.so::", 1);
  auto locs = gearkit::kin::default_plugin_locations("/opt/gk/bin/gearkit");
  ::unsetenv("GEARKIT_PLUGIN_PATH");
  ASSERT_EQ(locs.size(), 4u);
  EXPECT_EQ(locs[0], "/a");
  EXPECT_EQ(locs[1], "/b/c.so");
  EXPECT_EQ(locs[2], "/opt/gk/bin/plugins");
  EXPECT_EQ(locs[3], "/opt/gk/lib/gearkit/plugins");
}
