#include <gearkit/io/report.hpp>

#include <gearkit/io/error.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ostream>
#include <sstream>

namespace gearkit::io {

namespace {

// Display width of a UTF-8 string (counts code points, which is right for the symbols used:
// °, α, ε, µ).
std::size_t display_width(std::string_view s) {
  std::size_t w = 0;
  for (unsigned char c : s)
    if ((c & 0xC0) != 0x80) ++w;
  return w;
}

std::string pad(const std::string& s, std::size_t width, bool right) {
  std::size_t w = display_width(s);
  if (w >= width) return s;
  std::string fill(width - w, ' ');
  return right ? fill + s : s + fill;
}

bool looks_numeric(const std::string& s) {
  if (s.empty()) return false;
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  return end && *end == '\0';
}

void render_text_table(const Table& t, std::ostream& out) {
  if (!t.title.empty()) out << t.title << "\n";
  std::size_t ncol = t.header.size();
  for (const auto& r : t.rows) ncol = std::max(ncol, r.size());
  std::vector<std::size_t> width(ncol, 0);
  auto measure = [&](const std::vector<std::string>& r) {
    for (std::size_t i = 0; i < r.size(); ++i) width[i] = std::max(width[i], display_width(r[i]));
  };
  measure(t.header);
  for (const auto& r : t.rows) measure(r);
  auto line = [&](const std::vector<std::string>& r, bool header) {
    std::string s = "  ";
    for (std::size_t i = 0; i < ncol; ++i) {
      std::string cell = i < r.size() ? r[i] : "";
      bool right = !header && i > 0 && looks_numeric(cell);
      s += pad(cell, width[i], right);
      if (i + 1 < ncol) s += "  ";
    }
    while (!s.empty() && s.back() == ' ') s.pop_back();
    out << s << "\n";
  };
  if (!t.header.empty()) {
    line(t.header, true);
    std::string rule = "  ";
    for (std::size_t i = 0; i < ncol; ++i) {
      rule += std::string(width[i], '-');
      if (i + 1 < ncol) rule += "  ";
    }
    out << rule << "\n";
  }
  for (const auto& r : t.rows) line(r, false);
}

std::string md_escape(const std::string& s) {
  std::string r;
  for (char c : s) {
    if (c == '|') r += "\\|";
    else r += c;
  }
  return r;
}

void render_md_table(const Table& t, std::ostream& out) {
  if (!t.title.empty()) out << "### " << md_escape(t.title) << "\n\n";
  std::size_t ncol = t.header.size();
  for (const auto& r : t.rows) ncol = std::max(ncol, r.size());
  if (ncol == 0) return;
  auto row = [&](const std::vector<std::string>& r) {
    out << "|";
    for (std::size_t i = 0; i < ncol; ++i) out << " " << md_escape(i < r.size() ? r[i] : "") << " |";
    out << "\n";
  };
  row(t.header.empty() ? std::vector<std::string>(ncol, "") : t.header);
  out << "|";
  for (std::size_t i = 0; i < ncol; ++i) out << (i == 0 ? " --- |" : " ---: |");
  out << "\n";
  for (const auto& r : t.rows) row(r);
  out << "\n";
}

std::string csv_cell(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string r = "\"";
  for (char c : s) {
    if (c == '"') r += "\"\"";
    else r += c;
  }
  return r + "\"";
}

void render_csv_table(const Table& t, std::ostream& out) {
  auto row = [&](const std::vector<std::string>& r) {
    for (std::size_t i = 0; i < r.size(); ++i) out << (i ? "," : "") << csv_cell(r[i]);
    out << "\n";
  };
  if (!t.header.empty()) row(t.header);
  for (const auto& r : t.rows) row(r);
}

}  // namespace

Format parse_format(std::string_view s) {
  if (s == "text") return Format::text;
  if (s == "json") return Format::json;
  if (s == "csv") return Format::csv;
  if (s == "md" || s == "markdown") return Format::md;
  fail_option("--format", fmt::format("expected text, json, csv or md, found {}", quote(s)));
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
        render_text_table(report.tables[i], out);
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
      if (!report.title.empty()) out << "## " << md_escape(report.title) << "\n\n";
      for (const auto& t : report.tables) render_md_table(t, out);
      for (const auto& n : report.notes) out << n << "\n\n";
      out << "**Warnings:**" << (report.warnings.empty() ? " none\n" : "\n\n");
      for (const auto& w : report.warnings) out << "- " << md_escape(w) << "\n";
      return;
    }
    case Format::csv: {
      bool several = report.tables.size() > 1;
      for (std::size_t i = 0; i < report.tables.size(); ++i) {
        if (i) out << "\n";
        if (several && !report.tables[i].title.empty()) out << "# " << report.tables[i].title << "\n";
        render_csv_table(report.tables[i], out);
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

std::vector<std::string> non_finite_quantities(const Report& report) {
  std::vector<std::string> names;
  non_finite_paths(report.json, "", names);
  for (std::string& n : names) n = fmt::format("'{}'", n);
  for (const Table& t : report.tables)
    for (const auto& row : t.rows)
      for (std::size_t c = 0; c < row.size(); ++c) {
        if (!non_finite_text(row[c])) continue;
        std::string name = fmt::format("'{}' in table '{}'", c < t.header.size() ? t.header[c] : "?", t.title);
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
      }
  return names;
}

void warn_non_finite(Report& report) {
  const std::vector<std::string> names = non_finite_quantities(report);
  constexpr std::size_t kShown = 8;
  for (std::size_t i = 0; i < names.size() && i < kShown; ++i)
    report.warnings.push_back(fmt::format("non-finite result: {} is not a finite number (nan or inf; null in JSON): "
                                          "the inputs put it out of range", names[i]));
  if (names.size() > kShown)
    report.warnings.push_back(fmt::format("non-finite result: {} more quantities are not finite", names.size() - kShown));
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
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  std::string s = fmt::format("{:.{}f}", value, digits);
  // "-0.000" carries no information a reader can use.
  if (s.front() == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

}  // namespace gearkit::io
