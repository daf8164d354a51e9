#include <gearkit/io/yaml_model.hpp>
#include "yaml_parse.hpp"

#include <cctype>

#include <gearkit/io/output.hpp>

#include <fmt/format.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace gearkit::io {

namespace fs = std::filesystem;

namespace {

// Strict UTF-8 check (no overlongs, no surrogates); binary garbage fails it at once.
bool valid_utf8(std::string_view s, std::size_t& bad_offset) {
  const auto* p = reinterpret_cast<const unsigned char*>(s.data());
  std::size_t n = s.size(), i = 0;
  while (i < n) {
    unsigned char c = p[i];
    std::size_t len = 0;
    std::uint32_t cp = 0;
    if (c == 0) { bad_offset = i; return false; }
    if (c < 0x80) { ++i; continue; }
    if ((c & 0xE0) == 0xC0) { len = 2; cp = c & 0x1F; }
    else if ((c & 0xF0) == 0xE0) { len = 3; cp = c & 0x0F; }
    else if ((c & 0xF8) == 0xF0) { len = 4; cp = c & 0x07; }
    else { bad_offset = i; return false; }
    if (i + len > n) { bad_offset = i; return false; }
    for (std::size_t k = 1; k < len; ++k) {
      if ((p[i + k] & 0xC0) != 0x80) { bad_offset = i; return false; }
      cp = (cp << 6) | (p[i + k] & 0x3F);
    }
    bool overlong = (len == 2 && cp < 0x80) || (len == 3 && cp < 0x800) || (len == 4 && cp < 0x10000);
    if (overlong || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) { bad_offset = i; return false; }
    i += len;
  }
  return true;
}

// Line and column (1-based) of a byte offset, for messages about the raw text.
SourceMark mark_of_offset(std::string_view text, std::size_t offset, const std::string& file) {
  int line = 1, col = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') { ++line; col = 1; } else { ++col; }
  }
  return {file, line, col};
}

std::string describe_node(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Null: return "nothing";
    case YAML::NodeType::Scalar: return quote(node.Scalar());
    case YAML::NodeType::Sequence: return "a list";
    case YAML::NodeType::Map: return "a mapping";
    case YAML::NodeType::Undefined: return "nothing";
  }
  return "something else";
}

YamlDocument parse_checked(const std::string& text, const std::string& name) {
  std::size_t bad = 0;
  if (!valid_utf8(text, bad))
    fail_at(mark_of_offset(text, bad, name), "expected a YAML text file (UTF-8), found binary data");
  YamlDocument doc{name, {}};
  const std::vector<YAML::Node> documents = parse_yaml_documents(text, name);
  if (!documents.empty()) doc.root = documents.front();
  for (std::size_t i = 1; i < documents.size(); ++i)
    if (documents[i].IsDefined() && !documents[i].IsNull())
      fail_at(mark_of(documents[i], name), "expected one YAML document per file, found a second one after '---'");
  if (!doc.root.IsDefined() || doc.root.IsNull())
    fail_at({name, 0, 0}, "expected a YAML model, found an empty file");
  return doc;
}

bool parse_integer(std::string_view s, long long& out) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && ptr == s.data() + s.size() && !s.empty();
}

}  // namespace

YamlDocument load_yaml_file(const std::string& path, std::uintmax_t max_bytes) {
  std::error_code ec;
  fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) fail_at({path, 0, 0}, "expected a model file, found no such file");
  if (fs::is_directory(st)) fail_at({path, 0, 0}, "expected a model file, found a directory");
  if (!fs::is_regular_file(st)) fail_at({path, 0, 0}, "expected a regular model file, found a special file");
  std::uintmax_t size = fs::file_size(path, ec);
  if (!ec && size > max_bytes)
    fail_at({path, 0, 0}, fmt::format("expected a model file of at most {} MiB, found {} bytes", max_bytes >> 20, size));
  note_input_file(path);  // no output of this run may replace it
  std::ifstream in(path, std::ios::binary);
  if (!in) fail_at({path, 0, 0}, fmt::format("expected a readable file, found: {}", std::strerror(errno)));
  // Read into one string of the file's size (a stringstream held the text twice); then whatever
  // follows (a file that grows, or one whose size is not known), up to the limit.
  std::string text(ec ? std::uintmax_t{0} : size, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  for (char chunk[1 << 16]; in && text.size() <= max_bytes;) {
    in.read(chunk, sizeof chunk);
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) fail_at({path, 0, 0}, "expected a readable file, found a read error");
  if (text.size() > max_bytes)
    fail_at({path, 0, 0}, fmt::format("expected a model file of at most {} MiB, found more", max_bytes >> 20));
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    fail_at({path, 0, 0}, "expected a YAML model, found an empty file");
  return parse_checked(text, path);
}

