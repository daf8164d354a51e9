#include <gearkit/train/stage_relations.hpp>

#include <gearkit/train/linear_system.hpp>
#include <gearkit/train/willis.hpp>

#include <algorithm>
#include <numeric>
#include <optional>

namespace gearkit::train {

namespace {

std::size_t find_root(std::vector<std::size_t>& parent, std::size_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

// Meshes grouped into stages: two meshes sharing a planet belong together.
std::vector<std::vector<MeshId>> stages_of(const TrainModel& model) {
  const std::size_t n = model.meshes().size();
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<std::optional<std::size_t>> first_mesh_of_planet(model.member_count());
  for (MeshId k = 0; k < n; ++k)
    for (GearId g : {model.mesh(k).gear_a, model.mesh(k).gear_b}) {
      const MemberId m = model.gear(g).member;
      if (!model.is_planet(m)) continue;
      if (first_mesh_of_planet[m]) parent[find_root(parent, k)] = find_root(parent, *first_mesh_of_planet[m]);
      else first_mesh_of_planet[m] = k;
    }
  std::vector<std::vector<MeshId>> stages;
  std::vector<std::optional<std::size_t>> index(n);
  for (MeshId k = 0; k < n; ++k) {
    const std::size_t r = find_root(parent, k);
    if (!index[r]) {
      index[r] = stages.size();
      stages.emplace_back();
    }
    stages[*index[r]].push_back(k);
  }
  return stages;
}

// w_out as a combination of the stage's other central members and its arm, planets eliminated.
SparseRow output_in_terms_of_the_others(const TrainModel& model, const std::vector<MeshId>& meshes, MemberId output) {
  std::vector<long long> preference(model.member_count(), 0);
  for (MemberId m = 0; m < model.member_count(); ++m)
    if (model.is_planet(m)) preference[m] = 2;
  preference[output] = 1;
  EchelonSystem system(model.member_count(), 0, preference);
  system.add_row({{ground, Rational(1)}});  // the ground does not turn
  for (MeshId k : meshes) {
    SparseRow row;
    for (const auto& [member, coefficient] : willis_row(model, k)) row.emplace_back(member, Rational(coefficient));
    system.add_row(row);
  }
  return system.solve()[output];
}

}  // namespace

std::vector<StageRelation> stage_relations(const TrainModel& model, const std::vector<MemberId>& order) {
  auto rank = [&order](MemberId m) {
    const auto it = std::find(order.begin(), order.end(), m);
    return it == order.end() ? order.size() + m : static_cast<std::size_t>(it - order.begin());
  };
  std::vector<StageRelation> out;
  for (const std::vector<MeshId>& meshes : stages_of(model)) {
    const MemberId arm = model.mesh(meshes.front()).carrier;
    std::vector<MemberId> central;
    for (MeshId k : meshes)
      for (GearId g : {model.mesh(k).gear_a, model.mesh(k).gear_b}) {
        const MemberId m = model.gear(g).member;
        if (!model.is_planet(m) && m != arm && std::find(central.begin(), central.end(), m) == central.end())
          central.push_back(m);
      }
    std::sort(central.begin(), central.end(), [&rank](MemberId a, MemberId b) { return rank(a) < rank(b); });
    for (std::size_t i = 1; i < central.size(); ++i) {
      StageRelation r{central[0], central[i], arm, Rational(0), meshes};
      for (const auto& [member, coefficient] : output_in_terms_of_the_others(model, meshes, central[i]))
        if (member == central[0]) r.tau = coefficient;
      out.push_back(r);
    }
  }
  return out;
}

std::string stage_relation_text(const TrainModel& model, const StageRelation& r) {
  std::string text;
  auto term = [&](const Rational& c, MemberId m) {
    if (c == 0) return;
    const bool negative = c < 0;
    const Rational a = negative ? Rational(-c) : c;
    text += text.empty() ? (negative ? "-" : "") : (negative ? " - " : " + ");
    if (a != 1) text += to_fraction_string(a) + " ";
    text += "w_" + model.member(m).name;
  };
  term(r.tau, r.input);
  if (r.arm != ground) term(Rational(1) - r.tau, r.arm);
  term(Rational(-1), r.output);
  return text + " = 0";
}

}  // namespace gearkit::train
