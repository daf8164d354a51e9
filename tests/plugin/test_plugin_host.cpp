// Tests for gearkit/plugin/plugin_host.hpp: the loading rules (stamp read before loading,
// regular files only, absolute paths), the registry rules (built-ins always win, null functions
// refused, clashes name both files, all or nothing) and the search (failures collected).
#include <gearkit/mechanism/reader.hpp>
#include <gearkit/kin/solve.hpp>
#include <gearkit/plugin/plugin_host.hpp>

#include <run_gearkit.hpp>

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using gearkit::plugin::kApiVersion;
using gearkit::plugin::PluginError;
using gearkit::plugin::PluginHost;

namespace {

const fs::path kDir = GEARKIT_TEST_PLUGIN_DIR;

fs::path plugin(const std::string& name) { return kDir / ("test-" + name + ".so"); }

std::string load_error(PluginHost& host, const fs::path& f) {
  try {
    host.load(f);
  } catch (const PluginError& e) {
    EXPECT_EQ(e.file(), fs::absolute(f).lexically_normal());
    return e.what();
  }
  ADD_FAILURE() << "expected " << f << " to be refused";
  return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The host with the names the executable builds in.
gearkit::plugin::BuiltinNames builtins() { return {{"demo", "help", "kin", "plugins"}, {"revolute", "prismatic", "pin_in_slot"}}; }

// Sets GEARKIT_TEST_MARKER_DIR to a fresh folder for the static constructors of the test plugins.
fs::path marker_dir(const std::string& name) {
  const fs::path dir = gearkit::testing::scratch_dir(name);
  ::setenv("GEARKIT_TEST_MARKER_DIR", dir.c_str(), 1);
  return dir;
}

}  // namespace

TEST(PluginHost, LoadsAGoodPluginAndRunsItsCommand) {
  PluginHost host(builtins());
  host.load(plugin("good"));
  ASSERT_EQ(host.plugins().size(), 1u);
  const auto& p = host.plugins().front();
  EXPECT_EQ(p.name, "test-good");
  EXPECT_EQ(p.version, "9.8.7");
  EXPECT_EQ(p.file, plugin("good"));
  EXPECT_EQ(p.commands, std::vector<std::string>{"hello-test"});
  EXPECT_EQ(p.element_types, std::vector<std::string>{"test_element"});
  const auto* cmd = host.find_command("hello-test");
  ASSERT_NE(cmd, nullptr);
  std::ostringstream out, err;
  gearkit::plugin::CommandContext ctx{{"a", "b"}, out, err, host};
  EXPECT_EQ(cmd->run(ctx), 0);
  EXPECT_EQ(out.str(), "hello from test plugin a b\n");
  EXPECT_EQ(ctx.host.find_element_type("test_element"), host.find_element_type("test_element"));
}

// The element type a plugin registers reads a mechanism file through the host's lookup.
TEST(PluginHost, AnElementTypeOfAPluginReadsAMechanism) {
  PluginHost host(builtins());
  host.load(plugin("good"));
  const std::string text = R"(ground: {O: [0, 0], P: [100, 0]}
links:
  a: {points: {O: [0, 0]}}
  b: {points: {P: [0, 0]}}
joints:
  - {type: revolute, at: [a.O, ground.O]}
  - {type: revolute, at: [b.P, ground.P]}
elements:
  - {type: test_element, a: a, b: b, ratio: 2}
drivers:
  - {type: angle, link: a, value: 30 deg}
)";
  auto lookup = [&](std::string_view type) { return host.find_element_type(type); };
  const auto mech = gearkit::mechanism::read_mechanism(gearkit::io::load_yaml_text(text, "m.yaml"), lookup);
  gearkit::kin::Data data(mech.model);
  ASSERT_TRUE(gearkit::kin::solve_position(mech.model, data, 0.0).converged);
  EXPECT_NEAR(data.q(5), 2.0 * 30.0 * M_PI / 180.0, 1e-12);  // theta_b = 2 theta_a
}

