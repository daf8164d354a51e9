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

nlohmann::json reaction_json(const kin::Model& model, const kin::ConstraintReaction& r) {
  nlohmann::json j;
  j["joint"] = r.name;
  j["kind"] = r.kind;
  j["on"] = model.body_name(r.body);
  j["force_N"] = {r.force.x(), r.force.y()};
  if (r.moment != 0.0 || r.kind == "prismatic") j["moment_Nm"] = r.moment;
  if (!r.values.empty()) {
    nlohmann::json values = nlohmann::json::object();
    for (const kin::ReactionValue& v : r.values) values[key_with_unit(v)] = v.value;
    j["values"] = values;
  }
  return j;
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
