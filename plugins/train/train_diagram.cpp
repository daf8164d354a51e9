// Stick diagram and speed (Kutzbach) diagram of a gear train, laid out from its graph:
//  - coaxial groups: a mesh carried by an arm makes the arm and every member it holds but does not
//    carry (suns, rings) one axis; meshes on the frame put the groups on parallel axes, apart by
//    the sum (or difference, for an internal gear) of the pitch radii;
//  - planets sit above their arm's axis at the distance their mesh with a central gear gives;
//  - gear planes: meshes that share a gear share an axial position (a "slot") unless two gears of
//    one member or two gears of one kind on one axis would overlap there; a gear in several slots
//    is drawn wide (a long planet);
//  - every central member gets a lane (a shaft line a little above the axis) in the order of its
//    radius, and its arm drops to that lane outside the gears, outer members further out, so that
//    shafts and arms do not cross.
#include "train_diagram.hpp"

#include <gearkit/io/drawing_annotation.hpp>
#include <gearkit/io/report.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace gearkit::plugins::train {

namespace gt = gearkit::train;

namespace {

constexpr double kTall = 60.0;      // largest radius of the drawing [mm]
constexpr double kBar = 1.6;        // width of a gear bar [mm]
constexpr double kDepth = 2.5;      // depth of an internal gear's rim [mm]
constexpr double kSlot = 22.0;      // axial distance between gear planes [mm]
constexpr double kLane = 3.2;       // distance between coaxial shaft lines [mm]
constexpr double kArmStep = 6.0;    // distance between the arms on one side [mm]
constexpr double kText = 2.5;       // text height [mm]

const std::vector<io::Layer> kLayers = {
    {"axes", 8, "#888888", true},         {"gears", 5, "#1f4e9a", false},   {"gear_mirror", 5, "#1f4e9a", false},
    {"gear_labels", 5, "#1f4e9a", false}, {"shafts", 7, "#000000", false},  {"carriers", 1, "#b02020", false},
    {"ground", 8, "#555555", false},      {"member_labels", 7, "#000000", false},
    {"speed_axes", 8, "#555555", false},  {"speed_rays", 6, "#a000a0", false}, {"speed_labels", 6, "#a000a0", false},
    {"title", 7, "#000000", false}};

struct Layout {
  double scale = 1.0;               // drawing mm per model length unit
  bool modules = false;             // radii from modules (else z/2)
  std::vector<double> r;            // per gear: pitch radius, drawing mm
  std::vector<bool> ground_mesh;    // per gear: meshes on fixed axes (drawn on both sides of its axis)
  std::vector<gt::MemberId> group;  // per member: representative of its coaxial group
  std::vector<bool> drawn;          // per member: owns a gear or carries a planet
  std::vector<double> y;            // per member: height of its axis
  std::vector<int> slot_lo, slot_hi;  // per gear
  int slots = 0;
};

gt::MemberId find(std::vector<gt::MemberId>& parent, gt::MemberId i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

std::vector<gt::MemberId> coaxial_groups(const gt::TrainModel& m) {
  std::vector<gt::MemberId> parent(m.member_count());
  std::iota(parent.begin(), parent.end(), gt::MemberId{0});
  for (const gt::Mesh& mesh : m.meshes()) {
    if (mesh.carrier == gt::ground) continue;
    for (gt::GearId g : {mesh.gear_a, mesh.gear_b}) {
      const gt::MemberId member = m.gear(g).member;
      if (m.member(member).carried_by != mesh.carrier) parent[find(parent, member)] = find(parent, mesh.carrier);
    }
  }
  for (gt::MemberId i = 0; i < parent.size(); ++i) parent[i] = find(parent, i);
  return parent;
}

void radii(const gt::TrainModel& m, Layout& L) {
  std::optional<double> module;
  for (const gt::Gear& g : m.gears())
    if (g.module_mm && !module) module = *g.module_mm;
  L.modules = module.has_value();
  for (const gt::Gear& g : m.gears()) L.r.push_back(0.5 * g.module_mm.value_or(module.value_or(1.0)) * g.z / std::cos(g.beta));
  L.ground_mesh.assign(m.gears().size(), false);
  for (const gt::Mesh& mesh : m.meshes())
    if (mesh.carrier == gt::ground) L.ground_mesh[mesh.gear_a] = L.ground_mesh[mesh.gear_b] = true;
}

bool carries_planets(const gt::TrainModel& m, gt::MemberId c) {
  for (gt::MemberId p = 1; p < m.member_count(); ++p)
    if (m.member(p).carried_by == c && m.is_planet(p)) return true;
  return false;
}

bool group_has_carrier(const gt::TrainModel& m, const Layout& L, gt::MemberId g) {
  for (gt::MemberId i = 0; i < m.member_count(); ++i)
    if (L.group[i] == g && carries_planets(m, i)) return true;
  return false;
}

// Distance between the axes of two meshing gears.
double axis_distance(const gt::TrainModel& m, const Layout& L, gt::GearId a, gt::GearId b) {
  const bool internal = m.gear(a).kind == gt::GearKind::internal || m.gear(b).kind == gt::GearKind::internal;
  return internal ? std::abs(L.r[a] - L.r[b]) : L.r[a] + L.r[b];
}

// Axes on the frame: each group from a placed neighbour across a fixed-axis mesh, below a group
// drawn as a half section (its planets are above) and otherwise back towards the first axis, so a
// coaxial reducer comes out coaxial.
void place_fixed_axes(const gt::TrainModel& m, Layout& L, std::vector<std::optional<double>>& gy) {
  double next = 0.0;
  for (gt::MemberId s = 0; s < m.member_count(); ++s) {
    if (!L.drawn[s] || m.is_planet(s) || gy[L.group[s]]) continue;
    gy[L.group[s]] = next;
    for (bool grew = true; grew;) {
      grew = false;
      for (const gt::Mesh& mesh : m.meshes()) {
        if (mesh.carrier != gt::ground) continue;
        const gt::MemberId a = L.group[m.gear(mesh.gear_a).member], b = L.group[m.gear(mesh.gear_b).member];
        if (gy[a].has_value() == gy[b].has_value()) continue;
        const gt::MemberId from = gy[a] ? a : b, to = gy[a] ? b : a;
        const double dir = group_has_carrier(m, L, from) || *gy[from] > 0 ? -1.0 : 1.0;
        gy[to] = *gy[from] + dir * axis_distance(m, L, mesh.gear_a, mesh.gear_b);
        grew = true;
      }
    }
    double low = 0.0;
    for (gt::MemberId i = 0; i < m.member_count(); ++i)
      if (gy[L.group[i]]) low = std::min(low, *gy[L.group[i]]);
    next = low - 2.5 * *std::max_element(L.r.begin(), L.r.end());
  }
}

// A planet's axis: its arm's axis plus the distance its mesh with a central gear gives.
void place_planets(const gt::TrainModel& m, Layout& L, std::vector<bool>& placed) {
  for (std::size_t pass = 0; pass < m.member_count(); ++pass)
    for (gt::MemberId p = 1; p < m.member_count(); ++p) {
      const gt::MemberId c = m.member(p).carried_by;
      if (placed[p] || !m.is_planet(p) || !placed[c]) continue;
      double offset = 0.0;
      for (const gt::Mesh& mesh : m.meshes()) {
        if (mesh.carrier != c) continue;
        for (auto [mine, other] : {std::pair{mesh.gear_a, mesh.gear_b}, {mesh.gear_b, mesh.gear_a}}) {
          if (m.gear(mine).member != p || m.member(m.gear(other).member).carried_by == c) continue;
          if (offset == 0.0) offset = axis_distance(m, L, mine, other);
        }
      }
      if (offset == 0.0)  // meshes only other planets: beside the arm
        for (gt::GearId g = 0; g < m.gears().size(); ++g)
          if (m.gear(g).member == p) offset = std::max(offset, 1.5 * L.r[g]);
      L.y[p] = L.y[c] + offset;
      placed[p] = true;
    }
}

void place_axes(const gt::TrainModel& m, Layout& L) {
  const std::size_t n = m.member_count();
  L.drawn.assign(n, false);
  for (const gt::Gear& g : m.gears()) L.drawn[g.member] = true;
  for (gt::MemberId i = 0; i < n; ++i)
    if (carries_planets(m, i)) L.drawn[i] = true;
  std::vector<std::optional<double>> gy(n);
  place_fixed_axes(m, L, gy);
  L.y.assign(n, 0.0);
  std::vector<bool> placed(n, false);
  for (gt::MemberId i = 0; i < n; ++i)
    if (!m.is_planet(i) && gy[L.group[i]]) {
      L.y[i] = *gy[L.group[i]];
      placed[i] = true;
    }
  place_planets(m, L, placed);
}

bool same_axis(const gt::TrainModel& m, const Layout& L, gt::MemberId a, gt::MemberId b) {
  if (m.is_planet(a) || m.is_planet(b))
    return m.member(a).carried_by == m.member(b).carried_by && std::abs(L.y[a] - L.y[b]) < 1e-9;
  return L.group[a] == L.group[b];
}

// Whether gear g would overlap a gear already in the plane.
bool conflicts(const gt::TrainModel& m, const Layout& L, const std::vector<gt::GearId>& plane, gt::GearId g) {
  for (gt::GearId h : plane) {
    if (h == g) return false;
    const gt::Gear &a = m.gear(g), &b = m.gear(h);
    if (a.member == b.member) return true;
    if (same_axis(m, L, a.member, b.member) && a.kind == b.kind) return true;
  }
  return false;
}

void assign_slots(const gt::TrainModel& m, Layout& L) {
  std::vector<std::vector<gt::GearId>> planes;
  auto holds = [](const std::vector<gt::GearId>& p, gt::GearId g) { return std::find(p.begin(), p.end(), g) != p.end(); };
  for (const gt::Mesh& mesh : m.meshes()) {
    std::size_t chosen = planes.size();  // the latest plane that holds one of its gears and has room
    for (std::size_t s = 0; s < planes.size(); ++s)
      if ((holds(planes[s], mesh.gear_a) || holds(planes[s], mesh.gear_b)) && !conflicts(m, L, planes[s], mesh.gear_a) &&
          !conflicts(m, L, planes[s], mesh.gear_b))
        chosen = s;
    if (chosen == planes.size()) planes.emplace_back();
    for (gt::GearId g : {mesh.gear_a, mesh.gear_b})
      if (!holds(planes[chosen], g)) planes[chosen].push_back(g);
  }
  for (gt::GearId g = 0; g < m.gears().size(); ++g) {
    bool any = false;
    for (const auto& p : planes) any = any || holds(p, g);
    if (!any) planes.push_back({g});
  }
  L.slot_lo.assign(m.gears().size(), static_cast<int>(planes.size()));
  L.slot_hi.assign(m.gears().size(), -1);
  for (std::size_t s = 0; s < planes.size(); ++s)
    for (gt::GearId g : planes[s]) {
      L.slot_lo[g] = std::min(L.slot_lo[g], static_cast<int>(s));
      L.slot_hi[g] = std::max(L.slot_hi[g], static_cast<int>(s));
    }
  L.slots = static_cast<int>(planes.size());
}

Layout layout(const gt::TrainModel& m) {
  Layout L;
  radii(m, L);
  L.group = coaxial_groups(m);
  place_axes(m, L);
  // One scale for every length, so that the tallest element is kTall high.
  double extent = 0.0;
  for (gt::GearId g = 0; g < m.gears().size(); ++g) extent = std::max(extent, std::abs(L.y[m.gear(g).member]) + L.r[g]);
  L.scale = extent > 0 ? kTall / extent : 1.0;
  for (double& r : L.r) r *= L.scale;
  for (double& y : L.y) y *= L.scale;
  assign_slots(m, L);
  return L;
}

double slot_x(int s) { return kSlot * s; }

// ---- drawing ---------------------------------------------------------------------------------

struct Shaft {                // a central member's connection
  double attach = 0.0;        // radius its arm starts from (0: the shaft runs under its gear)
  int side = 0;               // -1 left, +1 right
  int lane = 0;
  double lane_y = 0.0;
  double arm_x = 0.0;
  double x_lo = 0.0, x_hi = 0.0;  // its elements
  bool exits = false;          // leaves the drawing (input, output, coupled, fixed on a shaft)
  bool ground_on_rim = false;  // a fixed internal gear: ground drawn on its rim
  bool fixed = false;
  std::string role;
};

// A label's candidate positions, in order of preference; placed once every line is drawn, at the
// first position where no line crosses it and no other label overlaps it (io::place_first_fitting).
using Candidates = std::vector<io::Drawing>;

io::Drawing one_text(const std::string& layer, double x, double y, const std::string& text) {
  io::Drawing d;
  d.texts.push_back({layer, x, y, kText, text});
  return d;
}

// A text at each of the heights ys (outer) and left edges xs (inner), in that order.
Candidates grid(const std::string& layer, std::initializer_list<double> xs, std::initializer_list<double> ys,
                const std::string& text) {
  Candidates c;
  for (double y : ys)
    for (double x : xs) c.push_back(one_text(layer, x, y, text));
  return c;
}

// A text at (x, y) or x_alt, then the same shifted by 1.6 text heights down and up, twice.
Candidates shifted(const std::string& layer, double x, double x_alt, double y, const std::string& text) {
  const double k = 1.6 * kText;
  return grid(layer, {x, x_alt}, {y, y - k, y + k, y - 2 * k, y + 2 * k}, text);
}

struct Roles {
  std::vector<std::string> role;  // per member
  std::vector<int> side;          // per member: -1, +1 or 0 (free)
  std::vector<bool> fixed;
};

Roles roles(const gt::TrainModel& m, const TrainDiagramInput& in) {
  Roles r{std::vector<std::string>(m.member_count()), std::vector<int>(m.member_count(), 0),
          std::vector<bool>(m.member_count(), false)};
  r.fixed[gt::ground] = true;
  r.role[gt::ground] = "frame";
  for (gt::MemberId f : in.fixed) {
    r.fixed[f] = true;
    r.role[f] = "fixed";
  }
  for (const auto& [a, b] : in.couplings) {
    r.role[a] = "= " + m.member(b).name;
    r.role[b] = "= " + m.member(a).name;
  }
  for (gt::MemberId i : in.inputs) {
    r.role[i] = r.role[i].empty() ? "input" : "input, " + r.role[i];
    r.side[i] = -1;
  }
  if (in.output) {
    r.role[*in.output] = r.role[*in.output].empty() ? "output" : "output, " + r.role[*in.output];
    r.side[*in.output] = 1;
  }
  return r;
}

double planet_top(const gt::TrainModel& m, const Layout& L, gt::MemberId c) {
  double top = 0.0;
  for (gt::MemberId p = 1; p < m.member_count(); ++p)
    if (m.member(p).carried_by == c && m.is_planet(p)) top = std::max(top, L.y[p] - L.y[c]);
  return top;
}

double member_extent(const gt::TrainModel& m, const Layout& L, gt::MemberId i, double& x_lo, double& x_hi) {
  double attach = 0.0;
  x_lo = 1e300;
  x_hi = -1e300;
  for (gt::GearId g = 0; g < m.gears().size(); ++g) {
    if (m.gear(g).member != i) continue;
    x_lo = std::min(x_lo, slot_x(L.slot_lo[g]));
    x_hi = std::max(x_hi, slot_x(L.slot_hi[g]));
    if (m.gear(g).kind == gt::GearKind::internal) attach = std::max(attach, L.r[g] + kDepth);
  }
  for (gt::MemberId p = 1; p < m.member_count(); ++p) {
    if (m.member(p).carried_by != i || !m.is_planet(p)) continue;
    for (gt::GearId g = 0; g < m.gears().size(); ++g)
      if (m.gear(g).member == p) {
        x_lo = std::min(x_lo, slot_x(L.slot_lo[g]));
        x_hi = std::max(x_hi, slot_x(L.slot_hi[g]));
      }
  }
  return std::max(attach, planet_top(m, L, i));
}

// Sides, lanes and arm positions of the central members of every axis.
std::vector<Shaft> shafts(const gt::TrainModel& m, const Layout& L, const Roles& roles) {
  const std::size_t n = m.member_count();
  std::vector<Shaft> s(n);
  const double middle = 0.5 * slot_x(L.slots - 1);
  int balance = 0;
  for (gt::MemberId i = 0; i < n; ++i) {
    if (!L.drawn[i] || m.is_planet(i)) continue;
    s[i].attach = member_extent(m, L, i, s[i].x_lo, s[i].x_hi);
    s[i].role = roles.role[i];
    s[i].side = roles.side[i];
    const double mean = 0.5 * (s[i].x_lo + s[i].x_hi);
    if (s[i].side == 0) s[i].side = mean < middle - 1e-9 ? -1 : mean > middle + 1e-9 ? 1 : (balance > 0 ? -1 : 1);
    balance += s[i].side;
    const bool internal_only = s[i].attach > 0 && !carries_planets(m, i);
    s[i].fixed = roles.fixed[i];
    s[i].ground_on_rim = roles.fixed[i] && internal_only;
    s[i].exits = !s[i].ground_on_rim && !s[i].role.empty();
  }
  // Lanes by radius within each axis; arms outwards by radius on each side.
  for (gt::MemberId g = 0; g < n; ++g) {
    std::vector<gt::MemberId> members;
    for (gt::MemberId i = 0; i < n; ++i)
      if (L.drawn[i] && !m.is_planet(i) && L.group[i] == g) members.push_back(i);
    std::stable_sort(members.begin(), members.end(), [&](auto a, auto b) { return s[a].attach < s[b].attach; });
    double lo = 1e300, hi = -1e300;
    for (gt::MemberId i : members) lo = std::min(lo, s[i].x_lo), hi = std::max(hi, s[i].x_hi);
    int rank[2] = {0, 0};
    for (std::size_t k = 0; k < members.size(); ++k) {
      Shaft& sh = s[members[k]];
      sh.lane = static_cast<int>(k);
      sh.lane_y = L.y[members[k]] + kLane * static_cast<double>(k);
      if (sh.attach > 0 && !sh.ground_on_rim) {
        int& r = rank[sh.side > 0];
        sh.arm_x = sh.side < 0 ? lo - 0.5 * kSlot - kArmStep * r : hi + 0.5 * kSlot + kArmStep * r;
        ++r;
      } else {
        sh.arm_x = sh.side < 0 ? sh.x_lo : sh.x_hi;
      }
    }
  }
  return s;
}

// A gear as a bar (an internal gear as an open bracket) and its label "name: z = N" beside it:
// right of the bar at heights along it, then left of it (a ring: left of its rim, right of it,
// above it).
void gear_bar(io::Drawing& d, std::vector<Candidates>& labels, const gt::TrainModel& m, const Layout& L,
              const std::vector<Shaft>& s, gt::GearId g) {
  const gt::Gear& gear = m.gear(g);
  const double xl = slot_x(L.slot_lo[g]) - 0.5 * kBar, xr = slot_x(L.slot_hi[g]) + 0.5 * kBar;
  const double y0 = L.y[gear.member], r = L.r[g];
  const std::string label = fmt::format("{}: z = {}", gear.name, gear.z);
  const double w = io::text_width(label, kText);
  Candidates c;
  if (gear.kind == gt::GearKind::internal) {
    d.polylines.push_back({"gears", {{xl, y0 + r, 0}, {xl, y0 + r + kDepth, 0}, {xr, y0 + r + kDepth, 0}, {xr, y0 + r, 0}}, false});
    if (L.ground_mesh[g])
      d.polylines.push_back({"gear_mirror", {{xl, y0 - r, 0}, {xl, y0 - r - kDepth, 0}, {xr, y0 - r - kDepth, 0}, {xr, y0 - r, 0}}, false});
    for (double y : {y0 + r + 0.2, y0 + r - 1.4 * kText, y0 + r + kDepth + 0.6})
      for (double x : {xl - 0.8 - w, xr + 0.8}) c.push_back(one_text("gear_labels", x, y, label));
    labels.push_back(std::move(c));
    return;
  }
  const bool whole = L.ground_mesh[g] || m.is_planet(gear.member);
  const double bottom = whole ? y0 - r : s[gear.member].lane_y;
  d.polylines.push_back({"gears", {{xl, bottom, 0}, {xr, bottom, 0}, {xr, y0 + r, 0}, {xl, y0 + r, 0}}, true});
  const double ty = m.is_planet(gear.member) ? y0 + 0.45 * r : y0 + std::max(0.55 * r, r - 2.0 * kText);
  // Left of the bar the label may sit in the gap beside another gear's bar (the Ravigneaux's
  // large sun, whose right is crossed by the carrier): a leader to its own bar says whose it is.
  for (double x : {xr + 0.8, xl - 2.4 - w})
    for (double k = 0.0; k < 12.0; k += 1.0)
      for (double y : {ty - 1.6 * kText * k, ty + 1.6 * kText * k}) {
        if (!(y > bottom + 0.3 * kText && y < y0 + r - kText && (k > 0.0 || y == ty))) continue;
        c.push_back(one_text("gear_labels", x, y, label));
        if (x < xl) c.back().lines.push_back({"gear_labels", x + w + 0.2, y + 0.35 * kText, xl, y + 0.35 * kText});
      }
  if (c.empty()) c.push_back(one_text("gear_labels", xr + 0.8, ty, label));
  labels.push_back(std::move(c));
}

void ground_hatch(io::Drawing& d, double x0, double y0, double x1, double y1, double nx, double ny) {
  d.lines.push_back({"ground", x0, y0, x1, y1});
  const double len = std::hypot(x1 - x0, y1 - y0);
  const int strokes = std::max(3, static_cast<int>(len / 1.5));
  for (int k = 0; k <= strokes; ++k) {
    const double t = static_cast<double>(k) / strokes;
    const double px = x0 + t * (x1 - x0), py = y0 + t * (y1 - y0);
    const double ux = (x1 - x0) / len, uy = (y1 - y0) / len;
    d.lines.push_back({"ground", px, py, px + 1.5 * nx - 1.2 * ux, py + 1.5 * ny - 1.2 * uy});
  }
}

std::string member_text(const gt::TrainModel& m, gt::MemberId i, const std::string& role) {
  return role.empty() || role == m.member(i).name ? m.member(i).name : fmt::format("{} ({})", m.member(i).name, role);
}

// A central member: its shaft line, its arm, its exit or ground, its name.
void central_member(io::Drawing& d, std::vector<Candidates>& labels, const gt::TrainModel& m, const Layout& L,
                    const Shaft& sh, gt::MemberId i, double edge_left, double edge_right) {
  const double y0 = L.y[i];
  const std::string name = member_text(m, i, sh.role);
  if (sh.ground_on_rim) {
    ground_hatch(d, sh.x_lo - 3.0, y0 + sh.attach, sh.x_hi + 3.0, y0 + sh.attach, 0.0, 1.0);
    labels.push_back(shifted("member_labels", sh.x_lo - 3.0, sh.x_hi + 3.0, y0 + sh.attach + 2.2, name));
    return;
  }
  const bool carrier = carries_planets(m, i);
  const char* layer = carrier ? "carriers" : "shafts";
  if (sh.attach > 0) {
    const double inner = sh.side < 0 ? sh.x_hi : sh.x_lo;  // the drum spans every rim of the member
    if (!carrier) d.lines.push_back({layer, inner, y0 + sh.attach, sh.arm_x, y0 + sh.attach});
    for (gt::GearId g = 0; g < m.gears().size(); ++g)
      if (m.gear(g).member == i && m.gear(g).kind == gt::GearKind::internal && L.r[g] + kDepth < sh.attach) {
        const double x = slot_x(sh.side < 0 ? L.slot_lo[g] : L.slot_hi[g]);
        d.lines.push_back({layer, x, y0 + L.r[g] + kDepth, x, y0 + sh.attach});
      }
    d.lines.push_back({layer, sh.arm_x, y0 + sh.attach, sh.arm_x, sh.lane_y});
  }
  const double near = sh.attach > 0 ? sh.arm_x : (sh.side < 0 ? sh.x_hi : sh.x_lo);
  const double edge = sh.side < 0 ? edge_left : edge_right;
  const double far = sh.exits ? edge : (sh.attach > 0 ? sh.arm_x + sh.side * 3.0 : (sh.side < 0 ? sh.x_lo : sh.x_hi));
  d.lines.push_back({"shafts", near, sh.lane_y, far, sh.lane_y});
  if (sh.exits && sh.fixed)
    ground_hatch(d, edge, sh.lane_y - 2.0, edge, sh.lane_y + 2.0, sh.side * 1.0, 0.0);
  if (sh.exits) {
    const double tx = sh.side < 0 ? edge - 2.5 - io::text_width(name, kText) : edge + 2.5;
    labels.push_back(shifted("member_labels", tx, tx, sh.lane_y - 0.4 * kText, name));
  } else if (sh.attach > 0) {  // beside its arm, on the outer side first
    const double w = io::text_width(name, kText), left = sh.arm_x - 1.0 - w, right = sh.arm_x + 1.0;
    Candidates c = shifted("member_labels", sh.side < 0 ? left : right, sh.side < 0 ? right : left, y0 + sh.attach + 0.6, name);
    // ... else at the foot of the arm, by its shaft's end (between other arms there may be no room).
    const double end = sh.side < 0 ? std::min(far, near) - 0.8 - w : std::max(far, near) + 0.8;
    for (Candidates more = grid("member_labels", {end, right, left}, {sh.lane_y - 0.4 * kText, sh.lane_y - 1.6 * kText, sh.lane_y + 0.6}, name);
         auto& candidate : more)
      c.push_back(std::move(candidate));
    labels.push_back(std::move(c));
  } else {  // along its shaft between its gears, below or above it
    const double w = io::text_width(name, kText), mid = 0.5 * (sh.x_lo + sh.x_hi);
    labels.push_back(grid("member_labels", {mid + 1.5, mid - 0.5 * w, sh.x_lo + 1.5, sh.x_hi - 1.5 - w},
                          {sh.lane_y - 1.4 * kText, sh.lane_y + 0.6, sh.lane_y - 3.0 * kText}, name));
  }
}

// A planet: its pin from the far side of its gears to its arm.
void planet(io::Drawing& d, std::vector<Candidates>& labels, const gt::TrainModel& m, const Layout& L,
            const std::vector<Shaft>& s, gt::MemberId p) {
  const gt::MemberId c = m.member(p).carried_by;
  double lo = 1e300, hi = -1e300;
  for (gt::GearId g = 0; g < m.gears().size(); ++g)
    if (m.gear(g).member == p) lo = std::min(lo, slot_x(L.slot_lo[g])), hi = std::max(hi, slot_x(L.slot_hi[g]));
  if (lo > hi) return;
  const Shaft& arm = s[c];
  const double arm_x = m.is_planet(c) ? lo - 0.5 * kSlot : arm.arm_x;
  const double far = arm_x < lo ? hi + 3.0 : lo - 3.0;
  d.lines.push_back({"carriers", std::min(arm_x, far), L.y[p], std::max(arm_x, far), L.y[p]});
  const std::string name = m.member(p).name + (m.member(p).planet_count > 1 ? fmt::format(" (x{})", m.member(p).planet_count) : "");
  const double tx = arm_x < lo ? far + 0.8 : far - 0.8 - io::text_width(name, kText);
  const double other = arm_x < lo ? lo - 3.8 - io::text_width(name, kText) : hi + 3.8;
  labels.push_back(shifted("member_labels", tx, other, L.y[p] - 0.4 * kText, name));
}

void stick_diagram(io::Drawing& d, const gt::TrainModel& m, const Layout& L, const std::vector<Shaft>& s) {
  double lo = 0.0, hi = slot_x(L.slots - 1);
  for (gt::MemberId i = 0; i < m.member_count(); ++i)
    if (L.drawn[i] && !m.is_planet(i)) lo = std::min(lo, s[i].arm_x), hi = std::max(hi, s[i].arm_x);
  const double edge_left = lo - 0.6 * kSlot, edge_right = hi + 0.6 * kSlot;
  std::vector<double> axes;
  for (gt::MemberId i = 0; i < m.member_count(); ++i)
    if (L.drawn[i] && !m.is_planet(i) && std::find(axes.begin(), axes.end(), L.y[i]) == axes.end()) axes.push_back(L.y[i]);
  for (double y : axes) d.lines.push_back({"axes", edge_left - 2.0, y, edge_right + 2.0, y});
  std::vector<Candidates> labels;
  for (gt::GearId g = 0; g < m.gears().size(); ++g) gear_bar(d, labels, m, L, s, g);
  for (gt::MemberId i = 0; i < m.member_count(); ++i) {
    if (!L.drawn[i]) continue;
    if (m.is_planet(i)) planet(d, labels, m, L, s, i);
    else central_member(d, labels, m, L, s[i], i, edge_left, edge_right);
  }
  for (const Candidates& c : labels) io::place_first_fitting(d, c);
}

// ---- speed diagram ---------------------------------------------------------------------------

// Up to 4 decimals, trailing zeros dropped: "3000", "857.1429", "-0.5".
std::string short_number(double v) {
  std::string t = io::fixed(v, 4);
  while (t.find('.') != std::string::npos && (t.back() == '0' || t.back() == '.')) {
    const bool dot = t.back() == '.';
    t.pop_back();
    if (dot) break;
  }
  return t;
}

struct Ray {
  gt::MemberId member;
  double r0, v0, r1, v1;  // radius (from the axis) and peripheral speed at both ends
};

std::vector<Ray> speed_rays(const gt::TrainModel& m, const Layout& L, const std::vector<Shaft>& s,
                            const std::vector<std::optional<double>>& w, gt::MemberId group, double top) {
  std::vector<Ray> rays;
  for (gt::MemberId i = 0; i < m.member_count(); ++i) {
    if (!L.drawn[i] || !w[i]) continue;
    if (!m.is_planet(i) && L.group[i] == group) {
      rays.push_back({i, 0.0, 0.0, top, *w[i] * top});
      continue;
    }
    const gt::MemberId c = m.member(i).carried_by;
    if (!m.is_planet(i) || m.is_planet(c) || L.group[c] != group || !w[c]) continue;
    double rp = 0.0;
    for (gt::GearId g = 0; g < m.gears().size(); ++g)
      if (m.gear(g).member == i) rp = std::max(rp, L.r[g]);
    const double a = L.y[i] - L.y[c];  // v(rho) = w_c a + w_p (rho - a): the planet's centre moves with the arm
    rays.push_back({i, a - rp, *w[c] * a - *w[i] * rp, a + rp, *w[c] * a + *w[i] * rp});
  }
  (void)s;
  return rays;
}

// Swaps the slots of two leaders (from end_of(slot) to (x, slot_y(slot))) that cross, until none
// do; at most n^2 rounds, as a safeguard.
template <class EndOf, class SlotY>
void uncross_leaders(std::vector<std::size_t>& order, EndOf end_of, SlotY slot_y, double x) {
  auto cross = [&](std::size_t a, std::size_t b) {
    const auto [ax, ay] = end_of(a);
    const auto [bx, by] = end_of(b);
    const double ay1 = slot_y(a), by1 = slot_y(b);
    auto side = [](double px, double py, double qx, double qy, double rx, double ry) { return (qx - px) * (ry - py) - (qy - py) * (rx - px); };
    return side(ax, ay, x, ay1, bx, by) * side(ax, ay, x, ay1, x, by1) < 0 && side(bx, by, x, by1, ax, ay) * side(bx, by, x, by1, x, ay1) < 0;
  };
  const std::size_t n = order.size();
  for (std::size_t round = 0; round < n * n + 1; ++round) {
    bool swapped = false;
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = a + 1; b < n; ++b)
        if (cross(a, b)) std::swap(order[a], order[b]), swapped = true;
    if (!swapped) return;
  }
}

void speed_diagram(io::Drawing& d, const gt::TrainModel& m, const Layout& L, const std::vector<Shaft>& s,
                   const TrainDiagramInput& in, gt::MemberId group, double x0) {
  const double y0 = L.y[group];
  double top = 0.0;
  for (gt::MemberId i = 0; i < m.member_count(); ++i)
    if (L.drawn[i] && !m.is_planet(i) && L.group[i] == group) top = std::max(top, s[i].attach);
  for (gt::GearId g = 0; g < m.gears().size(); ++g)
    if (!m.is_planet(m.gear(g).member) && L.group[m.gear(g).member] == group) top = std::max(top, L.r[g]);
  const std::vector<Ray> rays = speed_rays(m, L, s, in.speeds, group, top);
  if (rays.empty()) return;
  double vlo = 0.0, vhi = 0.0;
  for (const Ray& r : rays) vlo = std::min({vlo, r.v0, r.v1}), vhi = std::max({vhi, r.v0, r.v1});
  const double k = vhi > vlo ? 70.0 / (vhi - vlo) : 1.0;  // drawing mm per unit of speed x radius
  const double xc = x0 - k * vlo, xl = x0 - 4.0, xr = x0 + 74.0;
  d.lines.push_back({"speed_axes", xc, y0, xc, y0 + top + 4.0});
  d.lines.push_back({"speed_axes", xl, y0, xr, y0});
  d.lines.push_back({"speed_axes", xl, y0 + top, xr, y0 + top});
  d.texts.push_back({"speed_labels", xl, y0 - 2.0 * kText, kText, "speed (Kutzbach) diagram: peripheral speed v = n r"});
  d.texts.push_back({"speed_labels", xl, y0 - 3.8 * kText, kText,
                     fmt::format("against the radius r; n in {}, read where a ray meets the top line", in.speed_unit)});
  for (const Ray& r : rays) d.lines.push_back({"speed_rays", xc + k * r.v0, y0 + r.r0, xc + k * r.v1, y0 + r.r1});
  // Leaders run from the rays' upper ends up to a column of labels on the right. Slots are
  // assigned leftmost end to the top, then any two crossing leaders swap slots until none cross
  // (each swap shortens the leaders in total, so it ends): the order of the members crossed them.
  std::vector<std::size_t> order(rays.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return rays[a].v1 != rays[b].v1 ? rays[a].v1 < rays[b].v1 : rays[a].r1 > rays[b].r1;
  });
  auto slot_y = [&](std::size_t slot) { return y0 + top + 8.0 + 1.8 * kText * static_cast<double>(order.size() - 1 - slot); };
  auto end_of = [&](std::size_t slot) { return std::pair{xc + k * rays[order[slot]].v1, y0 + rays[order[slot]].r1}; };
  uncross_leaders(order, end_of, slot_y, xr + 4.0);
  for (std::size_t slot = 0; slot < order.size(); ++slot) {
    const Ray& r = rays[order[slot]];
    const std::string text = fmt::format("{}: n = {} {}", m.member(r.member).name, short_number(*in.speeds[r.member]), in.speed_unit);
    const double ty = slot_y(slot);
    io::add_label(d, xc + k * r.v1, y0 + r.r1, xr + 4.0, ty, text, kText, "speed_labels");
  }
}

}  // namespace

