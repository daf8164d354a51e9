#include <gearkit/sym/equations_file.hpp>

#include <gearkit/io/error.hpp>
#include <gearkit/kin/joints.hpp>

#include <fmt/format.h>

#include <algorithm>

namespace gearkit::sym {

namespace {

class SectionReader {
 public:
  SectionReader(const std::string& file, const kin::Model& model) : file_(file), model_(model) {}

  kin::BodyPoint point(const YAML::Node& node) const {
    const std::string text = node.IsScalar() ? node.Scalar() : "";
    const auto dot = text.find('.');
    if (dot == std::string::npos) fail(node, fmt::format("expected a point as link.point, found {}", io::quote(text)));
    const std::string link = text.substr(0, dot), name = text.substr(dot + 1);
    const auto body = model_.body_index(link);
    if (!body) fail(node, fmt::format("unknown link {}", io::quote(link)));
    const kin::Body& b = *body == kin::kGround ? model_.ground() : model_.bodies()[static_cast<std::size_t>(*body)];
    const auto local = b.point(name);
    if (!local) fail(node, fmt::format("link '{}' has no point {}", link, io::quote(name)));
    return {*body, *local};
  }

  std::pair<kin::BodyPoint, kin::BodyPoint> pair(const YAML::Node& node) const {
    if (!node.IsSequence() || node.size() != 2) fail(node, "expected two points [link.A, link.B]");
    const kin::BodyPoint a = point(node[0]), b = point(node[1]);
    if (a.body != b.body) fail(node, "expected two points of the same link");
    if ((a.local - b.local).norm() < 1e-12) fail(node, "expected two distinct points");
    return {a, b};
  }

  Coordinate coordinate(const YAML::Node& node) const {
    io::MapReader r(node, file_, "coordinate");
    Coordinate c;
    c.name = r.string("name");
    c.tex = r.optional_string("tex").value_or("");
    if (r.has("angle")) {
      const auto [from, to] = pair(r.node("angle"));
      if (from.body == kin::kGround) fail(r.node("angle"), "expected points of a moving link, found the ground's");
      c.angle.from = from;
      c.angle.to = to;
      c.angle.zero = r.quantity_or("zero", io::Quantity::angle, "deg", 0.0);
      c.angle.sense = r.boolean_or("clockwise", false) ? -1 : +1;
    } else {
      c.is_angle = false;
      const YAML::Node joint = r.node("slide");
      const auto k = model_.constraint_index(joint.IsScalar() ? joint.Scalar() : "");
      const auto* p = k ? dynamic_cast<const kin::Prismatic*>(model_.constraints()[static_cast<std::size_t>(*k)].constraint.get()) : nullptr;
      if (!p) fail(joint, "expected the name of a prismatic joint");
      c.displacement.joint = *k;
      c.displacement.origin = p->guide().local;
      if (r.has("from")) {
        const kin::BodyPoint o = point(r.node("from"));
        if (o.body != p->guide().body) fail(r.node("from"), "expected a point of the guide link");
        c.displacement.origin = o.local;
      }
      c.displacement.sign = r.boolean_or("reversed", false) ? -1 : +1;
    }
    r.finish();
    return c;
  }

  Symbol symbol(const YAML::Node& node) const {
    io::MapReader r(node, file_, "symbol");
    Symbol s;
    s.name = r.string("name");
    s.tex = r.optional_string("tex").value_or("");
    const std::vector<std::pair<const char*, Symbol::Kind>> kinds = {
        {"length", Symbol::Kind::length}, {"dx", Symbol::Kind::dx}, {"dy", Symbol::Kind::dy}, {"angle", Symbol::Kind::angle}};
    const auto it = std::find_if(kinds.begin(), kinds.end(), [&r](const auto& k) { return r.has(k.first); });
    if (it == kinds.end()) fail(node, "expected one of length, dx, dy or angle");
    s.kind = it->second;
    const YAML::Node v = r.node(it->first);
    if (s.kind == Symbol::Kind::angle) {
      if (!v.IsSequence() || v.size() != 2) fail(v, "expected two segments [[link.A, link.B], [link.C, link.D]]");
      std::tie(s.a, s.b) = pair(v[0]);
      std::tie(s.c, s.d) = pair(v[1]);
      if (s.c.body != s.a.body) fail(v, "expected both segments on the same link");
    } else {
      std::tie(s.a, s.b) = pair(v);
    }
    r.finish();
    return s;
  }

  [[noreturn]] void fail(const YAML::Node& node, const std::string& message) const {
    io::fail_at(io::mark_of(node, file_), message);
  }

 private:
  const std::string& file_;
  const kin::Model& model_;
};

}  // namespace

EquationsInput read_equations_input(const YAML::Node& section, const std::string& file, const kin::Model& model) {
  const SectionReader reader(file, model);
  io::MapReader r(section, file, "equations");
  EquationsInput in;
  for (const YAML::Node& c : r.sequence("coordinates")) in.coordinates.push_back(reader.coordinate(c));
  if (r.has("symbols"))
    for (const YAML::Node& s : r.sequence("symbols")) in.symbols.push_back(reader.symbol(s));
  if (auto ind = r.optional_node("independent")) {
    const std::string name = ind->IsScalar() ? ind->Scalar() : "";
    const auto it = std::find_if(in.coordinates.begin(), in.coordinates.end(), [&](const Coordinate& c) { return c.name == name; });
    if (it == in.coordinates.end()) reader.fail(*ind, fmt::format("expected the name of a coordinate, found {}", io::quote(name)));
    in.independent = {static_cast<int>(it - in.coordinates.begin())};
  }
  r.finish();
  if (in.coordinates.empty()) reader.fail(section, "expected at least one coordinate");
  return in;
}

}  // namespace gearkit::sym
