#include <gearkit/train/willis.hpp>

#include <fmt/format.h>

#include <map>

namespace gearkit::train {

int basic_ratio_sign(const Gear& a, const Gear& b) {
  return (a.kind == GearKind::internal || b.kind == GearKind::internal) ? +1 : -1;
}

Rational basic_ratio(const TrainModel& model, MeshId mesh) {
  const Mesh& m = model.mesh(mesh);
  const Gear& a = model.gear(m.gear_a);
  const Gear& b = model.gear(m.gear_b);
  return Rational(basic_ratio_sign(a, b) * a.z, b.z);
}

WillisCoefficients willis_coefficients(const TrainModel& model, MeshId mesh) {
  const Mesh& m = model.mesh(mesh);
  const Gear& a = model.gear(m.gear_a);
  const Gear& b = model.gear(m.gear_b);
  const long long s = basic_ratio_sign(a, b);
  WillisCoefficients c;
  c.on_a = -s * a.z;
  c.on_b = b.z;
  c.on_carrier = s * a.z - b.z;
  return c;
}

std::vector<std::pair<MemberId, long long>> willis_row(const TrainModel& model, MeshId mesh) {
  const Mesh& m = model.mesh(mesh);
  const WillisCoefficients c = willis_coefficients(model, mesh);
  std::map<MemberId, long long> merged;
  merged[model.gear(m.gear_a).member] += c.on_a;
  merged[model.gear(m.gear_b).member] += c.on_b;
  merged[m.carrier] += c.on_carrier;
  std::vector<std::pair<MemberId, long long>> row;
  for (const auto& [member, coefficient] : merged)
    if (coefficient != 0) row.emplace_back(member, coefficient);
  return row;
}

namespace {

std::string speed(const TrainModel& model, MemberId member) { return "w_" + model.member(member).name; }

std::string relative(const TrainModel& model, MemberId member, MemberId carrier) {
  if (carrier == ground) return speed(model, member);
  return fmt::format("({} - {})", speed(model, member), speed(model, carrier));
}

}  // namespace

std::string willis_equation_text(const TrainModel& model, MeshId mesh) {
  const Mesh& m = model.mesh(mesh);
  const Gear& a = model.gear(m.gear_a);
  const Gear& b = model.gear(m.gear_b);
  const char sign = basic_ratio_sign(a, b) < 0 ? '-' : '+';
  return fmt::format("{} / {} = {}{}/{}", relative(model, b.member, m.carrier), relative(model, a.member, m.carrier),
                     sign, a.z, b.z);
}

std::string willis_linear_text(const TrainModel& model, MeshId mesh) {
  const Mesh& m = model.mesh(mesh);
  const Gear& a = model.gear(m.gear_a);
  const Gear& b = model.gear(m.gear_b);
  const char sign = basic_ratio_sign(a, b) < 0 ? '+' : '-';
  return fmt::format("{}·{} {} {}·{} = 0", b.z, relative(model, b.member, m.carrier), sign, a.z,
                     relative(model, a.member, m.carrier));
}

}  // namespace gearkit::train