// Files without a matching stamp are refused from the file: none of their code runs (their
// static constructors would leave a marker file). The good plugin's constructor does run, which
// shows the marker would appear.
TEST(PluginHost, StampIsCheckedBeforeAnyCodeRuns) {
  const fs::path markers = marker_dir("plugin_markers");
  PluginHost host(builtins());
  const std::string api = load_error(host, plugin("wrong_api"));
  EXPECT_TRUE(contains(api, "test-wrong_api.so")) << api;
  EXPECT_TRUE(contains(api, "built for plugin API version " + std::to_string(kApiVersion + 41) +
                                ", this gearkit needs version " + std::to_string(kApiVersion)))
      << api;
  EXPECT_TRUE(contains(load_error(host, plugin("wrong_abi")), "another layout of the plugin interface"));
  EXPECT_TRUE(contains(load_error(host, plugin("no_stamp")), "has no gearkit plugin stamp"));
  for (const char* name : {"wrong_api", "wrong_abi", "no_stamp"}) EXPECT_FALSE(fs::exists(markers / name)) << name;
  // A fresh copy, so that its constructor runs even if this process loaded the plugin before.
  fs::copy_file(plugin("good"), markers / "good-copy.so");
  host.load(markers / "good-copy.so");
  EXPECT_TRUE(fs::exists(markers / "good"));
  ::unsetenv("GEARKIT_TEST_MARKER_DIR");
}

TEST(PluginHost, RejectsAMissingSymbol) {
  PluginHost host(builtins());
  EXPECT_TRUE(contains(load_error(host, plugin("missing_symbol")), "missing symbol 'gearkit_plugin_register'"));
}

TEST(PluginHost, LoadsRegularFilesOnly) {
  PluginHost host(builtins());
  EXPECT_TRUE(contains(load_error(host, kDir / "no-such-plugin.so"), "no such file"));
  const fs::path scratch = gearkit::testing::scratch_dir("plugin_files");
  std::ofstream(scratch / "broken.so") << "this is not an ELF file\n";
  const std::string broken = load_error(host, scratch / "broken.so");
  EXPECT_TRUE(contains(broken, "broken.so") && contains(broken, "not an ELF shared object")) << broken;
  EXPECT_TRUE(contains(load_error(host, scratch), "not a regular file"));
  // A FIFO would block a reader forever: it is refused without waiting for a writer.
  ASSERT_EQ(::mkfifo((scratch / "fifo.so").c_str(), 0600), 0);
  EXPECT_TRUE(contains(load_error(host, scratch / "fifo.so"), "not a regular file"));
  EXPECT_TRUE(host.plugins().empty());
}

// A bare name is the file in the working directory, never a library found on the library path:
// here the working directory holds the test plugin under the name of the C maths library.
TEST(PluginHost, BareNameIsTheFileInTheWorkingDirectory) {
  const fs::path scratch = gearkit::testing::scratch_dir("plugin_bare_name");
  fs::copy_file(plugin("good"), scratch / "libm.so.6", fs::copy_options::overwrite_existing);
  const fs::path before = fs::current_path();
  fs::current_path(scratch);
  PluginHost host(builtins());
  EXPECT_NO_THROW(host.load("libm.so.6"));
  fs::current_path(before);
  ASSERT_EQ(host.plugins().size(), 1u);
  EXPECT_EQ(host.plugins().front().name, "test-good");
  EXPECT_EQ(host.plugins().front().file, scratch / "libm.so.6");
}

TEST(PluginHost, BuiltInNamesCannotBeRegistered) {
  PluginHost host(builtins());
  EXPECT_TRUE(contains(load_error(host, plugin("builtin_command")), "registers the command 'kin', which is built into gearkit"));
  EXPECT_TRUE(contains(load_error(host, plugin("builtin_element")),
                       "registers the element type 'revolute', which is built into gearkit"));
  EXPECT_EQ(host.find_command("kin"), nullptr);
  EXPECT_EQ(host.find_element_type("revolute"), nullptr);
}

TEST(PluginHost, NullFunctionsAreRefused) {
  PluginHost host(builtins());
  EXPECT_TRUE(contains(load_error(host, plugin("null_function")), "without a name or a read function"));
  EXPECT_EQ(host.find_element_type("null_element"), nullptr);
}

TEST(PluginHost, ElementTypesOfAnotherElementAbiAreRefused) {
  PluginHost host(builtins());
  EXPECT_TRUE(contains(load_error(host, plugin("element_abi")), "another element ABI"));
  EXPECT_EQ(host.find_element_type("old_element"), nullptr);
}

// A name registered by two plugins: the later plugin is refused whole, naming both files; the
// earlier one keeps working.
TEST(PluginHost, AClashNamesBothFilesAndRefusesTheLaterPlugin) {
  PluginHost host(builtins());
  host.load(plugin("clash_a"));
  const std::string command = load_error(host, plugin("clash_b"));
  EXPECT_TRUE(contains(command, "test-clash_b.so") && contains(command, plugin("clash_a").string()) &&
              contains(command, "command 'clash-test'"))
      << command;
  host.load(plugin("good"));
  const std::string element = load_error(host, plugin("clash_element"));
  EXPECT_TRUE(contains(element, "test-clash_element.so") && contains(element, plugin("good").string()) &&
              contains(element, "element type 'test_element'"))
      << element;
  ASSERT_EQ(host.plugins().size(), 2u);
  std::ostringstream out, err;
  gearkit::plugin::CommandContext ctx{{}, out, err, host};
  host.find_command("clash-test")->run(ctx);
  EXPECT_EQ(out.str(), "clash a\n");
}

