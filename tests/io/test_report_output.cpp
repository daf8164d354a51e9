// Tests for gearkit/io/report_output.hpp: one table per CSV (--table), warnings moved to stderr
// for CSV, and the HTML page.
#include <gearkit/io/report_output.hpp>

#include <gearkit/io/error.hpp>

#include <gtest/gtest.h>

#include <sstream>

using namespace gearkit::io;

namespace {

Report two_tables() {
  Report r;
  r.title = "Gear <pair>";
  r.tables.push_back({"Speeds", {"member", "n [rpm]"}, {{"sun", "3000.0000"}, {"carrier", "857.1429"}}});
  r.tables.push_back({"Willis equations (one per mesh)", {"mesh", "equation"}, {{"s-p", "(w_p - w_c) / (w_s - w_c) = -24/18"}}});
  r.warnings.push_back("undercut on gear 1");
  r.notes.push_back("Ratio 2/7");
  r.json["ratio"] = 0.2857;
  return r;
}

CommonOptions options(Format f, std::string table = "") {
  CommonOptions o;
  o.format = f;
  o.table = std::move(table);
  return o;
}

std::string option_error(const Report& r, const CommonOptions& o) {
  std::ostringstream sink;
  OutputSet outputs(sink);
  try {
    render_for_output(r, o, outputs);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ReportOutput, TableKeysComeFromTitles) {
  EXPECT_EQ(table_key("Motion program", 1), "motion_program");
  EXPECT_EQ(table_key("Willis equations (one per mesh)", 2), "willis_equations_one_per_mesh");
  EXPECT_EQ(table_key("Torques: T [N*m]", 1), "torques_t_n_m");
  EXPECT_EQ(table_key("", 3), "table_3");
}

TEST(ReportOutput, SelectByKeyPrefixOrNumber) {
  const Report r = two_tables();
  EXPECT_EQ(select_table(r, "speeds").tables.at(0).title, "Speeds");
  EXPECT_EQ(select_table(r, "willis").tables.at(0).title, "Willis equations (one per mesh)");
  EXPECT_EQ(select_table(r, "2").tables.at(0).title, "Willis equations (one per mesh)");
  EXPECT_EQ(select_table(r, "all").tables.size(), 2u);
  try {
    select_table(r, "torques");
    FAIL();
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("option '--table'"), std::string::npos) << m;
    EXPECT_NE(m.find("speeds, willis_equations_one_per_mesh"), std::string::npos) << m;
  }
}

TEST(ReportOutput, CsvOfSeveralTablesNeedsTableAndNamesThem) {
  const std::string m = option_error(two_tables(), options(Format::csv));
  EXPECT_NE(m.find("option '--table'"), std::string::npos) << m;
  EXPECT_NE(m.find("speeds, willis_equations_one_per_mesh"), std::string::npos) << m;
  EXPECT_NE(option_error(two_tables(), options(Format::json, "speeds")).find("--table"), std::string::npos);
}

TEST(ReportOutput, OneCsvTableIsHeaderAndRowsOnlyAndItsWarningsGoToStderr) {
  std::ostringstream sink, err;
  OutputSet outputs(sink);
  const CommonOptions o = options(Format::csv, "speeds");
  const std::string csv = render_for_output(two_tables(), o, outputs);
  EXPECT_EQ(csv, "member,n [rpm]\nsun,3000.0000\ncarrier,857.1429\n");
  print_moved_warnings(two_tables(), o, err);
  EXPECT_EQ(err.str(), "gearkit: warning: undercut on gear 1\n");
  std::ostringstream none;
  print_moved_warnings(two_tables(), options(Format::text), none);
  EXPECT_EQ(none.str(), "");
}

TEST(ReportOutput, HtmlPageHoldsTablesPicturesInputsAndWarnings) {
  std::ostringstream out;
  HtmlPage page;
  page.pictures.push_back({"--svg a.svg", "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"><circle r=\"3\"/></svg>\n"});
  page.inputs.push_back({"model.yaml", "z: 24  # <teeth>\n"});
  render_html(two_tables(), page, out);
  const std::string html = out.str();
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("<title>Gear &lt;pair&gt;</title>"), std::string::npos);
  EXPECT_NE(html.find("<h2 id=\"speeds\">Speeds</h2>"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"num\">857.1429</td>"), std::string::npos);  // numbers right-aligned
  EXPECT_NE(html.find("<li>undercut on gear 1</li>"), std::string::npos);
  EXPECT_NE(html.find("<svg xmlns=\"http://www.w3.org/2000/svg\"><circle r=\"3\"/></svg>"), std::string::npos);
  EXPECT_EQ(html.find("<?xml"), std::string::npos);  // the SVG's declaration is dropped inside HTML
  EXPECT_NE(html.find("z: 24  # &lt;teeth&gt;"), std::string::npos);
  EXPECT_NE(html.find("&quot;ratio&quot;: 0.2857"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);  // self-contained, nothing to run or fetch
  EXPECT_EQ(html.find("http://"), html.find("http://www.w3.org/2000/svg"));
}
