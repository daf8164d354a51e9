// Tests for gearkit/io/report.hpp: one report, four formats.
#include <gearkit/io/report.hpp>

#include <gearkit/io/error.hpp>

#include <gtest/gtest.h>

using namespace gearkit::io;

namespace {
Report sample() {
  Report r;
  r.title = "Pair";
  Table t{"Gear 1", {"quantity", "value"}, {}};
  t.add_row({"d [mm]", "36.000"});
  t.add_row({"note", "a, \"quoted\" | piped"});
  r.tables.push_back(t);
  r.warnings.push_back("undercut on gear 1");
  r.json = {{"d_mm", 36.0}};
  return r;
}
}  // namespace

TEST(Report, JsonCarriesWarnings) {
  auto j = nlohmann::json::parse(render(sample(), Format::json));
  EXPECT_DOUBLE_EQ(j["d_mm"].get<double>(), 36.0);
  ASSERT_EQ(j["warnings"].size(), 1u);
  EXPECT_EQ(j["warnings"][0], "undercut on gear 1");
}

TEST(Report, TextAlignsNumbersAndListsWarnings) {
  std::string s = render(sample(), Format::text);
  EXPECT_NE(s.find("Pair\n"), std::string::npos);
  EXPECT_NE(s.find("  d [mm]                 36.000\n"), std::string::npos) << s;  // numbers right-aligned
  EXPECT_NE(s.find("! undercut on gear 1"), std::string::npos);
}

TEST(Report, CsvQuotesCellsThatNeedIt) {
  std::string s = render(sample(), Format::csv);
  EXPECT_NE(s.find("quantity,value\n"), std::string::npos);
  EXPECT_NE(s.find("note,\"a, \"\"quoted\"\" | piped\"\n"), std::string::npos) << s;
  EXPECT_NE(s.find("# warning: undercut on gear 1"), std::string::npos);
}

TEST(Report, MarkdownEscapesPipes) {
  std::string s = render(sample(), Format::md);
  EXPECT_NE(s.find("| quantity | value |"), std::string::npos) << s;
  EXPECT_NE(s.find("\\| piped"), std::string::npos);
  EXPECT_NE(s.find("- undercut on gear 1"), std::string::npos);
}

TEST(Report, ParseFormat) {
  EXPECT_EQ(parse_format("json"), Format::json);
  EXPECT_EQ(parse_format("md"), Format::md);
  try {
    parse_format("xml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "option '--format': expected text, json, csv or md, found 'xml'");
  }
}

TEST(Report, FixedDropsNegativeZero) {
  EXPECT_EQ(fixed(-0.0001, 3), "0.000");
  EXPECT_EQ(fixed(-1.23456, 3), "-1.235");
  EXPECT_EQ(fixed(2.5, 0), "2");  // round half to even, as printf does
}