YamlDocument load_yaml_text(const std::string& text, const std::string& name) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    fail_at({name, 0, 0}, "expected a YAML model, found an empty text");
  return parse_checked(text, name);
}

SourceMark mark_of(const YAML::Node& node, const std::string& file) {
  YAML::Mark m = node.Mark();
  if (m.is_null()) return {file, 0, 0};
  return {file, m.line + 1, m.column + 1};
}

std::string scalar_text(const YAML::Node& node, const std::string& file, std::string_view what) {
  if (!node.IsScalar()) fail_at(mark_of(node, file), fmt::format("expected {}, found {}", what, describe_node(node)));
  return node.Scalar();
}

void check_size(const YAML::Node& node, const std::string& file, std::size_t at_most, std::string_view items,
                std::string_view what) {
  if (!(node.IsSequence() || node.IsMap()) || node.size() <= at_most) return;
  auto first_beyond = node.begin();
  for (std::size_t i = 0; i < at_most; ++i) ++first_beyond;
  const YAML::Node here = node.IsMap() ? first_beyond->first : YAML::Node(*first_beyond);
  fail_at(mark_of(here, file), fmt::format("expected at most {} {} in {}, found {} (the first beyond the limit here; "
                                           "docs/cli.md, Limits)",
                                           at_most, items, what, node.size()));
}

double scalar_quantity(const YAML::Node& node, const std::string& file, Quantity q, std::string_view default_unit) {
  std::string text = scalar_text(node, file, describe(q));
  try {
    return parse_quantity_si(text, q, default_unit);
  } catch (const QuantityError& e) {
    fail_at(mark_of(node, file), e.what());
  }
}

// ---------------------------------------------------------------------------------------------

MapReader::MapReader(const YAML::Node& node, std::string file, std::string what)
    : node_(node), file_(std::move(file)), what_(std::move(what)) {
  if (!node_.IsMap())
    fail_at(mark_of(node_, file_), fmt::format("expected a mapping for {}, found {}", what_, describe_node(node_)));
  std::set<std::string> seen;
  for (const auto& kv : node_) {
    if (!kv.first.IsScalar())
      fail_at(mark_of(kv.first, file_), fmt::format("expected a key name in {}, found {}", what_, describe_node(kv.first)));
    if (!seen.insert(kv.first.Scalar()).second)
      fail_at(mark_of(kv.first, file_), fmt::format("duplicate key {} in {}", quote(kv.first.Scalar()), what_));
  }
}

bool MapReader::has(const std::string& key) const {
  known_.insert(key);
  return static_cast<bool>(node_[key]);
}

SourceMark MapReader::mark() const { return mark_of(node_, file_); }

SourceMark MapReader::mark(const std::string& key) const {
  YAML::Node n = node_[key];
  return n ? mark_of(n, file_) : mark();
}

YAML::Node MapReader::get(const std::string& key) const {
  known_.insert(key);
  YAML::Node n = node_[key];
  if (!n) fail_at(mark(), fmt::format("missing key '{}' in {}", key, what_));
  return n;
}

void MapReader::fail(const std::string& key, std::string_view message) const { fail_at(mark(key), message); }

double MapReader::quantity(const std::string& key, Quantity q, std::string_view default_unit) {
  YAML::Node n = get(key);
  std::string text = scalar_text(n, file_, fmt::format("{} for '{}'", describe(q), key));
  try {
    return parse_quantity_si(text, q, default_unit);
  } catch (const QuantityError& e) {
    fail(key, fmt::format("'{}': {}", key, e.what()));
  }
}

std::optional<double> MapReader::optional_quantity(const std::string& key, Quantity q, std::string_view default_unit) {
  if (!has(key)) return std::nullopt;
  return quantity(key, q, default_unit);
}

double MapReader::quantity_or(const std::string& key, Quantity q, std::string_view default_unit, double default_si) {
  return optional_quantity(key, q, default_unit).value_or(default_si);
}

