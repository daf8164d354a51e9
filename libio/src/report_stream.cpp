#include <gearkit/io/report_stream.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <ostream>
#include <stdexcept>

#include "table_text.hpp"

namespace gearkit::io {

namespace {

// Text tables are sized from their first rows; these many are held back before the header.
constexpr std::size_t kRowsForWidths = 1000;
// Rows are gathered into a buffer of about this size before they go to the stream.
constexpr std::size_t kBufferBytes = 1 << 16;

// `"key": value` as a member of the top-level object, nested lines indented like dump(2).
void json_member(std::ostream& out, const std::string& key, const nlohmann::json& value) {
  std::string text = value.dump(2);
  std::string indented;
  indented.reserve(text.size());
  for (const char c : text) {
    indented += c;
    if (c == '\n') indented += "  ";
  }
  std::string quoted;
  append_json_string(quoted, key);
  out << "  " << quoted << ": " << indented;
}

void add_unique(std::vector<std::string>& names, const std::string& name) {
  if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
}

}  // namespace

ReportStream::ReportStream(std::ostream& out, Format format) : out_(out), format_(format) {}

void ReportStream::begin(const Report& head, Table streamed, std::string rows_key) {
  head_.title = head.title;
  head_.notes = head.notes;
  head_.warnings = head.warnings;
  head_.json = head.json;
  streamed_ = std::move(streamed);
  for (const std::string& name : non_finite_quantities(head)) add_unique(non_finite_, name);
  switch (format_) {
    case Format::json:
      out_ << "{\n";
      for (const auto& [key, value] : head.json.items()) {
        json_member(out_, key, value);
        out_ << ",\n";
      }
      buffer_.clear();
      append_json_string(buffer_, rows_key);
      out_ << "  " << buffer_ << ": [";
      buffer_.clear();
      json_.set_path_prefix(rows_key + "[]");
      return;
    case Format::text:
      if (!head.title.empty()) out_ << head.title << "\n\n";
      for (const Table& t : head.tables) {
        detail::render_text_table(t, out_);
        out_ << "\n";
      }
      if (!streamed_.title.empty()) out_ << streamed_.title << "\n";
      detail::widen(width_, streamed_.header);
      return;
    case Format::md:
      if (!head.title.empty()) out_ << "## " << detail::md_escape(head.title) << "\n\n";
      for (const Table& t : head.tables) detail::render_md_table(t, out_);
      detail::md_table_head(out_, streamed_, streamed_.header.size());
      return;
    case Format::csv:
      if (!csv_streamed_only_) {
        for (const Table& t : head.tables) {
          if (!t.title.empty()) out_ << "# " << t.title << "\n";
          detail::render_csv_table(t, out_);
          out_ << "\n";
        }
        if (!streamed_.title.empty()) out_ << "# " << streamed_.title << "\n";
      }
      detail::csv_row(out_, streamed_.header);
      return;
    case Format::html:
      throw std::logic_error("ReportStream: an HTML page is rendered whole (report_output.hpp)");
  }
}

void ReportStream::note_non_finite_cells(const std::vector<std::string>& cells) {
  for (std::size_t c = 0; c < cells.size(); ++c)
    if (detail::non_finite_text(cells[c]))
      add_unique(non_finite_, fmt::format("'{}' in table '{}'", c < streamed_.header.size() ? streamed_.header[c] : "?",
                                          streamed_.title));
}

void ReportStream::write_text_head() {
  for (const auto& row : first_rows_) detail::widen(width_, row);
  if (!streamed_.header.empty()) {
    detail::text_line(out_, streamed_.header, width_, true);
    detail::text_rule(out_, width_);
  }
  for (const auto& row : first_rows_) detail::text_line(out_, row, width_, false);
  first_rows_.clear();
  first_rows_.shrink_to_fit();
  head_written_ = true;
}

void ReportStream::add_cells(const std::vector<std::string>& cells) {
  ++rows_;
  note_non_finite_cells(cells);
  switch (format_) {
    case Format::text:
      if (!head_written_) {
        first_rows_.push_back(cells);
        if (first_rows_.size() >= kRowsForWidths) write_text_head();
      } else {
        detail::text_line(buffer_, cells, width_, false);
      }
      break;
    case Format::md:
      detail::md_row(buffer_, cells, streamed_.header.size());
      break;
    case Format::csv:
      detail::csv_row(buffer_, cells);
      break;
    case Format::json:
    case Format::html:
      break;
  }
  flush_buffer(false);
}

JsonWriter& ReportStream::begin_json_row() {
  buffer_ += rows_ == 0 ? "\n    " : ",\n    ";
  return json_;
}

void ReportStream::end_json_row() {
  ++rows_;
  flush_buffer(false);
}

void ReportStream::flush_buffer(bool force) {
  if (buffer_.empty() || (!force && buffer_.size() < kBufferBytes)) return;
  out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  buffer_.clear();
}

std::vector<std::string> ReportStream::finish(const Report& tail) {
  flush_buffer(true);
  std::vector<std::string> names = non_finite_;
  for (const std::string& p : json_.non_finite_paths()) add_unique(names, "'" + p + "'");
  for (const std::string& name : non_finite_quantities(tail)) add_unique(names, name);
  std::vector<std::string> warnings = head_.warnings;
  warnings.insert(warnings.end(), tail.warnings.begin(), tail.warnings.end());
  for (std::string& w : non_finite_warnings(names)) warnings.push_back(std::move(w));
  std::vector<std::string> notes = head_.notes;
  notes.insert(notes.end(), tail.notes.begin(), tail.notes.end());

  switch (format_) {
    case Format::json: {
      out_ << (rows_ == 0 ? "]" : "\n  ]");
      for (const auto& [key, value] : tail.json.items()) {
        out_ << ",\n";
        json_member(out_, key, value);
      }
      out_ << ",\n";
      json_member(out_, "warnings", nlohmann::json(warnings));
      out_ << "\n}\n";
      break;
    }
    case Format::text:
      if (!head_written_) write_text_head();
      out_ << "\n";
      for (const Table& t : tail.tables) {
        detail::render_text_table(t, out_);
        out_ << "\n";
      }
      for (const auto& n : notes) out_ << n << "\n";
      if (!notes.empty()) out_ << "\n";
      if (warnings.empty()) {
        out_ << "Warnings: none\n";
      } else {
        out_ << "Warnings:\n";
        for (const auto& w : warnings) out_ << "  ! " << w << "\n";
      }
      break;
    case Format::md:
      out_ << "\n";
      for (const Table& t : tail.tables) detail::render_md_table(t, out_);
      for (const auto& n : notes) out_ << detail::md_escape(n) << "\n\n";
      out_ << "**Warnings:**" << (warnings.empty() ? " none\n" : "\n\n");
      for (const auto& w : warnings) out_ << "- " << detail::md_escape(w) << "\n";
      break;
    case Format::csv:
      if (csv_streamed_only_) break;
      for (const Table& t : tail.tables) {
        out_ << "\n";
        if (!t.title.empty()) out_ << "# " << t.title << "\n";
        detail::render_csv_table(t, out_);
      }
      for (const auto& w : warnings) out_ << "# warning: " << w << "\n";
      break;
    case Format::html:
      break;
  }
  out_.flush();
  return warnings;
}

}  // namespace gearkit::io
