#include "kin_reactions.hpp"

#include <string>

namespace gearkit::cli {

namespace {

// A JSON key carries its unit: "F_n" in "N" -> "F_n_N", "T_2" in "N m" -> "T_2_Nm".
std::string key_with_unit(const kin::ReactionValue& v) {
  std::string unit;
  for (char c : v.unit)
    if (c != ' ' && c != '*') unit += c;
  return unit.empty() ? v.symbol : v.symbol + "_" + unit;
}

}  // namespace

void write_reaction(io::JsonWriter& w, const kin::Model& model, const kin::ConstraintReaction& r) {
  w.begin_object();
  w.key("joint");
  w.value(r.name);
  w.key("kind");
  w.value(r.kind);
  w.key("on");
  w.value(model.body_name(r.body));
  w.key("force_N");
  w.begin_array();
  w.value(r.force.x());
  w.value(r.force.y());
  w.end_array();
  if (r.moment != 0.0 || r.kind == "prismatic") {
    w.key("moment_Nm");
    w.value(r.moment);
  }
  if (!r.values.empty()) {
    w.key("values");
    w.begin_object();
    for (const kin::ReactionValue& v : r.values) {
      w.key(key_with_unit(v));
      w.value(v.value);
    }
    w.end_object();
  }
  w.end_object();
}

std::optional<io::Table> element_reaction_table(const kin::ForceAnalysis& forces) {
  io::Table t{"Element reactions", {"element", "kind", "quantity", "value", "unit", "meaning"}, {}};
  for (const kin::ConstraintReaction& r : forces.reactions)
    for (const kin::ReactionValue& v : r.values)
      t.add_row({r.name, r.kind, v.symbol, io::fixed(v.value, 3), v.unit, v.description});
  if (t.rows.empty()) return std::nullopt;
  return t;
}

}  // namespace gearkit::cli
