// Tests for gearkit/io/report_stream.hpp: a report streamed row by row reads like the same
// report rendered whole by render() (report.hpp), in every format.
#include <gearkit/io/report_stream.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>

using namespace gearkit::io;

namespace {

struct Parts {
  Report head, tail, whole;
  Table table{"Sweep", {"x [mm]", "y [mm]"}, {}};
};

// The same report as head + streamed rows + tail, and rendered whole.
Parts sample(int rows) {
  Parts p;
  p.head.title = "Mechanism: test";
  p.head.notes.push_back("a note known before");
  p.head.json = {{"dof", 1}, {"mechanism", "test"}};
  p.tail.tables.push_back({"Dead points", {"input [deg]"}, {{"179.9"}}});
  p.tail.notes.push_back("a note known after");
  p.tail.warnings.push_back("dead point at 179.9 deg");
  p.tail.json = {{"dead_points", {179.9}}};
  p.whole.title = p.head.title;
  p.whole.notes = {"a note known before", "a note known after"};
  p.whole.warnings = p.tail.warnings;
  p.whole.json = {{"dof", 1}, {"mechanism", "test"}, {"dead_points", {179.9}}};
  Table t = p.table;
  nlohmann::json positions = nlohmann::json::array();
  for (int i = 0; i < rows; ++i) {
    t.add_row({fixed(i * 1.5, 4), fixed(-i * 100.0, 4)});
    positions.push_back({{"x_mm", i * 1.5}, {"y_mm", -i * 100.0}});
  }
  p.whole.tables = {t, p.tail.tables.front()};
  p.whole.json["positions"] = positions;
  return p;
}

std::string streamed(const Parts& p, int rows, Format format, std::vector<std::string>* warnings = nullptr) {
  std::ostringstream out;
  ReportStream s(out, format);
  s.begin(p.head, p.table, "positions");
  std::vector<std::string> cells;
  for (int i = 0; i < rows; ++i) {
    if (format == Format::json) {
      JsonWriter& w = s.begin_json_row();
      w.begin_object();
      w.key("x_mm");
      w.value(i * 1.5);
      w.key("y_mm");
      w.value(-i * 100.0);
      w.end_object();
      s.end_json_row();
    } else {
      s.add_cells({fixed(i * 1.5, 4), fixed(-i * 100.0, 4)});
    }
  }
  const auto w = s.finish(p.tail);
  if (warnings) *warnings = w;
  return out.str();
}

}  // namespace

// Text waits for 1000 rows to size its columns: below that, the same text as render().
TEST(ReportStream, TextMarkdownAndCsvReadLikeTheWholeReport) {
  for (int rows : {0, 1, 7, 999}) {
    const Parts p = sample(rows);
    EXPECT_EQ(streamed(p, rows, Format::text), render(p.whole, Format::text)) << rows << " rows";
    EXPECT_EQ(streamed(p, rows, Format::md), render(p.whole, Format::md)) << rows << " rows";
    EXPECT_EQ(streamed(p, rows, Format::csv), render(p.whole, Format::csv)) << rows << " rows";
  }
}

TEST(ReportStream, JsonIsOneDocumentWithTheSameContent) {
  for (int rows : {0, 1, 2500}) {
    const Parts p = sample(rows);
    const nlohmann::json got = nlohmann::json::parse(streamed(p, rows, Format::json));
    nlohmann::json expected = p.whole.json;
    expected["warnings"] = p.whole.warnings;
    EXPECT_EQ(got, expected) << rows << " rows";
  }
}

// Past the first 1000 rows, a text column keeps its width; a wider cell overflows it.
TEST(ReportStream, LongTextTablesKeepTheirColumns) {
  const Parts p = sample(1500);
  const std::string text = streamed(p, 1500, Format::text);
  // Columns sized by rows 0..999: 9 characters ("1498.5000") and 11 ("-99900.0000").
  EXPECT_NE(text.find("\n  0.0000          0.0000\n"), std::string::npos) << text.substr(0, 300);
  EXPECT_NE(text.find("\n  2248.5000  -149900.0000\n"), std::string::npos);  // row 1499 overflows by one
}

TEST(ReportStream, NonFiniteCellsAndValuesBecomeWarnings) {
  Parts p = sample(0);
  for (Format f : {Format::json, Format::csv}) {
    std::ostringstream out;
    ReportStream s(out, f);
    s.begin(p.head, p.table, "positions");
    if (f == Format::json) {
      JsonWriter& w = s.begin_json_row();
      w.begin_object();
      w.key("x_mm");
      w.value(NAN);
      w.end_object();
      s.end_json_row();
    } else {
      s.add_cells({"nan", "1.0"});
    }
    const std::vector<std::string> warnings = s.finish(p.tail);
    ASSERT_EQ(warnings.size(), 2u);
    EXPECT_NE(warnings[1].find(f == Format::json ? "'positions[].x_mm'" : "'x [mm]' in table 'Sweep'"), std::string::npos)
        << warnings[1];
  }
}
