#include "train_file.hpp"

#include <gearkit/io/limits.hpp>
#include <gearkit/io/yaml_model.hpp>

#include <fmt/format.h>

#include <initializer_list>
#include <map>

namespace gearkit::plugins::train {

namespace gt = gearkit::train;

namespace {

constexpr long long max_teeth = 100000;

// Where each field of one entry is (the entry itself under ""), to place model errors.
using FieldMarks = std::map<std::string, io::SourceMark>;

FieldMarks marks_of(const io::MapReader& r, std::initializer_list<const char*> keys) {
  FieldMarks marks{{"", r.mark()}};
  for (const char* key : keys) marks[key] = r.mark(key);
  return marks;
}

std::string member_name(const YAML::Node& node, const std::string& file, const std::string& what) {
  const std::string name = io::scalar_text(node, file, what);
  if (name.find('=') != std::string::npos || name.find_first_of(" \t") != std::string::npos)
    io::fail_at(io::mark_of(node, file),
                fmt::format("expected a member name without spaces or '=', found {}", io::quote(name)));
  return name;
}

// The entries of `key`, refused beyond `limit` at the first entry too many (docs/cli.md, Limits).
std::vector<YAML::Node> limited_sequence(io::MapReader& root, const char* key, std::size_t limit) {
  std::vector<YAML::Node> items = root.sequence(key);
  if (items.size() > limit)
    io::fail_at(io::mark_of(items[limit], root.file()),
                fmt::format("'{}': expected at most {} entries (docs/cli.md, Limits), found {}", key, limit,
                            items.size()));
  return items;
}

void read_members(io::MapReader& root, gt::TrainDescription& d, std::vector<FieldMarks>& marks) {
  const std::vector<YAML::Node> items = limited_sequence(root, "members", io::limits::kTrainMembers);
  // The ground is implicit: a train of nothing but the ground has nothing to turn.
  if (items.empty()) io::fail_at(root.mark("members"), "'members': expected at least one member, found none");
  for (const YAML::Node& item : items) {
    gt::MemberSpec spec;
    if (item.IsScalar()) {
      spec.name = member_name(item, root.file(), "a member name");
      marks.push_back(FieldMarks{{"", io::mark_of(item, root.file())}});
    } else {
      io::MapReader r(item, root.file(), "member");
      spec.name = member_name(r.node("name"), root.file(), "a member name");
      if (r.has("carried_by")) spec.carried_by = r.string("carried_by");
      if (const auto count = r.optional_integer("count")) {
        if (*count < 1 || *count > 1000)
          io::fail_at(r.mark("count"), fmt::format("'count': expected a planet count from 1 to 1000, found {}", *count));
        spec.planet_count = static_cast<int>(*count);
      }
      r.finish();
      marks.push_back(marks_of(r, {"name", "carried_by", "count"}));
    }
    d.members.push_back(spec);
  }
}

// What a gear without its own pressure or helix angle takes: the file's top-level
// `pressure_angle` and `helix_angle`, else 20 deg and 0 (spur).
struct GearDefaults {
  double alpha_n = gt::standard_pressure_angle;
  double beta = 0.0;
};

GearDefaults read_gear_defaults(io::MapReader& root) {
  GearDefaults defaults;
  defaults.alpha_n = root.quantity_or("pressure_angle", io::Quantity::angle, "deg", defaults.alpha_n);
  defaults.beta = root.quantity_or("helix_angle", io::Quantity::angle, "deg", defaults.beta);
  return defaults;
}

void read_gears(io::MapReader& root, gt::TrainDescription& d, std::vector<FieldMarks>& marks) {
  const GearDefaults defaults = read_gear_defaults(root);
  const io::SourceMark root_alpha = root.mark("pressure_angle"), root_beta = root.mark("helix_angle");
  for (const YAML::Node& item : limited_sequence(root, "gears", io::limits::kTrainGears)) {
    io::MapReader r(item, root.file(), "gear");
    gt::GearSpec spec;
    spec.name = r.string("name");
    spec.member = r.string("member");
    const long long z = r.integer("z");
    if (z > max_teeth || z < -max_teeth)
      io::fail_at(r.mark("z"), fmt::format("'z': expected a tooth count from 1 to {}, found {}", max_teeth, z));
    spec.z = static_cast<int>(z);
    spec.kind = r.choice("type", {"external", "internal"}, "external") == "internal" ? gt::GearKind::internal
                                                                                      : gt::GearKind::external;
    if (const auto m = r.optional_quantity("module", io::Quantity::length, "mm")) spec.module_mm = *m * 1000.0;
    if (const auto x = r.optional_number("x")) spec.x = *x;
    spec.alpha_n = r.quantity_or("pressure_angle", io::Quantity::angle, "deg", defaults.alpha_n);
    spec.beta = r.quantity_or("helix_angle", io::Quantity::angle, "deg", defaults.beta);
    r.optional_node("face_width");  // read by `train --rate` (train_rating.cpp)
    r.optional_node("material");
    r.finish();
    FieldMarks gear_marks = marks_of(r, {"name", "member", "z", "module"});
    // A bad inherited angle is placed at the top-level key it came from.
    gear_marks["pressure_angle"] = r.has("pressure_angle") ? r.mark("pressure_angle") : root_alpha;
    gear_marks["helix_angle"] = r.has("helix_angle") ? r.mark("helix_angle") : root_beta;
    marks.push_back(std::move(gear_marks));
    d.gears.push_back(spec);
  }
}

void read_meshes(io::MapReader& root, gt::TrainDescription& d, std::vector<FieldMarks>& marks,
                 double default_efficiency) {
  for (const YAML::Node& item : limited_sequence(root, "meshes", io::limits::kTrainMeshes)) {
    io::MapReader r(item, root.file(), "mesh");
    gt::MeshSpec spec;
    if (const auto name = r.optional_string("name")) spec.name = *name;
    const YAML::Node gears = r.node("gears");
    if (!gears.IsSequence() || gears.size() != 2)
      io::fail_at(r.mark("gears"), "'gears': expected a list of two gear names, e.g. [s, p]");
    spec.gear_a = io::scalar_text(gears[0], root.file(), "a gear name");
    spec.gear_b = io::scalar_text(gears[1], root.file(), "a gear name");
    if (r.has("carrier")) spec.carrier = r.string("carrier");
    spec.efficiency = r.optional_number("efficiency").value_or(default_efficiency);
    r.optional_node("rating");  // read by `train --rate` (train_rating.cpp)
    r.finish();
    marks.push_back(marks_of(r, {"gears", "carrier", "efficiency"}));
    d.meshes.push_back(spec);
  }
}

std::vector<WrittenCondition> read_list(io::MapReader& r, const std::string& key) {
  std::vector<WrittenCondition> list;
  if (!r.has(key)) return list;
  YAML::Node node = r.node(key);
  if (node.IsScalar()) {
    list.push_back({node.Scalar(), io::mark_of(node, r.file())});
    return list;
  }
  for (const YAML::Node& item : r.sequence(key))
    list.push_back({io::scalar_text(item, r.file(), fmt::format("a condition in '{}'", key)), io::mark_of(item, r.file())});
  return list;
}

FileAnalysis read_analysis(io::MapReader& root) {
  FileAnalysis a;
  if (!root.has("analysis")) return a;
  io::MapReader r = root.map("analysis");
  a.fix = read_list(r, "fix");
  a.couple = read_list(r, "couple");
  a.input = read_list(r, "input");
  if (r.has("output")) a.output = WrittenCondition{r.string("output"), r.mark("output")};
  r.finish();
  return a;
}

}  // namespace

TrainFile load_train_file(const std::string& path, double default_efficiency) {
  const io::YamlDocument doc = io::load_yaml_file(path);
  io::MapReader root(doc.root, doc.file, "train");
  gt::TrainDescription d;
  d.name = root.optional_string("name").value_or("");
  root.optional_string("description");
  std::vector<FieldMarks> member_marks, gear_marks, mesh_marks;
  read_members(root, d, member_marks);
  read_gears(root, d, gear_marks);
  read_meshes(root, d, mesh_marks, default_efficiency);
  FileAnalysis analysis = read_analysis(root);
  root.optional_node("rating");  // read by `train --rate` (train_rating.cpp)
  root.finish();
  try {
    return TrainFile{gt::make_train_model(d), std::move(analysis)};
  } catch (const gt::ModelError& e) {
    const auto& marks = e.item() == gt::ModelError::Item::member ? member_marks
                        : e.item() == gt::ModelError::Item::gear ? gear_marks
                                                                  : mesh_marks;
    const FieldMarks& entry = marks.at(e.index());
    const auto field = entry.find(e.field());
    io::fail_at(field != entry.end() ? field->second : entry.at(""), e.what());
  }
}

}  // namespace gearkit::plugins::train
