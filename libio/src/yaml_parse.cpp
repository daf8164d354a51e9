#include "yaml_parse.hpp"

#include <gearkit/io/error.hpp>

#include <fmt/format.h>
#include <yaml.h>

#include <map>
#include <memory>

namespace gearkit::io {
struct YamlNodeAccess;
}

namespace YAML {
// yaml-cpp wraps one of its internal nodes in a Node only for its friends. Every as_if<T, S> is
// one, so this specialisation is where a tree built from libyaml's events becomes a YAML::Node,
// exactly as yaml-cpp's own NodeBuilder::Root() makes it.
template <>
struct as_if<gearkit::io::YamlNodeAccess, void> {
  static Node wrap(detail::node& root, const detail::shared_memory_holder& memory) { return Node(root, memory); }
};
}  // namespace YAML

namespace gearkit::io {

namespace {

using Wrap = YAML::as_if<YamlNodeAccess, void>;

YAML::Mark mark_of_event(const yaml_mark_t& m) {
  YAML::Mark mark;
  mark.pos = static_cast<int>(m.index);
  mark.line = static_cast<int>(m.line);
  mark.column = static_cast<int>(m.column);
  return mark;
}

SourceMark source_mark(const yaml_mark_t& m, const std::string& name) {
  return {name, static_cast<int>(m.line) + 1, static_cast<int>(m.column) + 1};
}

// The nodes of one document, in the order of NodeBuilder's events: a scalar joins its
// collection at once, a collection when it ends; a mapping's key waits for its value.
class DocumentBuilder {
 public:
  /// @param nodes the nodes of the text so far, counted across its documents
  DocumentBuilder(const std::string& name, long& nodes) : name_(name), nodes_(nodes) {}

  void scalar(const yaml_event_t& e) {
    const auto& s = e.data.scalar;
    std::string value(reinterpret_cast<const char*>(s.value), s.length);
    YAML::detail::node& n = create(e, s.anchor);
    if (!s.tag && s.style == YAML_PLAIN_SCALAR_STYLE && YAML::IsNullString(value)) {  // ~, null, Null, NULL, nothing
      n.set_null();
    } else {
      n.set_scalar(value);
      n.set_tag(s.tag ? tag_text(s.tag) : s.style == YAML_PLAIN_SCALAR_STYLE ? "?" : "!");
    }
    attach(n);
  }

  void open(const yaml_event_t& e, YAML::NodeType::value type) {
    if (static_cast<int>(open_.size()) >= kMaxYamlDepth)
      fail_at(source_mark(e.start_mark, name_),
              fmt::format("expected YAML nested at most {} levels deep, found deeper nesting", kMaxYamlDepth));
    const bool map = type == YAML::NodeType::Map;
    const yaml_char_t* anchor = map ? e.data.mapping_start.anchor : e.data.sequence_start.anchor;
    const yaml_char_t* tag = map ? e.data.mapping_start.tag : e.data.sequence_start.tag;
    const bool flow = map ? e.data.mapping_start.style == YAML_FLOW_MAPPING_STYLE
                          : e.data.sequence_start.style == YAML_FLOW_SEQUENCE_STYLE;
    YAML::detail::node& n = create(e, anchor);
    n.set_type(type);
    n.set_tag(tag ? tag_text(tag) : "?");
    n.set_style(flow ? YAML::EmitterStyle::Flow : YAML::EmitterStyle::Block);
    open_.push_back({&n, nullptr});
  }

  void close() {
    YAML::detail::node& n = *open_.back().node;
    open_.pop_back();
    attach(n);
  }

  void alias(const yaml_event_t& e) {
    count(e);
    const auto found = anchors_.find(reinterpret_cast<const char*>(e.data.alias.anchor));
    if (found == anchors_.end())
      fail_at(source_mark(e.start_mark, name_),
              fmt::format("malformed YAML: expected an anchor defined before its alias, found *{}",
                          reinterpret_cast<const char*>(e.data.alias.anchor)));
    attach(*found->second);
  }

  YAML::Node root() const { return root_ ? Wrap::wrap(*root_, memory_) : YAML::Node(); }

 private:
  struct Open {
    YAML::detail::node* node;
    YAML::detail::node* key;  // a mapping's key waiting for its value
  };

