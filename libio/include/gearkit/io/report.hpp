#pragma once
// One result, many formats: a command fills a Report (titled tables + warnings + a JSON object)
// and render() prints it as text, JSON, CSV or Markdown.
#include <nlohmann/json.hpp>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace gearkit::io {

enum class Format { text, json, csv, md, html };

/// "text" | "json" | "csv" | "md" | "html". @throws InputError naming option --format otherwise.
Format parse_format(std::string_view s);

/// A table of already-formatted cells. Units belong in the header ("d_a [mm]").
struct Table {
  std::string title;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  void add_row(std::vector<std::string> row) { rows.push_back(std::move(row)); }
};

struct Report {
  std::string title;                  ///< first line of text/md output
  std::vector<Table> tables;
  std::vector<std::string> notes;     ///< informative lines (text/md only)
  std::vector<std::string> warnings;  ///< engineering problems; also json["warnings"]
  nlohmann::json json = nlohmann::json::object();  ///< keys carry unit suffixes (d_mm, omega_rad_s)
};

/// Renders the report. JSON output is `json` with "warnings" added. CSV writes each table
/// (header row first) separated by a blank line, prefixed by "# title" comment lines.
void render(const Report& report, Format format, std::ostream& out);
std::string render(const Report& report, Format format);

/// The quantities of a report that are not finite numbers, each named once: JSON keys as paths
/// ("'stages[].ratio'", indices as []) and table cells reading nan/inf ("'n [rpm]' in table
/// 'Shafts'").
std::vector<std::string> non_finite_quantities(const Report& report);

/// The warnings naming non-finite quantities (at most eight by name, then a count).
std::vector<std::string> non_finite_warnings(const std::vector<std::string>& names);

/// Adds a warning naming each non-finite quantity (docs/cli.md: a non-finite result is never
/// silent). emit() calls it on every report, so a command need not.
void warn_non_finite(Report& report);

/// A JSON number rounded to 12 significant digits: a value converted between units (m -> mm,
/// rad -> deg) carries noise in its last bits (30 deg comes back as 29.999999999999996, 17.66 mm
/// as 17.660000000000004) that no input can justify; null for a non-finite value.
nlohmann::json json_number(double value);

/// json_number applied to every floating-point number of a JSON tree (integers, strings and
/// non-finite values are left as they are).
void round_json_numbers(nlohmann::json& tree);

/// Fixed-point formatting with `digits` decimals, correctly rounded; "-0.000" prints as "0.000".
std::string fixed(double value, int digits);
/// The same, appended to `out`.
void append_fixed(std::string& out, double value, int digits);

}  // namespace gearkit::io
