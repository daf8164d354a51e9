#pragma once
// Reading model files: YAML loaded with yaml-cpp, then read field by field through MapReader,
// which checks types, units and unknown keys and reports every problem as
// "file:line:column: expected ..., found ...".
#include <gearkit/io/error.hpp>
#include <gearkit/io/quantity.hpp>
#include <yaml-cpp/yaml.h>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace gearkit::io {

/// A loaded YAML document and the file it came from.
struct YamlDocument {
  std::string file;
  YAML::Node root;
};

/// Loads a YAML file for a model.
/// @throws InputError when the path is missing, a directory or unreadable; the file is empty,
///         binary (NUL bytes or invalid UTF-8), larger than `max_bytes`, nested deeper or
///         holding more nodes than the limits of docs/cli.md, or malformed YAML (with the
///         parser's line and column).
YamlDocument load_yaml_file(const std::string& path, std::uintmax_t max_bytes = 64u << 20);

/// Parses YAML text (an embedded model) as if it came from `name`. Same errors as above.
YamlDocument load_yaml_text(const std::string& text, const std::string& name);

/// The position of a node in `file`.
SourceMark mark_of(const YAML::Node& node, const std::string& file);

/// Reads one YAML mapping. Every accessor marks its key as known; finish() then rejects any
/// key that no accessor asked for, so typos ("modulus: 3") never pass silently.
class MapReader {
 public:
  /// @param what what the mapping is, for messages ("gear", "mesh 'm1'").
  /// @throws InputError if `node` is not a mapping.
  MapReader(const YAML::Node& node, std::string file, std::string what);

  bool has(const std::string& key) const;
  SourceMark mark() const;                        ///< of the mapping itself
  SourceMark mark(const std::string& key) const;  ///< of the key's value (or the mapping)
  const std::string& file() const { return file_; }
  const std::string& what() const { return what_; }

  /// A quantity in SI, with `default_unit` for bare numbers. @throws InputError if missing or bad.
  double quantity(const std::string& key, Quantity q, std::string_view default_unit);
  std::optional<double> optional_quantity(const std::string& key, Quantity q, std::string_view default_unit);
  double quantity_or(const std::string& key, Quantity q, std::string_view default_unit, double default_si);

  /// A whole number (rejects 12.5, "twelve"). @throws InputError if missing or not an integer.
  long long integer(const std::string& key);
  std::optional<long long> optional_integer(const std::string& key);

  double number(const std::string& key);  ///< a plain dimensionless number
  std::optional<double> optional_number(const std::string& key);

  std::string string(const std::string& key);
  std::optional<std::string> optional_string(const std::string& key);
  /// A string that must be one of `choices`.
  std::string choice(const std::string& key, const std::vector<std::string>& choices,
                     std::optional<std::string> default_value = std::nullopt);

  bool boolean(const std::string& key);
  bool boolean_or(const std::string& key, bool default_value);

  /// The raw node (marks the key known). @throws InputError if missing.
  YAML::Node node(const std::string& key);
  std::optional<YAML::Node> optional_node(const std::string& key);
  /// A nested mapping. @throws InputError if missing or not a mapping.
  MapReader map(const std::string& key);
  /// A sequence's items. @throws InputError if missing or not a sequence.
  std::vector<YAML::Node> sequence(const std::string& key);
  /// A sequence of at most `at_most` items, `items` naming them for the message ("points").
  /// @throws InputError as above, or at the first item beyond the limit (docs/cli.md, Limits).
  std::vector<YAML::Node> sequence(const std::string& key, std::size_t at_most, std::string_view items);

  /// Rejects keys no accessor asked for: "file:l:c: unknown key 'x' in gear; expected one of: ...".
  void finish() const;

 private:
  YAML::Node get(const std::string& key) const;
  [[noreturn]] void fail(const std::string& key, std::string_view message) const;

  YAML::Node node_;
  std::string file_;
  std::string what_;
  mutable std::set<std::string> known_;
};

/// Refuses a list or mapping of more than `at_most` items, at the first one beyond the limit:
/// "expected at most N `items` in `what`, found M". Anything else passes.
void check_size(const YAML::Node& node, const std::string& file, std::size_t at_most, std::string_view items,
                std::string_view what);

/// Reads a scalar as a quantity, reporting errors at the node.
double scalar_quantity(const YAML::Node& node, const std::string& file, Quantity q,
                       std::string_view default_unit);
/// The scalar text of a node. @throws InputError if it is not a scalar.
std::string scalar_text(const YAML::Node& node, const std::string& file, std::string_view what);

}  // namespace gearkit::io
