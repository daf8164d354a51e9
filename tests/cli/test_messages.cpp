// The stderr rule of docs/cli.md ("Messages and exit status") end to end: one line per problem,
// each starting "gearkit:", warnings marked, the reason last on status 2, bad values quoted
// short (issue 11, items 2 and 11).
#include <run_gearkit.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using gearkit::testing::count_lines;
using gearkit::testing::run_gearkit;
using gearkit::testing::shell_quote;
using gearkit::testing::slurp;

namespace {

const std::string kTestPlugins = GEARKIT_TEST_PLUGIN_DIR;
const fs::path kExamples = fs::path(GEARKIT_SOURCE_DIR) / "examples";

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// Status 2 and exactly one stderr line that contains `part` and is at most `max_length` long.
void expect_one_line_error(const gearkit::testing::RunResult& r, const std::string& part, std::size_t max_length = 300) {
  EXPECT_EQ(r.status, 2) << r.err.substr(0, 300);
  ASSERT_EQ(count_lines(r.err), 1) << r.err.substr(0, 300);
  EXPECT_EQ(r.err.rfind("gearkit: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(part), std::string::npos) << r.err.substr(0, 300);
  EXPECT_LE(r.err.size(), max_length) << r.err.substr(0, 300);
}

fs::path write(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

}  // namespace

TEST(Messages, BrokenPluginsAreWarningsForCommandsAndErrorsForThePluginsCommand) {
  // A plugin folder with two broken plugins (and nothing else).
  const auto dir = gearkit::testing::scratch_dir("messages_plugins");
  for (const char* name : {"missing_symbol", "wrong_api"})
    std::filesystem::copy_file(kTestPlugins + "/test-" + name + ".so", dir / ("test-" + std::string(name) + ".so"));
  const std::string env = "GEARKIT_PLUGIN_PATH=" + shell_quote(dir.string());
  auto gear = run_gearkit("gear --z1 12 --z2 24 --module 3", env);
  EXPECT_EQ(gear.status, 0) << gear.err;
  auto warnings = lines_of(gear.err);
  ASSERT_EQ(warnings.size(), 2u) << gear.err;  // test-wrong_api.so and test-missing_symbol.so
  for (const auto& line : warnings) EXPECT_EQ(line.rfind("gearkit: warning: plugin '", 0), 0u) << line;

  auto listing = run_gearkit("plugins", env);
  EXPECT_EQ(listing.status, 2);
  auto lines = lines_of(listing.err);
  ASSERT_EQ(lines.size(), 2u) << listing.err;  // one per failure, the last one a reason
  EXPECT_NE(lines[0].find("test-missing_symbol.so': missing symbol"), std::string::npos) << listing.err;
  EXPECT_NE(lines[1].find("test-wrong_api.so': built for plugin API version"), std::string::npos) << listing.err;
  for (const auto& line : lines) EXPECT_EQ(line.rfind("gearkit: plugin '", 0), 0u) << line;
}

TEST(Messages, AHugeOrMultiLineBadValueIsQuotedShortOnOneLine) {
  auto dir = gearkit::testing::scratch_dir("messages_values");
  std::string cam = slurp(kExamples / "cams" / "translating_roller_cycloidal.yaml");
  std::string huge = cam;
  huge.replace(huge.find("lift: 20 mm"), 11, "lift: " + std::string(1 << 20, 'x'));
  expect_one_line_error(run_gearkit("cam " + shell_quote(write(dir / "huge.yaml", huge).string())), "xxx...");

  // A block scalar spans several lines of the file; the message shows it on one.
  std::string multi = "teeth: |\n  20\n  30\n  40\nmodule: 2 mm\n";
  expect_one_line_error(run_gearkit("train " + shell_quote(write(dir / "multi.yaml", multi).string())), "gearkit: ");
  std::string train = slurp(kExamples / "trains" / "simple_planetary.yaml");
  std::string bad_name = train + "\nextra_key: \"line one\\nline two\\nline three\"\n";
  expect_one_line_error(run_gearkit("train " + shell_quote(write(dir / "name.yaml", bad_name).string())), "extra_key");

  expect_one_line_error(run_gearkit("kin " + shell_quote((kExamples / "mechanisms" / "four_bar.yaml").string()) +
                                    " --at " + std::string(100000, '7') + "x"),
                        "option '--at'");
  expect_one_line_error(run_gearkit("gear --z1 " + std::string(100000, '1') + " --z2 20 --module 2"), "'--z1'");
}

TEST(Messages, OptionsAndArgumentsAreNamedAsTyped) {
  // otm2015_p4_flywheel asks no 'motion' question: there is no speed to plot.
  expect_one_line_error(run_gearkit("dyn " + shell_quote((kExamples / "dynamics" / "otm2015_p4_flywheel.yaml").string()) +
                                    " --speed-plot /dev/null"),
                        "option '--speed-plot'");
  expect_one_line_error(run_gearkit("cam"), "expected the FILE argument, found none");
  expect_one_line_error(run_gearkit("train"), "expected the FILE argument, found none");
  // One wording for a missing positional argument in every command (issue 12: dyn said "missing
  // the model file", synth "missing the task or its file").
  expect_one_line_error(run_gearkit("dyn"), "expected the FILE argument, found none");
  expect_one_line_error(run_gearkit("dyn --format json"), "expected the FILE argument, found none");
  expect_one_line_error(run_gearkit("synth"), "expected the TASK argument, found none");
  expect_one_line_error(run_gearkit("synth path"), "expected the FILE argument, found none");
  // Issue 11 item E: Boost's own wording leaked ("the argument ('x') for option ... is invalid").
  const std::string sp = shell_quote((kExamples / "trains" / "simple_planetary.yaml").string());
  expect_one_line_error(run_gearkit("train " + sp + " --mesh-efficiency x"),
                        "option '--mesh-efficiency': expected a number, found 'x'");
  expect_one_line_error(
      run_gearkit("synth path " + shell_quote((kExamples / "synthesis" / "path_ellipse.yaml").string()) +
                  " --evaluations 1e300"),
      "option '--evaluations': expected a whole number, found '1e300'");
  expect_one_line_error(run_gearkit("gear --z1 12 --z2 24 --module 3 --centre-distance 55 --center-distance 56"),
                        "option '--centre-distance': expected it once, found it 2 times");
  expect_one_line_error(run_gearkit("--frobnicate"), "option '--frobnicate': expected an option listed by --help");
  // Issue 11 item F: a bad --z1 was reported as a missing --z2.
  expect_one_line_error(run_gearkit("gear --z1 x"), "option '--z1': expected a whole number of teeth, found 'x'");
  expect_one_line_error(run_gearkit("gear --z1 12 --module 3"), "option '--z2': expected the teeth of gear 2 (or --ratio), found none");
  auto synth = run_gearkit("train synth gearbox --ratio 3");
  expect_one_line_error(synth, "train synth: expected 'reducer' or 'planetary'");
  EXPECT_EQ(synth.err.find("gearkit: gearkit"), std::string::npos) << synth.err;
  expect_one_line_error(run_gearkit("frobnicate"), "unknown command 'frobnicate'");
}

TEST(Messages, ASecondYamlDocumentIsAnErrorAtItsPosition) {
  auto dir = gearkit::testing::scratch_dir("messages_documents");
  std::string train = slurp(kExamples / "trains" / "simple_planetary.yaml");
  fs::path two = write(dir / "two.yaml", train + "---\nmembers: [x]\n");
  int line = count_lines(train) + 2;
  expect_one_line_error(run_gearkit("train " + shell_quote(two.string()) + " --fix ring --input sun=100rpm"),
                        two.string() + ":" + std::to_string(line) + ":");
  // An empty document after the end marker holds nothing to ignore.
  fs::path trailing = write(dir / "trailing.yaml", train + "---\n");
  auto ok = run_gearkit("train " + shell_quote(trailing.string()) + " --fix ring --input sun=100rpm");
  EXPECT_EQ(ok.status, 0) << ok.err;
}
