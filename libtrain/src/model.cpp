#include <gearkit/train/model.hpp>

#include <fmt/format.h>

#include <cmath>
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

constexpr double kDeg = 0.017453292519943295;  // rad per degree

void check_gear(const GearSpec& spec, std::size_t i) {
  if (spec.z <= 0)
    throw ModelError(Item::gear, i, "z", fmt::format("gear '{}': expected a tooth count z > 0, found {}", spec.name, spec.z));
  if (spec.module_mm && !(*spec.module_mm > 0))
    throw ModelError(Item::gear, i, "module",
                     fmt::format("gear '{}': expected a module > 0, found {}", spec.name, *spec.module_mm));
  if (!(spec.alpha_n > 0 && spec.alpha_n < 45 * kDeg))
    throw ModelError(Item::gear, i, "pressure_angle",
                     fmt::format("gear '{}': expected a pressure angle in (0, 45) deg, found {:g} deg", spec.name,
                                 spec.alpha_n / kDeg));
  if (!(std::abs(spec.beta) < 45 * kDeg))
    throw ModelError(Item::gear, i, "helix_angle",
                     fmt::format("gear '{}': expected a helix angle in (-45, 45) deg, found {:g} deg", spec.name,
                                 spec.beta / kDeg));
}

std::vector<Gear> resolve_gears(const TrainDescription& d, const std::map<std::string, MemberId>& member_index,
                                std::map<std::string, GearId>& gear_index) {
  std::vector<Gear> gears;
  for (std::size_t i = 0; i < d.gears.size(); ++i) {
    const GearSpec& spec = d.gears[i];
    if (spec.name.empty()) throw ModelError(Item::gear, i, "name", "gear has an empty name");
    if (gear_index.count(spec.name))
      throw ModelError(Item::gear, i, "name", fmt::format("gear '{}' is declared twice", spec.name));
    const auto m = member_index.find(spec.member);
    if (m == member_index.end())
      throw ModelError(Item::gear, i, "member",
                       fmt::format("gear '{}' is on unknown member '{}'", spec.name, spec.member));
    check_gear(spec, i);
    gear_index[spec.name] = gears.size();
    gears.push_back(Gear{spec.name, m->second, spec.z, spec.kind, spec.module_mm, spec.x, spec.alpha_n, spec.beta});
  }
  return gears;
}

// Two involute gears mesh on parallel axes only with equal normal base pitches (the same normal
// pressure angle for a common module) and matching helices: opposite hands for an external
// pair, the same hand for an internal one (ISO 21771).
void check_mesh_geometry(const std::string& name, const Gear& ga, const Gear& gb, std::size_t i) {
  if (std::abs(ga.alpha_n - gb.alpha_n) > 1e-12)
    throw ModelError(Item::mesh, i, "gears",
                     fmt::format("mesh '{}': gears '{}' and '{}' have pressure angles {:g} deg and {:g} deg; meshing "
                                 "gears need the same one", name, ga.name, gb.name, ga.alpha_n / kDeg, gb.alpha_n / kDeg));
  const bool internal = ga.kind == GearKind::internal || gb.kind == GearKind::internal;
  const double mismatch = internal ? ga.beta - gb.beta : ga.beta + gb.beta;
  if (std::abs(mismatch) > 1e-12)
    throw ModelError(Item::mesh, i, "gears",
                     fmt::format("mesh '{}': gears '{}' and '{}' have helix angles {:g} deg and {:g} deg; {}", name,
                                 ga.name, gb.name, ga.beta / kDeg, gb.beta / kDeg,
                                 internal ? "an internal pair needs the same helix angle (same hand)"
                                          : "an external pair needs opposite helix angles (one right-hand, one left-hand)"));
}

