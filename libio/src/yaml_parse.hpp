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
/// Most nodes (scalars, lists, mappings and aliases, keys included) a model may have: a yaml-cpp
/// node costs about 480 bytes, so the limit holds a model's tree under about 500 MB; the largest
/// model of the examples, `kin --example chain:10000`, has 710,059.
inline constexpr long kMaxYamlNodes = 1'000'000;

/// Every document of `text` (an empty vector for a text without any), built as yaml-cpp's own
/// parser builds them: a plain scalar ~, null, Null, NULL or empty is a null node; scalars carry
/// the tag "?" (plain) or "!" (quoted or block) unless tagged; aliases share their anchor's node;
/// every node carries the mark of its first character (0-based line and column).
/// @throws io::InputError at `name`:line:column for malformed YAML (libyaml's problem and its
///         context), an alias of no anchor, collections nested deeper than kMaxYamlDepth, or more
///         than kMaxYamlNodes nodes (at the first node beyond, before it is built).
std::vector<YAML::Node> parse_yaml_documents(std::string_view text, const std::string& name);

}  // namespace gearkit::io
