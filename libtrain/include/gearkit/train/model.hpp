#pragma once
// The immutable description of a gear train as a graph: members (rigid bodies turning about
// their own axis; `ground` always exists as member 0), gears fixed to members, and meshes (a pair
// of gears plus the member that carries both axes: ground for fixed axes, an arm for planets).
// Nothing here is specific to one train type; analyses are free functions in other headers.
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace gearkit::train {

using MemberId = std::size_t;
using GearId = std::size_t;
using MeshId = std::size_t;

/// Index of the frame. Its speed is zero by definition.
inline constexpr MemberId ground = 0;

struct Member {
  std::string name;
  MemberId carried_by = ground;  ///< member holding this member's axis: ground, or the arm of a planet
  int planet_count = 1;          ///< identical planets equally spaced around the arm (assembly checks)
};

enum class GearKind { external, internal };

/// The standard normal pressure angle alpha_n = 20 deg (ISO 53 basic rack) [rad]: what a gear
/// without its own pressure angle has.
inline constexpr double standard_pressure_angle = 0.3490658503988659;

struct Gear {
  std::string name;
  MemberId member = ground;
  int z = 0;                             ///< number of teeth
  GearKind kind = GearKind::external;
  std::optional<double> module_mm;       ///< normal module m_n [mm], only for assembly checks
  double x = 0.0;                        ///< profile shift coefficient (ISO 21771), assembly checks
  double alpha_n = standard_pressure_angle;  ///< normal pressure angle [rad], in (0, 45 deg)
  /// Helix angle at the reference circle [rad], |beta| < 45 deg: positive for a right-hand
  /// helix, negative for a left-hand one, 0 for a spur gear (ISO 21771).
  double beta = 0.0;
};

struct Mesh {
  std::string name;
  GearId gear_a = 0;
  GearId gear_b = 0;
  MemberId carrier = ground;  ///< member holding both axes
  double efficiency = 1.0;    ///< basic mesh efficiency eta_0 with the carrier held still, in (0, 1]
};

/// What a description names, by name; resolved and checked by make_train_model().
struct MemberSpec {
  std::string name;
  std::string carried_by = "ground";
  int planet_count = 1;
};
struct GearSpec {
  std::string name;
  std::string member;
  int z = 0;
  GearKind kind = GearKind::external;
  std::optional<double> module_mm;
  double x = 0.0;
  double alpha_n = standard_pressure_angle;  ///< [rad]
  double beta = 0.0;                         ///< [rad], signed as in Gear
};
struct MeshSpec {
  std::string name;  ///< may be empty: then "<gear_a>-<gear_b>"
  std::string gear_a;
  std::string gear_b;
  std::string carrier = "ground";
  double efficiency = 1.0;
};
struct TrainDescription {
  std::string name;
  std::vector<MemberSpec> members;  ///< without ground (it is implicit)
  std::vector<GearSpec> gears;
  std::vector<MeshSpec> meshes;
};

/// A description that does not make a train. `item` and `index` locate the offending entry of
/// the description (index into members/gears/meshes) so a file reader can point at its line.
class ModelError : public std::runtime_error {
 public:
  enum class Item { member, gear, mesh };
  ModelError(Item item, std::size_t index, std::string field, const std::string& message);
  ~ModelError() override;
  Item item() const { return item_; }
  std::size_t index() const { return index_; }
  const std::string& field() const { return field_; }

 private:
  Item item_;
  std::size_t index_;
  std::string field_;
};

class TrainModel {
 public:
  const std::string& name() const { return name_; }
  const std::vector<Member>& members() const { return members_; }
  const std::vector<Gear>& gears() const { return gears_; }
  const std::vector<Mesh>& meshes() const { return meshes_; }
  const Member& member(MemberId id) const { return members_.at(id); }
  const Gear& gear(GearId id) const { return gears_.at(id); }
  const Mesh& mesh(MeshId id) const { return meshes_.at(id); }
  std::size_t member_count() const { return members_.size(); }

  /// The member called `name` ("ground" is member 0), or nullopt.
  std::optional<MemberId> find_member(const std::string& name) const;
  /// True for a planet: a member whose axis is carried by an arm, not by the frame.
  bool is_planet(MemberId id) const { return id != ground && members_[id].carried_by != ground; }

 private:
  friend TrainModel make_train_model(const TrainDescription& description);
  std::string name_;
  std::vector<Member> members_;
  std::vector<Gear> gears_;
  std::vector<Mesh> meshes_;
};

/// Resolves names and checks the description.
/// @throws ModelError for: an empty or repeated name, a member called "ground", a member carried
///   by an unknown member, by itself or by a planet of a planet chain that loops; planet_count < 1;
///   a gear on an unknown member; z <= 0; module <= 0; a pressure angle outside (0, 45 deg); a
///   helix angle with |beta| >= 45 deg; a mesh naming an unknown gear, the same gear
///   twice, two gears on the same member, two internal gears, an unknown carrier; a mesh whose
///   gears are not both held by its carrier (each gear must sit on a planet of that carrier or on a
///   member coaxial with it, and at least one on a planet; on ground both sit on fixed axes);
///   an efficiency outside (0, 1]; a mesh of gears with different pressure angles, or helix
///   angles that cannot mesh on parallel axes (an external pair needs opposite hands, beta_a =
///   -beta_b; an internal pair the same hand, beta_a = beta_b).
TrainModel make_train_model(const TrainDescription& description);

}  // namespace gearkit::train
