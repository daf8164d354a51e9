#pragma once
// The cell and line layout of tables in text, Markdown and CSV, shared by the whole-report
// renderer (report.cpp) and the streamed one (report_stream.cpp), so both print alike.
#include <gearkit/io/report.hpp>

#include "glyphs.hpp"

#include <ostream>
#include <string>
#include <vector>

namespace gearkit::io::detail {

/// Widens `width` (one entry per column, grown as needed) to fit the cells of `row`.
void widen(std::vector<std::size_t>& width, const std::vector<std::string>& row);

/// One text line: cells padded to `width`, numbers right-aligned (not in the header), two
/// spaces between columns, indented by two, no trailing blanks.
void text_line(std::ostream& out, const std::vector<std::string>& row, const std::vector<std::size_t>& width, bool header);
void text_line(std::string& out, const std::vector<std::string>& row, const std::vector<std::size_t>& width, bool header);

/// The dashed rule under a text header.
void text_rule(std::ostream& out, const std::vector<std::size_t>& width);

/// "### title" and the header and alignment rows of a Markdown table of `columns` columns.
void md_table_head(std::ostream& out, const Table& t, std::size_t columns);
void md_row(std::ostream& out, const std::vector<std::string>& row, std::size_t columns);
void md_row(std::string& out, const std::vector<std::string>& row, std::size_t columns);
std::string md_escape(const std::string& s);

/// One CSV record (RFC 4180 quoting where a cell needs it).
void csv_row(std::ostream& out, const std::vector<std::string>& row);
void csv_row(std::string& out, const std::vector<std::string>& row);

/// Whole tables as render() prints them (text: title, header, rule, rows; Markdown: "###"
/// title, header, rows, blank line; CSV: header and rows).
void render_text_table(const Table& t, std::ostream& out);
void render_md_table(const Table& t, std::ostream& out);
void render_csv_table(const Table& t, std::ostream& out);

/// True when a cell reads nan or inf (alone or as a word of the cell).
bool non_finite_text(std::string_view cell);

}  // namespace gearkit::io::detail
