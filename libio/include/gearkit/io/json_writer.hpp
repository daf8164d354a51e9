#pragma once
// JSON written straight into a string, without a document tree: what a report streamed row by
// row needs (a sweep of a million positions cannot hold one nlohmann::json per row, and
// building one costs ten times more than writing it).
#include <string>
#include <string_view>
#include <vector>

namespace gearkit::io {

/// `s` as a JSON string literal, quotes included, appended to `out`.
void append_json_string(std::string& out, std::string_view s);

/// The shortest text of `v` that reads back as the same double ("0.1", "1e-05", "3.0"),
/// appended to `out`. Requires a finite v.
void append_json_number(std::string& out, double v);

/// A key escaped once, for keys written again and again (the columns of a sweep's rows).
struct JsonKey {
  explicit JsonKey(std::string_view name);
  std::string quoted;  ///< `,"name":`: what follows a previous member (the comma dropped for a first)
};

/// Appends JSON values to a string. Containers are opened and closed explicitly; commas come by
/// themselves. Numbers are written in their shortest form that reads back to the same double
/// (an integral value keeps a ".0", as nlohmann::json writes it). A number that is not finite is
/// written as null and its path is remembered (non_finite_paths()), so that the report can name
/// it in a warning: JSON has no NaN, and a silent null is not allowed (docs/cli.md).
/// One writer may write many values in turn (a row after another): its bookkeeping is reused,
/// so writing a row allocates nothing once the first row is done. The output string may be
/// emptied between values written at the top level (a streamed report flushes it after a row).
class JsonWriter {
 public:
  /// @param out where the text goes (appended to); it must outlive the writer.
  explicit JsonWriter(std::string& out) : out_(&out) {}

  void begin_object();
  void end_object();
  void begin_array();
  void end_array();
  /// The key of the next value in the enclosing object (escaped as JSON requires).
  void key(std::string_view k);
  void key(const JsonKey& k) {  // inline: a sweep writes tens of millions
    Level& level = levels_[depth_ - 1];
    const std::string_view text = level.first ? std::string_view(k.quoted).substr(1) : std::string_view(k.quoted);
    level.first = false;
    level.key_at = out_->size() + text.size() - k.quoted.size() + 2;  // inside its quotes
    level.key_length = k.quoted.size() - 4;
    out_->append(text);
  }
  void value(double v) {
    separate();
    if (v == v && v - v == 0) append_json_number(*out_, v);  // finite
    else non_finite_null();
  }
  void value(int v);
  void value(bool v);
  void value(std::string_view s);
  void value(const char* s) { value(std::string_view(s)); }
  void null();
  /// A value that is already JSON text (a small subtree dumped by nlohmann::json).
  void raw_value(std::string_view json);

  /// Paths of the non-finite numbers written, each once, written as `prefix` then the keys
  /// joined by '.', array elements as "[]" ("positions[].q.crank.angle_deg").
  const std::vector<std::string>& non_finite_paths() const { return non_finite_; }
  void set_path_prefix(std::string prefix) { prefix_ = std::move(prefix); }

 private:
  void separate() {  // commas between array elements (key() writes an object member's)
    if (depth_ == 0) return;
    Level& level = levels_[depth_ - 1];
    if (!level.array) return;
    if (!level.first) *out_ += ',';
    level.first = false;
  }
  void non_finite_null();
  void open(char bracket, bool array);
  void close(char bracket);
  void note_non_finite();

  std::string* out_;
  struct Level {
    bool first = true;
    bool array = false;
    // The key of the member being written (objects), as written in the output: a value follows
    // its key at once, so the text is still there when a non-finite value needs its path.
    std::size_t key_at = 0, key_length = 0;
  };
  std::vector<Level> levels_;  // only grows: depth_ says how many are open
  std::size_t depth_ = 0;
  std::vector<std::string> non_finite_;
  std::string prefix_;
};


}  // namespace gearkit::io
