#include <gearkit/train/model.hpp>

#include <fmt/format.h>

#include <map>

namespace gearkit::train {

ModelError::ModelError(Item item, std::size_t index, std::string field, const std::string& message)
    : std::runtime_error(message), item_(item), index_(index), field_(std::move(field)) {}
ModelError::~ModelError() = default;

std::optional<MemberId> TrainModel::find_member(const std::string& name) const {
  for (MemberId i = 0; i < members_.size(); ++i)
    if (members_[i].name == name) return i;
  return std::nullopt;
}

namespace {

using Item = ModelError::Item;

// A gear of a mesh is held by the mesh's carrier when it turns on a planet axis of that carrier,
// on the carrier itself, or on a member coaxial with the carrier (a sun or ring).
bool held_by(const std::vector<Member>& members, MemberId member, MemberId carrier) {
  if (member == carrier) return true;
  if (members[member].carried_by == carrier) return true;
  return members[member].carried_by == members[carrier].carried_by;
}

bool on_planet_of(const std::vector<Member>& members, MemberId member, MemberId carrier) {
  return member != ground && members[member].carried_by == carrier;
}

void resolve_members(const TrainDescription& d, std::vector<Member>& members, std::map<std::string, MemberId>& index) {
  members.push_back(Member{"ground", ground, 1});
  index["ground"] = ground;
  for (std::size_t i = 0; i < d.members.size(); ++i) {
    const MemberSpec& spec = d.members[i];
    if (spec.name.empty()) throw ModelError(Item::member, i, "name", "member has an empty name");
    if (spec.name == "ground")
      throw ModelError(Item::member, i, "name", "member 'ground' is implicit (the frame); do not declare it");
    if (index.count(spec.name))
      throw ModelError(Item::member, i, "name", fmt::format("member '{}' is declared twice", spec.name));
    if (spec.planet_count < 1)
      throw ModelError(Item::member, i, "count",
                       fmt::format("member '{}': expected a planet count >= 1, found {}", spec.name, spec.planet_count));
    index[spec.name] = members.size();
    members.push_back(Member{spec.name, ground, spec.planet_count});
  }
  for (std::size_t i = 0; i < d.members.size(); ++i) {
    const MemberSpec& spec = d.members[i];
    const auto it = index.find(spec.carried_by);
    if (it == index.end())
      throw ModelError(Item::member, i, "carried_by",
                       fmt::format("member '{}' is carried by unknown member '{}'", spec.name, spec.carried_by));
    if (it->second == i + 1)
      throw ModelError(Item::member, i, "carried_by", fmt::format("member '{}' cannot carry itself", spec.name));
    members[i + 1].carried_by = it->second;
  }
  // An axis chain must end at the frame.
  for (std::size_t i = 1; i < members.size(); ++i) {
    MemberId m = i;
    for (std::size_t steps = 0; m != ground; ++steps) {
      if (steps > members.size())
        throw ModelError(Item::member, i - 1, "carried_by",
                         fmt::format("member '{}': the chain of 'carried_by' loops and never reaches ground",
                                     members[i].name));
      m = members[m].carried_by;
    }
  }
}

}  // namespace

TrainModel make_train_model(const TrainDescription& d) {
  TrainModel model;
  model.name_ = d.name;
  std::map<std::string, MemberId> member_index;
  resolve_members(d, model.members_, member_index);
  const auto& members = model.members_;

  std::map<std::string, GearId> gear_index;
  for (std::size_t i = 0; i < d.gears.size(); ++i) {
    const GearSpec& spec = d.gears[i];
    if (spec.name.empty()) throw ModelError(Item::gear, i, "name", "gear has an empty name");
    if (gear_index.count(spec.name))
      throw ModelError(Item::gear, i, "name", fmt::format("gear '{}' is declared twice", spec.name));
    const auto m = member_index.find(spec.member);
    if (m == member_index.end())
      throw ModelError(Item::gear, i, "member",
                       fmt::format("gear '{}' is on unknown member '{}'", spec.name, spec.member));
    if (spec.z <= 0)
      throw ModelError(Item::gear, i, "z",
                       fmt::format("gear '{}': expected a tooth count z > 0, found {}", spec.name, spec.z));
    if (spec.module_mm && !(*spec.module_mm > 0))
      throw ModelError(Item::gear, i, "module",
                       fmt::format("gear '{}': expected a module > 0, found {}", spec.name, *spec.module_mm));
    gear_index[spec.name] = model.gears_.size();
    model.gears_.push_back(Gear{spec.name, m->second, spec.z, spec.kind, spec.module_mm, spec.x});
  }

  for (std::size_t i = 0; i < d.meshes.size(); ++i) {
    const MeshSpec& spec = d.meshes[i];
    const std::string name = spec.name.empty() ? spec.gear_a + "-" + spec.gear_b : spec.name;
    const auto a = gear_index.find(spec.gear_a);
    const auto b = gear_index.find(spec.gear_b);
    if (a == gear_index.end())
      throw ModelError(Item::mesh, i, "gears", fmt::format("mesh '{}' names unknown gear '{}'", name, spec.gear_a));
    if (b == gear_index.end())
      throw ModelError(Item::mesh, i, "gears", fmt::format("mesh '{}' names unknown gear '{}'", name, spec.gear_b));
    if (a->second == b->second)
      throw ModelError(Item::mesh, i, "gears", fmt::format("mesh '{}' names gear '{}' twice", name, spec.gear_a));
    const Gear& ga = model.gears_[a->second];
    const Gear& gb = model.gears_[b->second];
    if (ga.member == gb.member)
      throw ModelError(Item::mesh, i, "gears",
                       fmt::format("mesh '{}': gears '{}' and '{}' are both on member '{}' and cannot mesh", name,
                                   ga.name, gb.name, members[ga.member].name));
    if (ga.kind == GearKind::internal && gb.kind == GearKind::internal)
      throw ModelError(Item::mesh, i, "gears",
                       fmt::format("mesh '{}': gears '{}' and '{}' are both internal; an internal gear meshes only "
                                   "with an external one", name, ga.name, gb.name));
    const auto c = member_index.find(spec.carrier);
    if (c == member_index.end())
      throw ModelError(Item::mesh, i, "carrier",
                       fmt::format("mesh '{}': carrier '{}' is not a member", name, spec.carrier));
    const MemberId carrier = c->second;
    for (const Gear* g : {&ga, &gb})
      if (!held_by(members, g->member, carrier))
        throw ModelError(
            Item::mesh, i, "carrier",
            fmt::format("mesh '{}': gear '{}' is on member '{}', whose axis is carried by '{}', not by the mesh "
                        "carrier '{}' nor coaxial with it", name, g->name, members[g->member].name,
                        members[members[g->member].carried_by].name, spec.carrier));
    if (carrier != ground && !on_planet_of(members, ga.member, carrier) && !on_planet_of(members, gb.member, carrier))
      throw ModelError(Item::mesh, i, "carrier",
                       fmt::format("mesh '{}': neither '{}' nor '{}' is a planet of carrier '{}' (declare the planet "
                                   "member with 'carried_by: {}')", name, members[ga.member].name,
                                   members[gb.member].name, spec.carrier, spec.carrier));
    if (!(spec.efficiency > 0 && spec.efficiency <= 1))
      throw ModelError(Item::mesh, i, "efficiency",
                       fmt::format("mesh '{}': expected an efficiency in (0, 1], found {}", name, spec.efficiency));
    model.meshes_.push_back(Mesh{name, a->second, b->second, carrier, spec.efficiency});
  }
  return model;
}

}  // namespace gearkit::train
