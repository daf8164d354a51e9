#pragma once
// Reports whose main table is written row by row while it is computed (a sweep of a mechanism),
// in every format of report.hpp, in memory that does not grow with the number of rows. The
// output reads like a whole report rendered by render(): title, tables, notes, warnings; in JSON
// one valid document whose rows form one array.
#include <gearkit/io/json_writer.hpp>
#include <gearkit/io/report.hpp>

#include <iosfwd>
#include <string>
#include <vector>

namespace gearkit::io {

class ReportStream {
 public:
  /// @param out where the report goes (a stream of an OutputSet); it must outlive this object.
  ReportStream(std::ostream& out, Format format);

  Format format() const { return format_; }

  /// CSV: write the streamed table alone, header first, so that a spreadsheet or pandas loads it
  /// as it is (docs/cli.md, "Tables and formats"): no other table, no comment line; the caller
  /// reports the warnings (on stderr) and the tables left out. Otherwise (the default) every
  /// table follows the other, each after a "# title" line, warnings as "# warning:" lines.
  /// Call before begin().
  void set_csv_streamed_table_only(bool only) { csv_streamed_only_ = only; }

  /// Writes what is known before the rows: `head`'s title, tables and JSON keys, then the
  /// streamed table's title and header (text waits for its first 1000 rows to size the columns;
  /// later rows wider than those overflow their column). In JSON the rows form the array
  /// `rows_key`. Call once, first.
  void begin(const Report& head, Table streamed, std::string rows_key);

  /// One row of the streamed table as its cells (text, CSV and Markdown only).
  void add_cells(const std::vector<std::string>& cells);

  /// One row as JSON (JSON only): write exactly one value with the returned writer (usually an
  /// object), then call end_json_row().
  JsonWriter& begin_json_row();
  void end_json_row();

  /// Writes the rest: `tail`'s tables after the streamed one, the head's notes then the tail's,
  /// the warnings (the head's, the tail's and one for each quantity that was not a finite
  /// number, in a row or in the tail, as emit() adds for whole reports), and in JSON the tail's
  /// keys and "warnings". Flushes the stream.
  /// @returns every warning written, for the exit status.
  std::vector<std::string> finish(const Report& tail);

  /// Rows written so far.
  long rows() const { return rows_; }

 private:
  void flush_buffer(bool force);
  void write_text_head();
  void note_non_finite_cells(const std::vector<std::string>& cells);

  std::ostream& out_;
  Format format_;
  bool csv_streamed_only_ = false;
  Report head_;  // title, notes and warnings kept for the end (its tables are written at once)
  Table streamed_;
  std::vector<std::vector<std::string>> first_rows_;  // text: rows held until the widths are known
  std::vector<std::size_t> width_;
  bool head_written_ = false;
  std::string buffer_;
  JsonWriter json_{buffer_};
  long rows_ = 0;
  std::vector<std::string> non_finite_;  // quantities met as nan/inf in rows
};

}  // namespace gearkit::io