void check_mesh_gears(const std::string& name, const Gear& ga, const Gear& gb, const std::vector<Member>& members,
                      std::size_t i) {
  if (ga.member == gb.member)
    throw ModelError(Item::mesh, i, "gears",
                     fmt::format("mesh '{}': gears '{}' and '{}' are both on member '{}' and cannot mesh", name,
                                 ga.name, gb.name, members[ga.member].name));
  if (ga.kind == GearKind::internal && gb.kind == GearKind::internal)
    throw ModelError(Item::mesh, i, "gears",
                     fmt::format("mesh '{}': gears '{}' and '{}' are both internal; an internal gear meshes only "
                                 "with an external one", name, ga.name, gb.name));
  check_mesh_geometry(name, ga, gb, i);
}

void check_mesh_carrier(const std::string& name, const Gear& ga, const Gear& gb, const std::vector<Member>& members,
                        MemberId carrier, std::size_t i) {
  for (const Gear* g : {&ga, &gb})
    if (!held_by(members, g->member, carrier))
      throw ModelError(
          Item::mesh, i, "carrier",
          fmt::format("mesh '{}': gear '{}' is on member '{}', whose axis is carried by '{}', not by the mesh "
                      "carrier '{}' nor coaxial with it", name, g->name, members[g->member].name,
                      members[members[g->member].carried_by].name, members[carrier].name));
  if (carrier != ground && !on_planet_of(members, ga.member, carrier) && !on_planet_of(members, gb.member, carrier))
    throw ModelError(Item::mesh, i, "carrier",
                     fmt::format("mesh '{}': neither '{}' nor '{}' is a planet of carrier '{}' (declare the planet "
                                 "member with 'carried_by: {}')", name, members[ga.member].name,
                                 members[gb.member].name, members[carrier].name, members[carrier].name));
}

Mesh resolve_mesh(const MeshSpec& spec, std::size_t i, const std::vector<Member>& members,
                  const std::map<std::string, MemberId>& member_index, const std::vector<Gear>& gears,
                  const std::map<std::string, GearId>& gear_index) {
  const std::string name = spec.name.empty() ? spec.gear_a + "-" + spec.gear_b : spec.name;
  const auto a = gear_index.find(spec.gear_a);
  const auto b = gear_index.find(spec.gear_b);
  if (a == gear_index.end())
    throw ModelError(Item::mesh, i, "gears", fmt::format("mesh '{}' names unknown gear '{}'", name, spec.gear_a));
  if (b == gear_index.end())
    throw ModelError(Item::mesh, i, "gears", fmt::format("mesh '{}' names unknown gear '{}'", name, spec.gear_b));
  if (a->second == b->second)
    throw ModelError(Item::mesh, i, "gears", fmt::format("mesh '{}' names gear '{}' twice", name, spec.gear_a));
  const Gear& ga = gears[a->second];
  const Gear& gb = gears[b->second];
  check_mesh_gears(name, ga, gb, members, i);
  const auto c = member_index.find(spec.carrier);
  if (c == member_index.end())
    throw ModelError(Item::mesh, i, "carrier", fmt::format("mesh '{}': carrier '{}' is not a member", name, spec.carrier));
  check_mesh_carrier(name, ga, gb, members, c->second, i);
  if (!(spec.efficiency > 0 && spec.efficiency <= 1))
    throw ModelError(Item::mesh, i, "efficiency",
                     fmt::format("mesh '{}': expected an efficiency in (0, 1], found {}", name, spec.efficiency));
  return Mesh{name, a->second, b->second, c->second, spec.efficiency};
}

}  // namespace

TrainModel make_train_model(const TrainDescription& d) {
  TrainModel model;
  model.name_ = d.name;
  std::map<std::string, MemberId> member_index;
  resolve_members(d, model.members_, member_index);
  std::map<std::string, GearId> gear_index;
  model.gears_ = resolve_gears(d, member_index, gear_index);
  for (std::size_t i = 0; i < d.meshes.size(); ++i)
    model.meshes_.push_back(resolve_mesh(d.meshes[i], i, model.members_, member_index, model.gears_, gear_index));
  return model;
}

}  // namespace gearkit::train
