#pragma once
// Trains used by several test files, built from the references they reproduce.
#include <gearkit/train/kinematics.hpp>
#include <gearkit/train/model.hpp>

#include <string>

namespace gearkit::train::testing {

inline GearSpec gear(std::string name, std::string member, int z, GearKind kind = GearKind::external) {
  GearSpec g;
  g.name = std::move(name);
  g.member = std::move(member);
  g.z = z;
  g.kind = kind;
  return g;
}

inline MeshSpec mesh(std::string a, std::string b, std::string carrier = "ground", double efficiency = 1.0) {
  MeshSpec m;
  m.gear_a = std::move(a);
  m.gear_b = std::move(b);
  m.carrier = std::move(carrier);
  m.efficiency = efficiency;
  return m;
}

inline MemberSpec member(std::string name, std::string carried_by = "ground", int count = 1) {
  return MemberSpec{std::move(name), std::move(carried_by), count};
}

/// Simple planetary: sun, carrier, planet (on carrier), ring.
inline TrainDescription simple_planetary(int z_sun, int z_planet, int z_ring, double eta_sp = 1.0,
                                         double eta_pr = 1.0, int planets = 1) {
  TrainDescription d;
  d.name = "simple planetary";
  d.members = {member("sun"), member("carrier"), member("planet", "carrier", planets), member("ring")};
  d.gears = {gear("s", "sun", z_sun), gear("p", "planet", z_planet), gear("r", "ring", z_ring, GearKind::internal)};
  d.meshes = {mesh("s", "p", "carrier", eta_sp), mesh("p", "r", "carrier", eta_pr)};
  return d;
}

/// Seed 004_b4a8ce5a956e12a3.txt, 2020-21 exam, exercise 2 (CVT train): z1 = 35, z2 = 90 on
/// fixed axes; epicyclic 3-4-5 on arm b with z3/z5 = 1/3 (only the ratio is given; 20/20/60 chosen).
inline TrainDescription seed_cvt_train() {
  TrainDescription d;
  d.members = {member("1"), member("23"), member("b"), member("4", "b"), member("5")};
  d.gears = {gear("z1", "1", 35), gear("z2", "23", 90), gear("z3", "23", 20), gear("z4", "4", 20),
             gear("z5", "5", 60, GearKind::internal)};
  d.meshes = {mesh("z1", "z2"), mesh("z3", "z4", "b"), mesh("z4", "z5", "b")};
  return d;
}

/// Seed 004_b4a8ce5a956e12a3.txt, second 2020-21 exam, exercise 1: z1..z7 = 48, 24, 18, 90, 84, 30, 24.
inline TrainDescription seed_two_epicyclic_stages() {
  TrainDescription d;
  d.members = {member("1"), member("b"), member("45"), member("7"), member("23", "b"), member("6", "b")};
  d.gears = {gear("z1", "1", 48), gear("z2", "23", 24), gear("z3", "23", 18),
             gear("z4", "45", 90, GearKind::internal), gear("z5", "45", 84, GearKind::internal),
             gear("z6", "6", 30), gear("z7", "7", 24)};
  d.meshes = {mesh("z1", "z2", "b"), mesh("z3", "z4", "b"), mesh("z5", "z6", "b"), mesh("z6", "z7", "b")};
  return d;
}

inline MemberId id(const TrainModel& model, const std::string& name) { return model.find_member(name).value(); }

inline Condition fix(const TrainModel& model, const std::string& name) {
  return Condition{Condition::Kind::fix, id(model, name), ground, "fix " + name};
}
inline Condition input(const TrainModel& model, const std::string& name) {
  return Condition{Condition::Kind::input, id(model, name), ground, "input " + name};
}
inline Condition couple(const TrainModel& model, const std::string& a, const std::string& b) {
  return Condition{Condition::Kind::couple, id(model, a), id(model, b), "couple " + a + "=" + b};
}

}  // namespace gearkit::train::testing
