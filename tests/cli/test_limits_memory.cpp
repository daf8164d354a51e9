// Issue 26, section 1: every documented limit of a model's size (docs/cli.md, "Limits") is run AT
// the limit under a 2 GiB address-space cap, where it must complete, and one past it, where it must
// be refused with status 2 and file:line:column of the first item beyond. Before, a 3 MB list of
// YAML took 478 MB, a 48 MB file 7.5 GB (out of memory under 2 GB), a cam table of 100,000 points
// over a minute, and an HTML page of a 100,000-position sweep 3 GB. Inputs are generated here.
// The expected lines and columns are where the generator put the first item beyond (counted by
// construction, not read from gearkit's output).
#include <run_gearkit.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fs = std::filesystem;
using gearkit::testing::count_lines;
using gearkit::testing::run_gearkit;
using gearkit::testing::shell_quote;

namespace {

// 2 GiB of address space (ulimit -v counts KiB): the cap of the acceptance.
const std::string kCap = "ulimit -v 2097152;";

#ifdef GEARKIT_SANITIZED
#define SKIP_UNDER_ASAN() GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: ulimit -v cannot apply"
#else
#define SKIP_UNDER_ASAN() (void)0
#endif

fs::path write(const std::string& name, const std::string& text) {
  static const fs::path dir = gearkit::testing::scratch_dir("limits-memory");
  std::ofstream(dir / name) << text;
  return dir / name;
}

std::string q(const fs::path& p) { return shell_quote(p.string()); }

/// Completed (status 0), with nothing on stderr but warning lines.
void expect_completed(const gearkit::testing::RunResult& r) {
  EXPECT_EQ(r.status, 0) << r.err;
  std::istringstream err(r.err);
  for (std::string line; std::getline(err, line);) EXPECT_EQ(line.rfind("gearkit: warning: ", 0), 0u) << line;
}

/// Status 2 and one stderr line: "gearkit: FILE:LINE:COLUMN: ..." holding `part`.
void expect_refused_at(const gearkit::testing::RunResult& r, const fs::path& file, int line, int column,
                       const std::string& part) {
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  const std::string where = "gearkit: " + file.string() + ":" + std::to_string(line) + ":" + std::to_string(column) + ": ";
  EXPECT_EQ(r.err.rfind(where, 0), 0u) << "expected at " << where << "\n" << r.err;
  EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
}

/// A mapping with one key whose value is a block list of `items` scalars: 3 + items nodes (the
/// mapping, the key, the list), item i (0-based) on line 2 + i, column 5 ("  - 1").
std::string junk_list(long items) {
  std::string text = "junk:\n";
  text.reserve(6 + 6 * static_cast<std::size_t>(items));
  for (long i = 0; i < items; ++i) text += "  - 1\n";
  return text;
}

}  // namespace

// 1,000,000 nodes are read (the mechanism reader then finds no links); the 1,000,001st, item
// 999,997 of the list on line 999,999, is refused before it is built.
TEST(LimitsMemory, YamlNodesAtTheLimitAreRead) {
  SKIP_UNDER_ASAN();
  const fs::path at = write("nodes_at.yaml", junk_list(1'000'000 - 3));
  const auto r = run_gearkit("kin " + q(at), kCap);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err.find("YAML nodes"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("'links'"), std::string::npos) << r.err;  // read through: the model lacks its links
}

TEST(LimitsMemory, YamlNodesBeyondTheLimitAreRefusedWhereTheyBegin) {
  SKIP_UNDER_ASAN();
  const fs::path beyond = write("nodes_beyond.yaml", junk_list(1'000'000 - 2));
  expect_refused_at(run_gearkit("kin " + q(beyond), kCap), beyond, 999'999, 5,
                    "expected a model of at most 1000000 YAML nodes");
  // The nodes of every document count: a second document cannot restart the count.
  const fs::path two = write("nodes_two.yaml", junk_list(600'000) + "---\n" + junk_list(600'000));
  // The first document has 600,003 nodes on lines 1 to 600,001, '---' is line 600,002; the
  // second's mapping is node 600,004, its list's item i node 600,007 + i on line 600,004 + i.
  // The 1,000,001st node is item 399,994.
  expect_refused_at(run_gearkit("kin " + q(two), kCap), two, 600'004 + 399'994, 5, "YAML nodes");
}

