// --table selection, CSV warnings moved to stderr, and the HTML report's extras.
#include <gearkit/io/report_output.hpp>

#include <gearkit/io/error.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <optional>
#include <ostream>
#include <sstream>

namespace gearkit::io {

namespace {

std::string keys(const Report& report) {
  std::vector<std::string> k;
  for (std::size_t i = 0; i < report.tables.size(); ++i) k.push_back(table_key(report.tables[i].title, i + 1));
  return fmt::format("{}", fmt::join(k, ", "));
}

bool is_number(const std::string& s) {
  return !s.empty() && s.size() < 6 && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// The text of a file read by the run, up to 1 MB (model files are far smaller).
std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string text(1 << 20, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return text;
}

}  // namespace

std::string table_key(const std::string& title, std::size_t index) {
  std::string key;
  for (unsigned char c : title) {
    const bool word = (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || (c >= 'A' && c <= 'Z');
    if (word) key += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    else if (!key.empty() && key.back() != '_') key += '_';
  }
  while (!key.empty() && key.back() == '_') key.pop_back();
  return key.empty() ? fmt::format("table_{}", index) : key;
}

namespace {

// The index of the table `name` selects (see select_table).
std::size_t selected_index(const Report& report, const std::string& name) {
  std::vector<std::size_t> hits;
  for (std::size_t i = 0; i < report.tables.size(); ++i) {
    const std::string key = table_key(report.tables[i].title, i + 1);
    if (key == name) {
      hits = {i};
      break;
    }
    if (key.rfind(name, 0) == 0) hits.push_back(i);
  }
  if (hits.empty() && is_number(name) && std::stoul(name) >= 1 && std::stoul(name) <= report.tables.size())
    hits = {std::stoul(name) - 1};
  if (hits.size() != 1)
    fail_option("--table", fmt::format("expected one of the report's tables ({}), a unique prefix, a number from 1 to {} "
                                       "or 'all', found {}{}",
                                       keys(report), report.tables.size(), quote(name),
                                       hits.empty() ? "" : fmt::format(" ({} match)", hits.size())));
  return hits.front();
}

std::vector<Table> select_table_index_copy(const Report& report, const std::string& name) {
  if (name.empty()) return report.tables;  // one table (checked by the caller) or none
  return {report.tables[selected_index(report, name)]};
}

}  // namespace

Report select_table(const Report& report, const std::string& name) {
  if (name.empty() || name == "all") return report;
  Report one = report;
  one.tables = {report.tables[selected_index(report, name)]};
  return one;
}

std::string render_for_output(const Report& report, const CommonOptions& options, const OutputSet& outputs) {
  if (options.format == Format::json && !options.table.empty())
    fail_option("--table", "expected --format csv, text, md or html (JSON holds every table's data by key)");
  if (options.format == Format::csv && options.table.empty() && report.tables.size() > 1)
    fail_option("--table", fmt::format("csv writes one table per file: choose it with --table NAME (this report has {}: "
                                       "{}), or --table all for every table with '# title' lines",
                                       report.tables.size(), keys(report)));
  // Copies only where something changes: a sweep's report can be most of the memory of a run.
  if (options.format != Format::csv && options.format != Format::html && options.table.empty())
    return render(report, options.format);
  if (options.format == Format::csv && options.table == "all") return render(report, options.format);
  if (options.format == Format::csv) {
    Report view;  // the one table, no JSON, warnings left for stderr
    view.tables = select_table_index_copy(report, options.table);
    return render(view, options.format);
  }
  if (options.format != Format::html) return render(select_table(report, options.table), options.format);
  std::optional<Report> chosen;
  if (!options.table.empty()) chosen = select_table(report, options.table);
  const Report& selected = chosen ? *chosen : report;
  HtmlPage page;
  for (const OutputSet::Picture& p : outputs.pictures()) page.pictures.push_back({p.option + " " + p.path, p.svg});
  for (const std::string& path : input_files()) page.inputs.push_back({path, file_text(path)});
  std::ostringstream out;
  render_html(selected, page, out);
  return out.str();
}

void print_moved_warnings(const Report& report, const CommonOptions& options, std::ostream& err) {
  if (options.format != Format::csv || options.table == "all") return;
  for (std::string w : report.warnings) {
    std::replace(w.begin(), w.end(), '\n', ' ');
    if (w.size() > 560) w = w.substr(0, 556) + " ...";
    err << "gearkit: warning: " << w << "\n";
  }
}

}  // namespace gearkit::io