  static std::string tag_text(const yaml_char_t* tag) { return reinterpret_cast<const char*>(tag); }

  // Every node counts, aliases too: a node beyond the limit is refused before yaml-cpp builds it.
  void count(const yaml_event_t& e) {
    if (++nodes_ > kMaxYamlNodes)
      fail_at(source_mark(e.start_mark, name_),
              fmt::format("expected a model of at most {} YAML nodes (values, keys, lists and mappings), found more",
                          kMaxYamlNodes));
  }

  YAML::detail::node& create(const yaml_event_t& e, const yaml_char_t* anchor) {
    count(e);
    YAML::detail::node& n = memory_->create_node();
    n.set_mark(mark_of_event(e.start_mark));
    if (anchor) anchors_[reinterpret_cast<const char*>(anchor)] = &n;
    return n;
  }

  void attach(YAML::detail::node& n) {
    if (open_.empty()) {
      root_ = &n;
      return;
    }
    Open& parent = open_.back();
    if (parent.node->type() == YAML::NodeType::Sequence) {
      parent.node->push_back(n, memory_);
    } else if (!parent.key) {
      parent.key = &n;
    } else {
      parent.node->insert(*parent.key, n, memory_);
      parent.key = nullptr;
    }
  }

  const std::string& name_;
  YAML::detail::shared_memory_holder memory_ = std::make_shared<YAML::detail::memory_holder>();
  std::vector<Open> open_;
  std::map<std::string, YAML::detail::node*, std::less<>> anchors_;
  YAML::detail::node* root_ = nullptr;
  long& nodes_;
};

// libyaml's problem, with its context when it has one, as one line at the problem's place.
[[noreturn]] void fail_malformed(const yaml_parser_t& p, const std::string& name) {
  std::string message = fmt::format("malformed YAML: {}", p.problem ? p.problem : "unreadable text");
  if (p.context)
    message += fmt::format(" ({} at line {}, column {})", p.context, p.context_mark.line + 1, p.context_mark.column + 1);
  fail_at(source_mark(p.problem_mark, name), message);
}

// Owns a libyaml parser and its current event, so that an error thrown while building frees them.
struct Parser {
  yaml_parser_t parser{};
  yaml_event_t event{};
  bool has_event = false;
  explicit Parser(std::string_view text) {
    if (!yaml_parser_initialize(&parser)) throw std::bad_alloc();
    yaml_parser_set_input_string(&parser, reinterpret_cast<const unsigned char*>(text.data()), text.size());
  }
  ~Parser() {
    if (has_event) yaml_event_delete(&event);
    yaml_parser_delete(&parser);
  }
  Parser(const Parser&) = delete;
  Parser& operator=(const Parser&) = delete;
  const yaml_event_t& next(const std::string& name) {
    if (has_event) yaml_event_delete(&event);
    has_event = false;
    if (!yaml_parser_parse(&parser, &event)) {
      if (parser.error == YAML_MEMORY_ERROR) throw std::bad_alloc();
      fail_malformed(parser, name);
    }
    has_event = true;
    return event;
  }
};

}  // namespace

std::vector<YAML::Node> parse_yaml_documents(std::string_view text, const std::string& name) {
  Parser parser(text);
  std::vector<YAML::Node> documents;
  std::unique_ptr<DocumentBuilder> document;
  long nodes = 0;
  for (;;) {
    const yaml_event_t& e = parser.next(name);
    switch (e.type) {
      case YAML_STREAM_END_EVENT: return documents;
      case YAML_DOCUMENT_START_EVENT: document = std::make_unique<DocumentBuilder>(name, nodes); break;
      case YAML_DOCUMENT_END_EVENT: documents.push_back(document->root()); break;
      case YAML_SCALAR_EVENT: document->scalar(e); break;
      case YAML_ALIAS_EVENT: document->alias(e); break;
      case YAML_SEQUENCE_START_EVENT: document->open(e, YAML::NodeType::Sequence); break;
      case YAML_MAPPING_START_EVENT: document->open(e, YAML::NodeType::Map); break;
      case YAML_SEQUENCE_END_EVENT:
      case YAML_MAPPING_END_EVENT: document->close(); break;
      default: break;  // stream start, no event
    }
  }
}

}  // namespace gearkit::io
