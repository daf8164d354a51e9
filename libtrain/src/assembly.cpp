#include <gearkit/train/assembly.hpp>
#include <gearkit/train/rational.hpp>
#include <gearkit/train/willis.hpp>

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <numeric>

namespace gearkit::train {

namespace {

// |z_a + z_b| for an external pair, z_int - z_ext with an internal gear.
double teeth_in_centre_distance(const Gear& a, const Gear& b) {
  const bool internal = a.kind == GearKind::internal || b.kind == GearKind::internal;
  return internal ? std::abs(a.z - b.z) : a.z + b.z;
}

}  // namespace

std::optional<double> reference_centre_distance(const Gear& a, const Gear& b) {
  if (!a.module_mm || !b.module_mm || *a.module_mm != *b.module_mm) return std::nullopt;
  if (a.x != 0.0 || b.x != 0.0) return std::nullopt;
  return *a.module_mm * teeth_in_centre_distance(a, b) / (2.0 * std::cos(a.beta));
}

namespace {

// A mesh between a planet gear and a central (coaxial) gear of the same carrier.
struct CentralMesh {
  MeshId mesh;
  GearId planet_gear;
  GearId central_gear;
};

struct Distance {
  std::optional<double> value;
  bool in_modules = false;
};

Distance distance_of(const Gear& a, const Gear& b, const CentreDistanceFunction& centre_distance) {
  if (!a.module_mm && !b.module_mm) {
    if (a.x != 0.0 || b.x != 0.0) return {};
    return {teeth_in_centre_distance(a, b) / (2.0 * std::cos(a.beta)), true};
  }
  return {centre_distance(a, b), false};
}

// Lengths without modules are multiples of the (assumed common) module m.
std::string unit(bool in_modules) { return in_modules ? "·m" : " mm"; }

std::vector<CentralMesh> central_meshes(const TrainModel& model, MemberId planet) {
  const MemberId carrier = model.member(planet).carried_by;
  std::vector<CentralMesh> result;
  for (MeshId k = 0; k < model.meshes().size(); ++k) {
    const Mesh& mesh = model.mesh(k);
    if (mesh.carrier != carrier) continue;
    const GearId a = mesh.gear_a, b = mesh.gear_b;
    const MemberId ma = model.gear(a).member, mb = model.gear(b).member;
    const auto central = [&](MemberId m) { return !model.is_planet(m) && m != carrier; };
    if (ma == planet && central(mb)) result.push_back({k, a, b});
    if (mb == planet && central(ma)) result.push_back({k, b, a});
  }
  return result;
}

bool has_planet_planet_mesh(const TrainModel& model, MemberId planet) {
  for (const Mesh& mesh : model.meshes()) {
    const MemberId ma = model.gear(mesh.gear_a).member, mb = model.gear(mesh.gear_b).member;
    if ((ma == planet && model.is_planet(mb)) || (mb == planet && model.is_planet(ma))) return true;
  }
  return false;
}

// (w_p - w_c)/(w_A - w_c) for planet gear p meshing central gear A.
Rational planet_ratio(const Gear& central, const Gear& planet) {
  return Rational(basic_ratio_sign(central, planet) * central.z, planet.z);
}

std::vector<AssemblyCheck> internal_mesh_checks(const TrainModel& model) {
  std::vector<AssemblyCheck> checks;
  for (MeshId k = 0; k < model.meshes().size(); ++k) {
    const Gear& a = model.gear(model.mesh(k).gear_a);
    const Gear& b = model.gear(model.mesh(k).gear_b);
    if (a.kind == b.kind) continue;
    const Gear& internal = a.kind == GearKind::internal ? a : b;
    const Gear& external = a.kind == GearKind::internal ? b : a;
    AssemblyCheck c{"mesh '" + model.mesh(k).name + "'", "internal mesh", true, internal.z > external.z, ""};
    c.detail = fmt::format("internal gear '{}' z = {} against external gear '{}' z = {}{}", internal.name, internal.z,
                           external.name, external.z, c.satisfied ? "" : ": the internal gear must be the larger");
    checks.push_back(c);
  }
  return checks;
}

// Every central gear a planet meshes with must sit at the same centre distance from it.
AssemblyCheck coaxiality_check(const TrainModel& model, const std::string& subject,
                               const std::vector<CentralMesh>& central, const std::vector<Distance>& distances,
                               double tolerance) {
  AssemblyCheck c{subject, "coaxiality", true, true, ""};
  std::string listing;
  for (std::size_t i = 0; i < central.size(); ++i) {
    const Distance& d = distances[i];
    if (!d.value || d.in_modules != distances[0].in_modules) {
      c.checked = false;
      c.detail = fmt::format("not checked: the centre distance of mesh '{}' needs modules (and, with profile "
                             "shift, the working centre distance)", model.mesh(central[i].mesh).name);
      return c;
    }
    listing += fmt::format("{}a({}) = {:.4f}{}", i ? ", " : "", model.mesh(central[i].mesh).name, *d.value,
                           unit(d.in_modules));
    if (std::fabs(*d.value - *distances[0].value) > tolerance) c.satisfied = false;
  }
  c.detail = listing + fmt::format(" (tolerance {:g}{}){}", tolerance, unit(distances[0].in_modules),
                                   c.satisfied ? "" : ": the planet axis cannot be at both distances");
  return c;
}

// Turning the carrier by 2 pi/N with central gear A held turns each other central gear B by
// q_B = (1 - i0_B) z_B / N of its pitches. A planet can be put there if one turn of it by j
// pitches of p1 (which keeps it meshing with A) also brings every B mesh into phase:
// q_B + s_B j z_pB / z_p1 integer for all B, s_B the sign of the planet-B mesh.
AssemblyCheck spacing_between_central_gears(const TrainModel& model, const std::string& subject,
                                            const std::vector<CentralMesh>& central, int n) {
  const Gear& gA = model.gear(central[0].central_gear);
  const Gear& gp1 = model.gear(central[0].planet_gear);
  std::vector<Rational> q, step;
  std::string listing;
  for (std::size_t i = 1; i < central.size(); ++i) {
    const Gear& gB = model.gear(central[i].central_gear);
    const Gear& gpB = model.gear(central[i].planet_gear);
    const Rational i0 = planet_ratio(gA, gp1) / planet_ratio(gB, gpB);
    q.push_back((Rational(1) - i0) * gB.z / n);
    step.push_back(Rational(basic_ratio_sign(gpB, gB) * gpB.z, gp1.z));
    listing += fmt::format("{}q({}) = {}", i > 1 ? ", " : "", gB.name, to_fraction_string(q.back()));
  }
  std::optional<int> shift;
  for (int j = 0; j < gp1.z && !shift; ++j) {
    bool all = true;
    for (std::size_t i = 0; i < q.size() && all; ++i)
      all = boost::multiprecision::denominator(Rational(q[i] + j * step[i])) == 1;
    if (all) shift = j;
  }
  AssemblyCheck spacing{subject, "equal spacing", true, shift.has_value(), ""};
  spacing.detail =
      shift ? fmt::format("{} planets at 2pi/{}: central gears turn by {} pitches{}", n, n, listing,
                          *shift == 0 ? "" : fmt::format(", matched by turning each planet {} pitches of '{}'",
                                                         *shift, gp1.name))
            : fmt::format("{} planets at 2pi/{}: central gears turn by {} pitches, which no planet rotation "
                          "matches: the planets cannot be equally spaced", n, n, listing);
  return spacing;
}

AssemblyCheck spacing_check(const TrainModel& model, MemberId p, const std::string& subject,
                            const std::vector<CentralMesh>& central, int n) {
  if (has_planet_planet_mesh(model, p))
    return {subject, "equal spacing", false, false, "not checked: the planet meshes with another planet"};
  if (central.empty())  // nothing to space the planets against (and no central[0] to read)
    return {subject, "equal spacing", false, false, "not checked: the planet meshes no central gear", true};
  if (central.size() == 1)
    return {subject, "equal spacing", true, true,
            fmt::format("{} planets around one central gear: any spacing assembles", n)};
  return spacing_between_central_gears(model, subject, central, n);
}

// Tip diameter d_a = m_n z / cos(beta) + 2 m_n (1 + x) (ISO 21771, standard addendum, no tip
// shortening) of the largest external gear of planet p; nullopt if one has no module.
std::optional<double> largest_planet_tip_diameter(const TrainModel& model, MemberId p, bool in_modules) {
  std::optional<double> tip;
  for (const Gear& g : model.gears()) {
    if (g.member != p || g.kind != GearKind::external) continue;
    if (!in_modules && !g.module_mm) return std::nullopt;
    const double m = in_modules ? 1.0 : *g.module_mm;
    const double d_a = m * g.z / std::cos(g.beta) + 2.0 * m * (1.0 + g.x);
    if (!tip || d_a > *tip) tip = d_a;
  }
  return tip;
}

AssemblyCheck clearance_check(const TrainModel& model, MemberId p, const std::string& subject,
                              const std::vector<Distance>& distances, int n) {
  AssemblyCheck clearance{subject, "neighbour clearance", false, false, ""};
  if (distances.empty() || !distances[0].value) {
    clearance.detail = "not checked: no centre distance";
    return clearance;
  }
  const bool in_modules = distances[0].in_modules;
  const std::optional<double> tip = largest_planet_tip_diameter(model, p, in_modules);
  if (!tip) {
    clearance.detail = "not checked: a planet gear has no module";
    return clearance;
  }
  const double spacing_chord = 2.0 * *distances[0].value * std::sin(std::numbers::pi / n);
  clearance.checked = true;
  clearance.satisfied = spacing_chord > *tip;
  clearance.detail = fmt::format("2·a·sin(pi/N) = {:.6g}{} against the largest planet tip diameter {:.6g}{}{}",
                                 spacing_chord, unit(in_modules), *tip, unit(in_modules),
                                 clearance.satisfied ? "" : ": neighbouring planets collide");
  return clearance;
}

}  // namespace

std::vector<AssemblyCheck> check_assembly(const TrainModel& model, const CentreDistanceFunction& centre_distance,
                                          double tolerance) {
  std::vector<AssemblyCheck> checks = internal_mesh_checks(model);
  for (MemberId p = 1; p < model.member_count(); ++p) {
    if (!model.is_planet(p)) continue;
    const MemberId carrier = model.member(p).carried_by;
    const std::string subject =
        fmt::format("planet '{}' on carrier '{}'", model.member(p).name, model.member(carrier).name);
    const std::vector<CentralMesh> central = central_meshes(model, p);
    std::vector<Distance> distances;
    for (const CentralMesh& cm : central)
      distances.push_back(distance_of(model.gear(cm.planet_gear), model.gear(cm.central_gear), centre_distance));
    if (central.size() >= 2) checks.push_back(coaxiality_check(model, subject, central, distances, tolerance));
    const int n = model.member(p).planet_count;
    if (n < 2) continue;
    checks.push_back(spacing_check(model, p, subject, central, n));
    checks.push_back(clearance_check(model, p, subject, distances, n));
  }
  return checks;
}

}  // namespace gearkit::train
