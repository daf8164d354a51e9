// The HTML report: one page, no script and no external resource, so it opens offline, can be
// mailed as one file and prints to PDF as it shows.
#include <gearkit/io/report_output.hpp>

#include <gearkit/io/version.hpp>
#include <gearkit/io/xml.hpp>

#include <fmt/format.h>

#include <cstdlib>
#include <ostream>

namespace gearkit::io {

namespace {

constexpr const char* kStyle = R"css(
body { font-family: "DejaVu Sans", Arial, sans-serif; font-size: 14px; color: #111; max-width: 70em; margin: 1.5em auto; padding: 0 1em; }
h1 { font-size: 1.5em; margin-bottom: 0.2em; }
h2 { font-size: 1.15em; margin: 1.4em 0 0.4em; }
p.meta { color: #555; margin-top: 0; }
table { border-collapse: collapse; margin: 0.3em 0 1em; }
th, td { border: 1px solid #bbb; padding: 0.2em 0.6em; vertical-align: top; }
th { background: #eef; text-align: left; }
td.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
ul.warnings li { color: #a00000; }
figure { margin: 1em 0; break-inside: avoid; }
figure svg { max-width: 100%; height: auto; border: 1px solid #ddd; }
figcaption { color: #555; font-size: 0.9em; }
pre { background: #f6f6f6; padding: 0.6em; overflow-x: auto; font-size: 0.85em; }
@media print { body { max-width: none; margin: 0; } details { display: block; } h2 { break-after: avoid; } table { break-inside: avoid; } }
)css";

bool numeric(const std::string& s) {
  if (s.empty()) return false;
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  return end && *end == '\0';
}

void table_html(const Table& t, std::size_t index, std::ostream& out) {
  out << fmt::format("<h2 id=\"{}\">{}</h2>\n<table>\n", table_key(t.title, index), xml_escape(t.title.empty() ? "Table" : t.title));
  if (!t.header.empty()) {
    out << "<thead><tr>";
    for (const auto& h : t.header) out << "<th>" << xml_escape(h) << "</th>";
    out << "</tr></thead>\n";
  }
  out << "<tbody>\n";
  for (const auto& row : t.rows) {
    out << "<tr>";
    for (const auto& cell : row) out << (numeric(cell) ? "<td class=\"num\">" : "<td>") << xml_escape(cell) << "</td>";
    out << "</tr>\n";
  }
  out << "</tbody>\n</table>\n";
}

// The SVG document without its XML declaration, ready to sit inside HTML.
std::string inline_svg(const std::string& svg) {
  const std::size_t start = svg.find("<svg");
  return start == std::string::npos ? std::string() : svg.substr(start);
}

void extras_html(const HtmlPage& page, const Report& report, std::ostream& out) {
  if (!page.pictures.empty()) out << "<h2>Pictures</h2>\n";
  for (const HtmlPicture& p : page.pictures)
    out << "<figure>\n" << inline_svg(p.svg) << "<figcaption>" << xml_escape(p.caption) << "</figcaption>\n</figure>\n";
  if (!page.inputs.empty()) {
    out << "<h2>Inputs</h2>\n<p>Every quantity carries its unit as written in the file (docs/units.md); table headers "
           "name the units of the results, JSON keys carry them as suffixes (d_mm, omega_rad_s).</p>\n";
  }
  for (const HtmlInput& in : page.inputs)
    out << "<details open>\n<summary>" << xml_escape(in.path) << "</summary>\n<pre>" << xml_escape(in.content)
        << "</pre>\n</details>\n";
  nlohmann::json j = report.json;
  j["warnings"] = report.warnings;
  out << "<h2>Data (JSON)</h2>\n<details>\n<summary>every result by key, units in the key names</summary>\n<pre>"
      << xml_escape(j.dump(2)) << "</pre>\n</details>\n";
}

}  // namespace

void render_html(const Report& report, const HtmlPage& page, std::ostream& out) {
  const std::string title = report.title.empty() ? std::string("gearkit report") : report.title;
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      << "<meta name=\"generator\" content=\"gearkit " << version() << "\">\n"
      << "<title>" << xml_escape(title) << "</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n";
  out << "<h1>" << xml_escape(title) << "</h1>\n<p class=\"meta\">gearkit " << version() << "</p>\n";
  out << "<h2 id=\"warnings\">Warnings</h2>\n";
  if (report.warnings.empty()) out << "<p>none</p>\n";
  else {
    out << "<ul class=\"warnings\">\n";
    for (const auto& w : report.warnings) out << "<li>" << xml_escape(w) << "</li>\n";
    out << "</ul>\n";
  }
  for (std::size_t i = 0; i < report.tables.size(); ++i) table_html(report.tables[i], i + 1, out);
  if (!report.notes.empty()) {
    out << "<h2>Notes</h2>\n";
    for (const auto& n : report.notes) out << "<p>" << xml_escape(n) << "</p>\n";
  }
  extras_html(page, report, out);
  out << "</body>\n</html>\n";
}

}  // namespace gearkit::io