// The largest mechanism, a chain of 10,000 four-bar loops (20,001 links, 30,001 joints), is solved
// under the cap; a 20,002nd link and a 30,002nd joint are refused where they are written.
TEST(LimitsMemory, MechanismListsAtAndBeyondTheLimit) {
  SKIP_UNDER_ASAN();
  const fs::path chain = write("chain.yaml", run_gearkit("kin --example chain:10000").out);
  expect_completed(run_gearkit("kin " + q(chain), kCap, "/dev/null", "/dev/null"));

  std::string links = "links:\n";
  for (int i = 0; i < 20'002; ++i) links += "  l" + std::to_string(i) + ": {points: {A: [0, 0]}}\n";
  const fs::path many_links = write("links.yaml", links);
  expect_refused_at(run_gearkit("kin " + q(many_links), kCap), many_links, 20'003, 3, "expected at most 20001 links");

  std::string joints = "links:\n  a: {points: {A: [0, 0]}}\njoints:\n";
  for (int i = 0; i < 30'002; ++i) joints += "  - {type: revolute, at: [a.A, ground.O]}\n";
  const fs::path many_joints = write("joints.yaml", joints);
  expect_refused_at(run_gearkit("kin " + q(many_joints), kCap), many_joints, 4 + 30'001, 5,
                    "expected at most 30001 joints");
}

namespace {

// A knife-edge cam whose rise over 0..150 deg is the table of `points` (one per line, the first
// on line 14, column 9), then the rest of examples/cams/offset_knife_table.yaml's program.
std::string cam_with_table(int points) {
  std::ostringstream text;
  text << "name: big table\ncam:\n  base_radius: 35 mm\n  rotation: ccw\nfollower:\n  type: translating\n"
          "  contact: knife_edge\n  offset: 5 mm\nmotion:\n  - type: table\n    from: 0 deg\n    to: 150 deg\n"
          "    points:\n";
  text.precision(12);
  for (int i = 0; i < points; ++i) {
    const double u = static_cast<double>(i) / (points - 1);
    text << "      - [" << 150.0 * u << " deg, " << 8.0 * (1.0 - std::cos(M_PI * u)) << " mm]\n";
  }
  text << "  - {type: dwell, from: 150 deg, to: 210 deg}\n"
          "  - {type: return, from: 210 deg, to: 330 deg, law: modified_sine, lift: 16 mm}\n"
          "  - {type: dwell, from: 330 deg, to: 360 deg}\n";
  return text.str();
}

}  // namespace

TEST(LimitsMemory, CamTablesAtAndBeyondTheLimit) {
  SKIP_UNDER_ASAN();
  const fs::path at = write("cam_at.yaml", cam_with_table(10'000));
  expect_completed(run_gearkit("cam " + q(at), kCap, "/dev/null", "/dev/null"));
  const fs::path beyond = write("cam_beyond.yaml", cam_with_table(10'001));
  expect_refused_at(run_gearkit("cam " + q(beyond), kCap), beyond, 14 + 10'000, 9, "expected at most 10000 points");

  // 1,000 segments of 0.36 deg are read; the 1,001st of a program is refused.
  auto program = [](int segments) {
    std::string text = "cam: {base_radius: 35 mm}\nfollower: {type: translating, contact: knife_edge}\nmotion:\n";
    for (int i = 0; i < segments; ++i)
      text += "  - {type: dwell, from: " + std::to_string(0.36 * i) + " deg, to: " + std::to_string(0.36 * (i + 1)) +
              " deg}\n";
    return text;
  };
  const fs::path segments_at = write("segments_at.yaml", program(1000));
  expect_completed(run_gearkit("cam " + q(segments_at), kCap, "/dev/null", "/dev/null"));
  const fs::path segments_beyond = write("segments_beyond.yaml", program(1001));
  expect_refused_at(run_gearkit("cam " + q(segments_beyond), kCap), segments_beyond, 4 + 1000, 5,
                    "expected at most 1000 segments");
}

namespace {

// examples/dynamics/crank_press_linkage.yaml with tables of `rows` rows over 0..360 deg: the
// inertia table's first row on line 24, column 7, the torque table's on line 26 + rows, column 9.
std::string dyn_with_tables(int rows, int torque_rows) {
  std::ostringstream text;
  text.precision(10);
  text << "title: press\nmotor:\n  speed: 1450 rpm\n  efficiency: 0.9\n  inertia: 0.004 kg*m^2\n  torque:\n"
          "    expression: \"min(25, Tn*(50*_pi - omega)/(50*_pi - wn))\"\n    parameters: {Tn: 8.5, wn: 151.8436}\n"
          "stages:\n  - name: reducer\n    ratio: 1/10\n    efficiency: 0.95\n"
          "flywheel:\n  cycle: 360 deg\n  fluctuation: 2 %\n  drive: {constant: 1 N*m, scale: balance}\n"
          "motion: {speed: 1450 rpm, with_flywheel: true, t_end: 120 s, output_step: 10 ms}\n"
          "load:\n  name: crank\n";
  // 19 lines so far; four more before the first inertia row.
  text << "  # the slider-crank's reduced inertia and the press force, tabulated\n  #\n  #\n  inertia_table:\n";
  for (int i = 0; i < rows; ++i) {
    const double a = 360.0 * i / (rows - 1);
    text << "    - [" << a << " deg, " << 0.05 + 0.1 * std::pow(std::sin(a * M_PI / 180), 2) << " kg*m^2]\n";
  }
  text << "  resisting:\n    table:\n";
  for (int i = 0; i < torque_rows; ++i) {
    const double a = 360.0 * i / (torque_rows - 1);
    text << "      - [" << a << " deg, " << 100 * std::abs(std::sin(a * M_PI / 180)) << " N*m]\n";
  }
  return text.str();
}

}  // namespace

TEST(LimitsMemory, DynTablesAtAndBeyondTheLimit) {
  SKIP_UNDER_ASAN();
  const fs::path at = write("dyn_at.yaml", dyn_with_tables(36'001, 36'001));
  expect_completed(run_gearkit("dyn " + q(at), kCap, "/dev/null", "/dev/null"));
  const fs::path inertia = write("dyn_inertia.yaml", dyn_with_tables(36'002, 2));
  expect_refused_at(run_gearkit("dyn " + q(inertia), kCap), inertia, 24 + 36'001, 7, "expected at most 36001 rows");
  const fs::path torque = write("dyn_torque.yaml", dyn_with_tables(2, 36'002));
  expect_refused_at(run_gearkit("dyn " + q(torque), kCap), torque, 28 + 36'001, 9, "expected at most 36001 rows");
}

// A sweep of 100,000 positions as an HTML page: 2,000 rows, one position in 50 (inputs 0, 0.18,
// 0.36 ... deg: 50 x 0.0036), with a note; 1,000,000 positions under the cap (14.5 GB before).
TEST(LimitsMemory, HtmlSweepsShowAtMostTwoThousandPositions) {
  SKIP_UNDER_ASAN();
  const std::string four_bar = shell_quote(std::string(GEARKIT_SOURCE_DIR) + "/examples/mechanisms/four_bar.yaml");
  const fs::path page = fs::path(gearkit::testing::scratch_dir("limits-memory-html")) / "sweep.html";
  const auto r = run_gearkit("kin " + four_bar + " --sweep 0:359.9964:0.0036 --format html -o " + q(page), kCap);
  expect_completed(r);
  const std::string html = gearkit::testing::slurp(page);
  EXPECT_LT(html.size(), 20u << 20);  // 386 MB before
  EXPECT_NE(html.find("one position in 50 (2000 of the 100000 positions swept"), std::string::npos);
  const std::size_t table = html.find("<h2 id=\"sweep\">");
  ASSERT_NE(table, std::string::npos);
  const std::size_t end = html.find("</table>", table);
  long rows = 0;
  for (std::size_t at = html.find("<tr><td", table); at < end; at = html.find("<tr><td", at + 1)) ++rows;
  EXPECT_EQ(rows, 2000);
  EXPECT_NE(html.find("<tr><td class=\"num\">0.1800</td>", table), std::string::npos);  // the 51st position

  const auto million = run_gearkit("kin " + four_bar + " --sweep 0:359.99964:0.00036 --format html -o " + q(page), kCap);
  expect_completed(million);
  EXPECT_NE(gearkit::testing::slurp(page).find("one position in 500 (2000 of the 1000000"), std::string::npos);
}

// A CSV of a table other than the positions (here the extremes) of a million-position sweep: the
// positions are not kept for a table that is not written (they were, past 2 GiB).
TEST(LimitsMemory, CsvOfAnotherTableKeepsNoPositions) {
  SKIP_UNDER_ASAN();
  const std::string four_bar = shell_quote(std::string(GEARKIT_SOURCE_DIR) + "/examples/mechanisms/four_bar.yaml");
  const auto r = run_gearkit("kin " + four_bar + " --sweep 0:359.99964:0.00036 --format csv --table 2", kCap);
  expect_completed(r);
  EXPECT_LT(count_lines(r.out), 100) << "the extremes of three outputs, not the positions";
  EXPECT_GT(count_lines(r.out), 1);
}
