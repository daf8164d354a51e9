#pragma once
// The YAML documents of a model text, parsed by libyaml (the reference C parser) into yaml-cpp
// nodes. yaml-cpp stays the node type every reader uses; only its parser is left out: it reads
// a 431 KB mechanism file (`gearkit kin --example chain:1000`) in about 100 ms, libyaml's events
// and the nodes built from them take about a quarter of that.
#include <yaml-cpp/yaml.h>

#include <string>
#include <string_view>
#include <vector>

namespace gearkit::io {

/// Deepest nesting of collections a model may have (docs/cli.md, Limits).
inline constexpr int kMaxYamlDepth = 500;

/// Every document of `text` (an empty vector for a text without any), built as yaml-cpp's own
/// parser builds them: a plain scalar ~, null, Null, NULL or empty is a null node; scalars carry
/// the tag "?" (plain) or "!" (quoted or block) unless tagged; aliases share their anchor's node;
/// every node carries the mark of its first character (0-based line and column).
/// @throws io::InputError at `name`:line:column for malformed YAML (libyaml's problem and its
///         context), an alias of no anchor, or collections nested deeper than kMaxYamlDepth.
std::vector<YAML::Node> parse_yaml_documents(std::string_view text, const std::string& name);

}  // namespace gearkit::io