io::Drawing train_diagram(const gt::TrainModel& model, const TrainDiagramInput& in) {
  io::Drawing d;
  d.layers = kLayers;
  if (model.gears().empty()) return d;
  const Layout L = layout(model);
  const Roles r = roles(model, in);
  const std::vector<Shaft> s = shafts(model, L, r);
  stick_diagram(d, model, L, s);
  const io::Box stick = io::drawing_box(d);
  if (!in.speeds.empty()) {
    double x0 = stick.xmax + 10.0;
    for (gt::MemberId g = 0; g < model.member_count(); ++g)
      if (L.group[g] == g && L.drawn[g] && group_has_carrier(model, L, g)) {
        speed_diagram(d, model, L, s, in, g, x0);
        x0 = io::drawing_box(d).xmax + 10.0;
      }
  }
  const io::Box box = io::drawing_box(d);
  const std::string scale = L.modules ? fmt::format("pitch radii to scale, 1 : {:.3g}", 1.0 / L.scale)
                                      : "pitch radii proportional to the tooth counts (no module given)";
  d.texts.push_back({"title", stick.xmin, box.ymax + 2.0 * kText, 1.4 * kText,
                     fmt::format("{} - stick diagram ({})", in.title, scale)});
  return d;
}

}  // namespace gearkit::plugins::train
