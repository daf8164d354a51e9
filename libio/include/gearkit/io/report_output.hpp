#pragma once
// What emit() writes beyond render(): one table per CSV file (--table NAME), and the HTML page
// (--format html) with the run's pictures inline and its input files. docs/cli.md ("Tables and
// formats") states the rules for users.
#include <gearkit/io/command_line.hpp>
#include <gearkit/io/output.hpp>
#include <gearkit/io/report.hpp>

#include <iosfwd>
#include <string>
#include <vector>

namespace gearkit::io {

/// A table's name for --table: its title in lower case, each run of characters other than ASCII
/// letters and digits one '_', none at either end ("Motion program" -> "motion_program",
/// "Willis equations (one per mesh)" -> "willis_equations_one_per_mesh"); "table_N" for an
/// untitled N-th table (1-based).
std::string table_key(const std::string& title, std::size_t index);

/// The report with only the table `name` names: its key, a prefix of exactly one key, or its
/// number (1 = first). "" and "all" keep every table.
/// @throws InputError naming --table when no table or several match, listing the keys.
Report select_table(const Report& report, const std::string& name);

/// The report as the options ask: --table applied; csv of a report with several tables and no
/// --table is refused (InputError naming --table and listing the tables), and one table is written
/// alone, header first, its warnings left to print_moved_warnings(); html gets the SVG pictures
/// among `outputs` inline and the input files (io::input_files()).
/// @throws InputError for --table with --format json, or as select_table().
std::string render_for_output(const Report& report, const CommonOptions& options, const OutputSet& outputs);

/// With --format csv of one table: the report's warnings as "gearkit: warning: ..." lines on
/// `err`, one line each (a CSV file loads into a spreadsheet or pandas only if it holds its table
/// and nothing else). Nothing for the other formats, whose output carries them.
void print_moved_warnings(const Report& report, const CommonOptions& options, std::ostream& err);

struct HtmlPicture {
  std::string caption;  ///< e.g. "--svg train.svg"
  std::string svg;      ///< an SVG document (an XML declaration is dropped)
};

struct HtmlInput {
  std::string path;
  std::string content;  ///< the file's text
};

struct HtmlPage {
  std::vector<HtmlPicture> pictures;
  std::vector<HtmlInput> inputs;
};

/// One self-contained HTML5 page: title, gearkit version, warnings, the tables (numbers right
/// aligned, each with the id table_key()), notes, the pictures inline, the inputs with their units
/// as written, and the JSON data; no script, no external resource, a print style sheet.
void render_html(const Report& report, const HtmlPage& page, std::ostream& out);

}  // namespace gearkit::io