long long MapReader::integer(const std::string& key) {
  YAML::Node n = get(key);
  std::string text = scalar_text(n, file_, fmt::format("a whole number for '{}'", key));
  long long v = 0;
  if (!parse_integer(text, v)) fail(key, fmt::format("'{}': expected a whole number, found {}", key, quote(text)));
  return v;
}

std::optional<long long> MapReader::optional_integer(const std::string& key) {
  if (!has(key)) return std::nullopt;
  return integer(key);
}

double MapReader::number(const std::string& key) {
  YAML::Node n = get(key);
  std::string text = scalar_text(n, file_, fmt::format("a number for '{}'", key));
  try {
    return parse_quantity_si(text, Quantity::dimensionless, "");
  } catch (const QuantityError& e) {
    fail(key, fmt::format("'{}': {}", key, e.what()));
  }
}

std::optional<double> MapReader::optional_number(const std::string& key) {
  if (!has(key)) return std::nullopt;
  return number(key);
}

std::string MapReader::string(const std::string& key) {
  return scalar_text(get(key), file_, fmt::format("a text value for '{}'", key));
}

std::optional<std::string> MapReader::optional_string(const std::string& key) {
  if (!has(key)) return std::nullopt;
  return string(key);
}

std::string MapReader::choice(const std::string& key, const std::vector<std::string>& choices,
                              std::optional<std::string> default_value) {
  if (!has(key)) {
    if (default_value) return *default_value;
    fail_at(mark(), fmt::format("missing key '{}' in {} (one of: {})", key, what_, fmt::join(choices, ", ")));
  }
  std::string v = string(key);
  for (const auto& c : choices)
    if (c == v) return v;
  fail(key, fmt::format("'{}': expected one of {}, found {}", key, fmt::join(choices, ", "), quote(v)));
}

bool MapReader::boolean(const std::string& key) {
  YAML::Node n = get(key);
  std::string text = scalar_text(n, file_, fmt::format("true or false for '{}'", key));
  if (text == "true" || text == "yes" || text == "on") return true;
  if (text == "false" || text == "no" || text == "off") return false;
  fail(key, fmt::format("'{}': expected true or false, found {}", key, quote(text)));
}

bool MapReader::boolean_or(const std::string& key, bool default_value) {
  if (!has(key)) return default_value;
  return boolean(key);
}

YAML::Node MapReader::node(const std::string& key) { return get(key); }

std::optional<YAML::Node> MapReader::optional_node(const std::string& key) {
  if (!has(key)) return std::nullopt;
  return get(key);
}

MapReader MapReader::map(const std::string& key) {
  YAML::Node n = get(key);
  return MapReader(n, file_, fmt::format("'{}' of {}", key, what_));
}

std::vector<YAML::Node> MapReader::sequence(const std::string& key) {
  YAML::Node n = get(key);
  if (!n.IsSequence()) fail(key, fmt::format("'{}': expected a list, found {}", key, describe_node(n)));
  std::vector<YAML::Node> items;
  items.reserve(n.size());
  for (const auto& item : n) items.push_back(item);
  return items;
}

std::vector<YAML::Node> MapReader::sequence(const std::string& key, std::size_t at_most, std::string_view items) {
  const YAML::Node n = get(key);
  if (n.IsSequence()) check_size(n, file_, at_most, items, fmt::format("'{}' of {}", key, what_));
  return sequence(key);  // (refuses anything but a list)
}

void MapReader::finish() const {
  for (const auto& kv : node_) {
    const std::string& k = kv.first.Scalar();
    if (known_.count(k)) continue;
    // "{m: 2,5 mm}": YAML splits a flow mapping at the comma, leaving "5 mm" as a key.
    if (!k.empty() && std::isdigit(static_cast<unsigned char>(k.front())) && kv.second.IsNull())
      fail_at(mark_of(kv.first, file_),
              fmt::format("expected a decimal point, found a decimal comma before {} in {} (inside "
                          "{{...}} a comma separates entries: write 2.5, not 2,5)",
                          quote(k), what_));
    fail_at(mark_of(kv.first, file_), fmt::format("unknown key {} in {}; expected one of: {}", quote(k), what_,
                                                 fmt::join(known_, ", ")));
  }
}

}  // namespace gearkit::io
