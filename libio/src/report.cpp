#include <gearkit/io/report.hpp>

#include <gearkit/io/error.hpp>
#include <gearkit/io/report_output.hpp>

#include "table_text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <ostream>
#include <sstream>

namespace gearkit::io {

namespace detail {

namespace {

const std::string kEmpty;

// A number as strtod reads one, without its cost (text tables test every cell): sign, digits,
// point, digits, exponent; or inf/nan.
bool looks_numeric(const std::string& s) {
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
  if (s.compare(i, std::string::npos, "inf") == 0 || s.compare(i, std::string::npos, "nan") == 0) return true;
  bool digits = false;
  while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, digits = true;
  if (i < s.size() && s[i] == '.') ++i;
  while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, digits = true;
  if (!digits) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
    bool exponent = false;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, exponent = true;
    if (!exponent) return false;
  }
  return i == s.size();
}

void append_csv_cell(std::string& out, const std::string& s) {
  bool plain = true;
  for (const char c : s) plain = plain && c != ',' && c != '"' && c != '\n' && c != '\r';
  if (plain) {
    out += s;
    return;
  }
  out += '"';
  for (char c : s) {
    if (c == '"') out += "\"\"";
    else out += c;
  }
  out += '"';
}

}  // namespace

void widen(std::vector<std::size_t>& width, const std::vector<std::string>& row) {
  if (width.size() < row.size()) width.resize(row.size(), 0);
  for (std::size_t i = 0; i < row.size(); ++i) width[i] = std::max(width[i], glyphs(row[i]));
}

void text_line(std::string& s, const std::vector<std::string>& row, const std::vector<std::size_t>& width, bool header) {
  const std::size_t start = s.size();
  s += "  ";
  for (std::size_t i = 0; i < width.size(); ++i) {
    const std::string& cell = i < row.size() ? row[i] : kEmpty;
    const bool right = !header && i > 0 && looks_numeric(cell);
    const std::size_t w = glyphs(cell);
    if (right && w < width[i]) s.append(width[i] - w, ' ');
    s += cell;
    if (!right && w < width[i]) s.append(width[i] - w, ' ');
    if (i + 1 < width.size()) s += "  ";
  }
  while (s.size() > start && s.back() == ' ') s.pop_back();
  s += '\n';
}

void text_line(std::ostream& out, const std::vector<std::string>& row, const std::vector<std::size_t>& width, bool header) {
  std::string s;
  text_line(s, row, width, header);
  out << s;
}

void text_rule(std::ostream& out, const std::vector<std::size_t>& width) {
  std::string rule = "  ";
  for (std::size_t i = 0; i < width.size(); ++i) {
    rule += std::string(width[i], '-');
    if (i + 1 < width.size()) rule += "  ";
  }
  out << rule << "\n";
}

std::string md_escape(const std::string& s) {
  // Markdown passes HTML through: a name "<script>" would run in a rendered report. The entities
  // show the characters themselves; '|' would end a table cell.
  std::string r;
  for (char c : s) {
    if (c == '|') r += "\\|";
    else if (c == '<') r += "&lt;";
    else if (c == '>') r += "&gt;";
    else if (c == '&') r += "&amp;";
    else r += c;
  }
  return r;
}

void md_row(std::string& s, const std::vector<std::string>& row, std::size_t columns) {
  s += '|';
  for (std::size_t i = 0; i < columns; ++i) {
    s += ' ';
    s += md_escape(i < row.size() ? row[i] : kEmpty);
    s += " |";
  }
  s += '\n';
}

void md_row(std::ostream& out, const std::vector<std::string>& row, std::size_t columns) {
  std::string s;
  md_row(s, row, columns);
  out << s;
}

void md_table_head(std::ostream& out, const Table& t, std::size_t columns) {
  if (!t.title.empty()) out << "### " << md_escape(t.title) << "\n\n";
  md_row(out, t.header.empty() ? std::vector<std::string>(columns, "") : t.header, columns);
  out << "|";
  for (std::size_t i = 0; i < columns; ++i) out << (i == 0 ? " --- |" : " ---: |");
  out << "\n";
}

void csv_row(std::string& s, const std::vector<std::string>& row) {
  for (std::size_t i = 0; i < row.size(); ++i) {
    if (i) s += ',';
    append_csv_cell(s, row[i]);
  }
  s += '\n';
}

void csv_row(std::ostream& out, const std::vector<std::string>& row) {
  std::string s;
  csv_row(s, row);
  out << s;
}

bool non_finite_text(std::string_view cell) {
  std::size_t start = 0;
  while (start <= cell.size()) {
    std::size_t end = cell.find(' ', start);
    std::string_view token = cell.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
    if (!token.empty() && (token.front() == '-' || token.front() == '+')) token.remove_prefix(1);
    if (token == "nan" || token == "inf" || token == "NaN" || token == "Inf") return true;
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  return false;
}

void render_text_table(const Table& t, std::ostream& out) {
  if (!t.title.empty()) out << t.title << "\n";
  std::vector<std::size_t> width;
  detail::widen(width, t.header);
  for (const auto& r : t.rows) detail::widen(width, r);
  if (!t.header.empty()) {
    detail::text_line(out, t.header, width, true);
    detail::text_rule(out, width);
  }
  for (const auto& r : t.rows) detail::text_line(out, r, width, false);
}

void render_md_table(const Table& t, std::ostream& out) {
  std::size_t ncol = t.header.size();
  for (const auto& r : t.rows) ncol = std::max(ncol, r.size());
  if (ncol == 0) {
    if (!t.title.empty()) out << "### " << detail::md_escape(t.title) << "\n\n";
    return;
  }
  detail::md_table_head(out, t, ncol);
  for (const auto& r : t.rows) detail::md_row(out, r, ncol);
  out << "\n";
}

void render_csv_table(const Table& t, std::ostream& out) {
  if (!t.header.empty()) detail::csv_row(out, t.header);
  for (const auto& r : t.rows) detail::csv_row(out, r);
}

}  // namespace detail

Format parse_format(std::string_view s) {
  if (s == "text") return Format::text;
  if (s == "json") return Format::json;
  if (s == "csv") return Format::csv;
  if (s == "md" || s == "markdown") return Format::md;
  if (s == "html") return Format::html;
  fail_option("--format", fmt::format("expected text, json, csv, md or html, found {}", quote(s)));
}

void render(const Report& report, Format format, std::ostream& out) {
  switch (format) {
    case Format::json: {
      nlohmann::json j = report.json;
      j["warnings"] = report.warnings;
      out << j.dump(2) << "\n";
      return;
    }
    case Format::text: {
      if (!report.title.empty()) out << report.title << "\n\n";
      for (std::size_t i = 0; i < report.tables.size(); ++i) {
        detail::render_text_table(report.tables[i], out);
        out << "\n";
      }
      for (const auto& n : report.notes) out << n << "\n";
      if (!report.notes.empty()) out << "\n";
      if (report.warnings.empty()) {
        out << "Warnings: none\n";
      } else {
        out << "Warnings:\n";
        for (const auto& w : report.warnings) out << "  ! " << w << "\n";
      }
      return;
    }
    case Format::md: {
      if (!report.title.empty()) out << "## " << detail::md_escape(report.title) << "\n\n";
      for (const auto& t : report.tables) detail::render_md_table(t, out);
      for (const auto& n : report.notes) out << detail::md_escape(n) << "\n\n";
      out << "**Warnings:**" << (report.warnings.empty() ? " none\n" : "\n\n");
      for (const auto& w : report.warnings) out << "- " << detail::md_escape(w) << "\n";
      return;
    }
    case Format::html:
      render_html(report, {}, out);
      return;
    case Format::csv: {
      bool several = report.tables.size() > 1;
      for (std::size_t i = 0; i < report.tables.size(); ++i) {
        if (i) out << "\n";
        if (several && !report.tables[i].title.empty()) out << "# " << report.tables[i].title << "\n";
        detail::render_csv_table(report.tables[i], out);
      }
      for (const auto& w : report.warnings) out << "# warning: " << w << "\n";
      return;
    }
  }
}

std::string render(const Report& report, Format format) {
  std::ostringstream os;
  render(report, format, os);
  return os.str();
}

namespace {


// JSON paths of non-finite numbers, array indices written "[]" so that a column of a sweep
// is named once.
void non_finite_paths(const nlohmann::json& j, const std::string& path, std::vector<std::string>& out) {
  if (j.is_number_float() && !std::isfinite(j.get<double>())) {
    if (std::find(out.begin(), out.end(), path) == out.end()) out.push_back(path);
  } else if (j.is_object()) {
    for (const auto& [key, value] : j.items()) non_finite_paths(value, path.empty() ? key : path + "." + key, out);
  } else if (j.is_array()) {
    for (const auto& value : j) non_finite_paths(value, path + "[]", out);
  }
}

}  // namespace

namespace {

/// The name a note gives a non-finite number: the words before it back to the last ':' or '='
/// and the clause before that ("Driving force: nan N by ..." -> 'Driving force'), or "" if none.
std::string quantity_in_note(std::string_view note) {
  std::size_t start = 0;
  while (start <= note.size()) {
    std::size_t end = note.find(' ', start);
    std::string_view token = note.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
    if (detail::non_finite_text(token)) {
      std::string_view before = note.substr(0, start);
      while (!before.empty() && (before.back() == ' ' || before.back() == ':' || before.back() == '=')) before.remove_suffix(1);
      const std::size_t cut = before.find_last_of(",;.(");
      if (cut != std::string_view::npos) before.remove_prefix(cut + 1);
      while (!before.empty() && before.front() == ' ') before.remove_prefix(1);
      return quote(before.empty() ? note : before);
    }
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  return "";
}

}  // namespace

std::vector<std::string> non_finite_quantities(const Report& report) {
  std::vector<std::string> names;
  non_finite_paths(report.json, "", names);
  for (std::string& n : names) n = fmt::format("'{}'", n);
  // A note may carry a number too ("Driving force: nan N"): the text and Markdown reports show it.
  for (const std::string& note : report.notes) {
    const std::string quantity = quantity_in_note(note);
    if (quantity.empty()) continue;
    std::string name = quantity + " in a note";
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(std::move(name));
  }
  for (const Table& t : report.tables)
    for (const auto& row : t.rows)
      for (std::size_t c = 0; c < row.size(); ++c) {
        if (!detail::non_finite_text(row[c])) continue;
        std::string name = fmt::format("'{}' in table '{}'", c < t.header.size() ? t.header[c] : "?", t.title);
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
      }
  return names;
}

std::vector<std::string> non_finite_warnings(const std::vector<std::string>& names) {
  constexpr std::size_t kShown = 8;
  std::vector<std::string> warnings;
  for (std::size_t i = 0; i < names.size() && i < kShown; ++i)
    warnings.push_back(fmt::format("non-finite result: {} is not a finite number (nan or inf; null in JSON): "
                                   "the inputs put it out of range", names[i]));
  if (names.size() > kShown)
    warnings.push_back(fmt::format("non-finite result: {} more quantities are not finite", names.size() - kShown));
  return warnings;
}

void warn_non_finite(Report& report) {
  for (std::string& w : non_finite_warnings(non_finite_quantities(report))) report.warnings.push_back(std::move(w));
}

void append_fixed(std::string& out, double value, int digits) {
  if (std::isnan(value)) {
    out += "nan";
    return;
  }
  if (std::isinf(value)) {
    out += value > 0 ? "inf" : "-inf";
    return;
  }
  const std::size_t start = out.size();
  // Fast path: value * 10^digits rounded to an integer, exact unless the product lies within
  // its own rounding error of a half (a tie), where the correctly rounded text comes from
  // std::to_chars (Ryu printf) instead. A sweep formats millions of cells.
  static constexpr double kPow10[] = {1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8};
  const double scaled = digits >= 0 && digits <= 8 ? std::abs(value) * kPow10[digits] : INFINITY;
  const double whole = std::nearbyint(scaled);
  if (scaled < 1e15 && std::abs(std::abs(scaled - whole) - 0.5) > 1e-15 * scaled + 1e-9) {
    auto units = static_cast<unsigned long long>(whole);
    char text[32];
    char* p = text + sizeof text;
    for (int d = 0; d < digits; ++d, units /= 10) *--p = static_cast<char>('0' + units % 10);
    if (digits > 0) *--p = '.';
    do {
      *--p = static_cast<char>('0' + units % 10);
      units /= 10;
    } while (units != 0);
    if (value < 0 && whole != 0) *--p = '-';  // "-0.000" carries no information a reader can use
    out.append(p, text + sizeof text);
    return;
  }
  char text[400];
  const auto [end, ec] = std::to_chars(text, text + sizeof text, value, std::chars_format::fixed, digits);
  if (ec == std::errc()) out.append(text, end);
  else out += fmt::format("{:.{}f}", value, digits);
  if (out[start] == '-' && out.find_first_not_of("-0.", start) == std::string::npos) out.erase(start, 1);
}

nlohmann::json json_number(double value) {
  if (!std::isfinite(value)) return nullptr;
  if (value == 0) return 0.0;
  return std::strtod(fmt::format("{:.12g}", value).c_str(), nullptr);
}

void round_json_numbers(nlohmann::json& tree) {
  if (tree.is_number_float()) {
    const double v = tree.get<double>();
    if (std::isfinite(v)) tree = json_number(v);
    return;
  }
  if (tree.is_structured())
    for (auto& child : tree) round_json_numbers(child);
}

std::string fixed(double value, int digits) {
  std::string s;
  append_fixed(s, value, digits);
  return s;
}

}  // namespace gearkit::io