TEST(PluginHost, APluginNameLoadsOnce) {
  const fs::path scratch = gearkit::testing::scratch_dir("plugin_twice");
  fs::copy_file(plugin("good"), scratch / "again.so", fs::copy_options::overwrite_existing);
  PluginHost host(builtins());
  host.load(plugin("good"));
  const std::string again = load_error(host, scratch / "again.so");
  EXPECT_TRUE(contains(again, "is plugin 'test-good', already loaded from '" + plugin("good").string())) << again;
}

// The search: copies of a loaded plugin further down the path are skipped, every other failure
// is collected (one per file, in name order), missing folders are no error.
TEST(PluginHost, LoadAllSkipsCopiesAndCollectsFailures) {
  const fs::path first = gearkit::testing::scratch_dir("plugin_path_1");
  const fs::path second = gearkit::testing::scratch_dir("plugin_path_2");
  for (const fs::path& dir : {first, second})
    fs::copy_file(plugin("good"), dir / "gearkit-test-good.so", fs::copy_options::overwrite_existing);
  fs::copy_file(plugin("wrong_api"), second / "a-wrong.so", fs::copy_options::overwrite_existing);
  fs::copy_file(plugin("missing_symbol"), second / "b-missing.so", fs::copy_options::overwrite_existing);
  PluginHost host(builtins());
  host.load_all({first, "/nonexistent/folder", second});
  ASSERT_EQ(host.plugins().size(), 1u);
  EXPECT_EQ(host.plugins().front().file, first / "gearkit-test-good.so");
  ASSERT_EQ(host.failures().size(), 2u);
  EXPECT_EQ(host.failures()[0].file(), second / "a-wrong.so");
  EXPECT_TRUE(contains(host.failures()[0].reason(), "plugin API version"));
  EXPECT_EQ(host.failures()[1].file(), second / "b-missing.so");
}

TEST(PluginHost, DefaultLocationsHonourTheEnvironment) {
  ::setenv("GEARKIT_PLUGIN_PATH", "/a:/b/c.so::", 1);
  const auto locs = gearkit::plugin::default_plugin_locations("/opt/gk/bin/gearkit");
  ::unsetenv("GEARKIT_PLUGIN_PATH");
  ASSERT_EQ(locs.size(), 3u);
  EXPECT_EQ(locs[0], "/a");
  EXPECT_EQ(locs[1], "/b/c.so");
  EXPECT_EQ(locs[2], "/opt/gk/lib/gearkit/plugins");
}

// Issue 26, section 2: code others can replace is never loaded (the file, its folder, and the
// folder of a link to it, writable by the group or by everyone), and a relative location of the
// search path is not searched.
TEST(PluginHost, PluginsWritableByOthersAndRelativeLocationsAreRefused) {
  const fs::path scratch = gearkit::testing::scratch_dir("plugin_modes");
  const fs::path safe = scratch / "safe", open = scratch / "open";
  fs::create_directories(safe);
  fs::create_directories(open);
  fs::permissions(safe, static_cast<fs::perms>(0755));
  fs::permissions(open, static_cast<fs::perms>(0775));
  fs::copy_file(plugin("good"), safe / "good.so");
  fs::permissions(safe / "good.so", static_cast<fs::perms>(0646));
  PluginHost host(builtins());
  EXPECT_TRUE(contains(load_error(host, safe / "good.so"), "the file '" + (safe / "good.so").string() +
                                                               "' is writable by everyone (mode 0646)"));
  fs::permissions(safe / "good.so", static_cast<fs::perms>(0755));
  fs::create_symlink(safe / "good.so", open / "link.so");  // a safe file, reached from an open folder
  EXPECT_TRUE(contains(load_error(host, open / "link.so"), "its folder '" + open.string() +
                                                               "' is writable by its group (mode 0775)"));
  EXPECT_TRUE(host.plugins().empty());
  host.load(safe / "good.so");
  EXPECT_EQ(host.plugins().size(), 1u);

  PluginHost searching(builtins());
  searching.load_all({"relative/folder"});
  ASSERT_EQ(searching.failures().size(), 1u);
  EXPECT_TRUE(contains(searching.failures()[0].reason(), "a relative entry of the plugin path is ignored"));
}
