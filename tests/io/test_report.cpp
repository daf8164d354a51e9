// Tests for gearkit/io/report.hpp: one report, four formats.
#include <gearkit/io/report.hpp>

#include <gearkit/io/error.hpp>

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <limits>

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

// Issue 26, section 3: Markdown renders inline HTML, so a name "<script>" in a title, a cell, a
// note or a warning must reach the page as text (CommonMark 0.30, section 6.6 "Raw HTML"; the
// entities &lt; &gt; &amp; render as the characters themselves, section 2.5).
TEST(Report, MarkdownEscapesHtmlInEveryPart) {
  Report r;
  r.title = "<script>alert(1)</script>";
  Table t{"<b>gears</b>", {"name", "value"}, {}};
  t.add_row({"<img src=x onerror=y>", "1 & 2"});
  r.tables.push_back(t);
  r.notes.push_back("link <a href=x>");
  r.warnings.push_back("gear '<script>' undercut");
  const std::string s = render(r, Format::md);
  EXPECT_EQ(s.find('<'), std::string::npos) << s;
  EXPECT_EQ(s.find('>'), std::string::npos) << s;
  EXPECT_NE(s.find("## &lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos) << s;
  EXPECT_NE(s.find("| &lt;img src=x onerror=y&gt; | 1 &amp; 2 |"), std::string::npos) << s;
  EXPECT_NE(s.find("link &lt;a href=x&gt;"), std::string::npos) << s;
  EXPECT_NE(s.find("- gear '&lt;script&gt;' undercut"), std::string::npos) << s;
}

TEST(Report, ParseFormat) {
  EXPECT_EQ(parse_format("json"), Format::json);
  EXPECT_EQ(parse_format("md"), Format::md);
  try {
    parse_format("xml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "option '--format': expected text, json, csv, md or html, found 'xml'");
  }
}

TEST(Report, FixedDropsNegativeZero) {
  EXPECT_EQ(fixed(-0.0001, 3), "0.000");
  EXPECT_EQ(fixed(-1.23456, 3), "-1.235");
  EXPECT_EQ(fixed(2.5, 0), "2");  // round half to even, as printf does
}

// Issue 11 item 10: a non-finite number in a report is never silent. JSON keeps it as null (the
// only JSON for it) and a warning names each quantity once, however many rows hold it.
TEST(Report, JsonNumbersDropConversionNoise) {
  // 0.01766 m written in mm and 30 deg through radians: the last bits are conversion noise.
  EXPECT_EQ(json_number(0.01766 * 1000).dump(), "17.66");
  EXPECT_EQ(json_number(30 * (M_PI / 180) * (180 / M_PI)).dump(), "30.0");
  EXPECT_TRUE(json_number(std::nan("")).is_null());
  nlohmann::json tree = {{"a_mm", 0.01766 * 1000}, {"list", {0.1 + 0.2, 7, "text"}}, {"nested", {{"b", 1.0 / 3}}}};
  round_json_numbers(tree);
  EXPECT_EQ(tree["a_mm"].dump(), "17.66");
  EXPECT_EQ(tree["list"].dump(), R"([0.3,7,"text"])");
  EXPECT_EQ(tree["nested"]["b"].dump(), "0.333333333333");
}

TEST(Report, NonFiniteResultsAreNamedInAWarning) {
  Report r = sample();
  r.json["ratio"] = std::numeric_limits<double>::infinity();
  r.json["stages"] = nlohmann::json::array({{{"n_rpm", 1.0}}, {{"n_rpm", std::nan("")}}, {{"n_rpm", std::nan("")}}});
  Table shafts{"Shafts", {"shaft", "n [rpm]"}, {}};
  shafts.add_row({"motor", "1440.00"});
  shafts.add_row({"drum", fixed(std::nan(""), 2)});
  shafts.add_row({"cutter", fixed(-std::numeric_limits<double>::infinity(), 2)});
  r.tables.push_back(shafts);
  const std::vector<std::string> names = non_finite_quantities(r);
  EXPECT_EQ(names, (std::vector<std::string>{"'ratio'", "'stages[].n_rpm'", "'n [rpm]' in table 'Shafts'"}));
  warn_non_finite(r);
  ASSERT_EQ(r.warnings.size(), 4u);  // "undercut on gear 1" and three named quantities
  EXPECT_EQ(r.warnings[1].rfind("non-finite result: 'ratio' is not a finite number", 0), 0u) << r.warnings[1];
  EXPECT_TRUE(non_finite_quantities(sample()).empty());  // "36.000" and words like "info" are fine
}

// fixed() takes a fast integer path where value * 10^digits is unambiguous and falls back to
// std::to_chars near ties: either way the text must be the correctly rounded one, which fmt's
// "{:.Nf}" gives (an independent implementation: Dragon4/Grisu with exact fallback).
TEST(Report, FixedIsCorrectlyRoundedEverywhere) {
  std::uint64_t state = 12345;
  const auto next = [&state] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / static_cast<double>(1ULL << 53);
  };
  for (int i = 0; i < 200000; ++i) {
    const double magnitude = std::pow(10.0, 12.0 * next() - 6.0);
    const double v = (next() < 0.5 ? -1 : 1) * magnitude * next();
    const int digits = i % 7;
    std::string expected = fmt::format("{:.{}f}", v, digits);
    if (expected.front() == '-' && expected.find_first_not_of("-0.") == std::string::npos) expected.erase(0, 1);
    ASSERT_EQ(fixed(v, digits), expected) << v << " with " << digits << " digits";
  }
  // Exact binary ties round to even (0.125 is exact: 0.12), near-ties go the right way.
  EXPECT_EQ(fixed(0.125, 2), "0.12");
  EXPECT_EQ(fixed(0.375, 2), "0.38");
  EXPECT_EQ(fixed(2.5, 0), "2");
  EXPECT_EQ(fixed(1.005, 2), "1.00");  // 1.005 is 1.00499999999999989... in binary
  EXPECT_EQ(fixed(-0.00001, 4), "0.0000");
  EXPECT_EQ(fixed(-1.5, 4), "-1.5000");
  EXPECT_EQ(fixed(1e20, 2), "100000000000000000000.00");
  EXPECT_EQ(fixed(NAN, 3), "nan");
  EXPECT_EQ(fixed(-INFINITY, 3), "-inf");
}
