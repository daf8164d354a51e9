#include <gearkit/mechanism/reader.hpp>

#include "references.hpp"

#include <gearkit/io/limits.hpp>

#include <fmt/format.h>

#include <gearkit/kin/constraint.hpp>
#include <gearkit/kin/joints.hpp>

#include <cmath>
#include <deque>
#include <map>
#include <set>

namespace gearkit::mechanism {

namespace {

using io::fail_at;
using io::mark_of;
using io::MapReader;
using io::Quantity;
using io::scalar_quantity;
using io::scalar_text;
using kin::BodyPoint;
using kin::kGround;

std::string scalar(const YAML::Node& node, const std::string& file, std::string_view what) {
  return scalar_text(node, file, what);
}

// A pair [x, y] of lengths (bare numbers in mm).
Eigen::Vector2d read_xy(const YAML::Node& node, const std::string& file, Quantity q, std::string_view unit,
                        std::string_view what) {
  if (!node.IsSequence() || node.size() != 2)
    fail_at(mark_of(node, file), std::string("expected ") + std::string(what) + " as [x, y], found " +
                                     (node.IsScalar() ? io::quote(node.Scalar()) : std::string("something else")));
  return {scalar_quantity(node[0], file, q, unit), scalar_quantity(node[1], file, q, unit)};
}

// A contact joint as written, until its side can be taken from the placed drawing.
struct PendingContact {
  BodyPoint circle, line;
  double radius = 0.0;
  Eigen::Vector2d axis;
  int side = 0;  // 0: from the drawing
  int constraint = 0;
  YAML::Node node;
};

// Builds the model step by step, remembering where each link was declared.
class Reader {
 public:
  Reader(const io::YamlDocument& doc, const ElementTypeLookup& elements) : doc_(doc), elements_(elements) {}

  Mechanism read() {
    MapReader root(doc_.root, doc_.file, "mechanism");
    mech_.file = doc_.file;
    mech_.title = root.optional_string("mechanism").value_or(doc_.file);
    if (auto g = root.optional_node("ground")) read_ground(*g);
    read_links(root.node("links"));
    std::vector<YAML::Node> joints;
    if (root.has("joints")) joints = root.sequence("joints", io::limits::kMechanismItems, "joints");
    std::vector<YAML::Node> elements;
    if (root.has("elements")) elements = root.sequence("elements", io::limits::kMechanismItems, "elements");
    std::vector<YAML::Node> drivers;
    if (root.has("drivers")) drivers = root.sequence("drivers", io::limits::kMechanismItems, "drivers");
    for (const YAML::Node& j : joints) read_joint(j);
    place_links();
    for (const YAML::Node& e : elements) read_element(e);
    for (const YAML::Node& d : drivers) read_driver(d);
    if (auto loads = root.optional_node("loads")) read_loads(*loads);
    check_unknown_loads();
    if (root.has("outputs"))
      for (const YAML::Node& o : root.sequence("outputs", io::limits::kMechanismItems, "outputs")) read_output(o);
    root.optional_node("equations");  // the course's coordinates: read by `kin --equations` (libsym)
    root.finish();
    return std::move(mech_);
  }

 private:
  [[noreturn]] void fail(const YAML::Node& node, const std::string& message) const {
    fail_at(mark_of(node, doc_.file), message);
  }

  void read_ground(const YAML::Node& node) {
    if (!node.IsMap()) fail(node, "expected 'ground' as a mapping of point names to [x, y], found something else");
    io::check_size(node, doc_.file, io::limits::kMechanismItems, "points", "'ground'");
    for (auto it = node.begin(); it != node.end(); ++it) {
      const std::string name = scalar(it->first, doc_.file, "a ground point name");
      if (mech_.model.ground().point(name)) fail(it->first, "duplicate ground point " + io::quote(name));
      mech_.model.ground().points.emplace_back(name, read_xy(it->second, doc_.file, Quantity::length, "mm", "a ground point"));
    }
  }

  void read_links(const YAML::Node& node) {
    if (!node.IsMap() || node.size() == 0)
      fail(node, "expected 'links' as a mapping of link names to their points, found " +
                     std::string(node.IsMap() ? "an empty mapping" : "something else"));
    io::check_size(node, doc_.file, io::limits::kMechanismLinks, "links", "'links'");
    for (auto it = node.begin(); it != node.end(); ++it) {
      kin::Body b;
      b.name = scalar(it->first, doc_.file, "a link name");
      if (b.name == "ground" || b.name.find('.') != std::string::npos || b.name.empty())
        fail(it->first, "expected a link name without '.' other than 'ground', found " + io::quote(b.name));
      if (mech_.model.body_index(b.name)) fail(it->first, "duplicate link " + io::quote(b.name));
      MapReader link(it->second, doc_.file, "link " + io::quote(b.name));
      const YAML::Node points = link.node("points");
      if (!points.IsMap() || points.size() == 0)
        fail(points, "expected the points of link " + io::quote(b.name) + " as a mapping name: [x, y], found something else");
      io::check_size(points, doc_.file, io::limits::kMechanismItems, "points", "a link");
      for (auto p = points.begin(); p != points.end(); ++p) {
        const std::string pname = scalar(p->first, doc_.file, "a point name");
        if (b.point(pname)) fail(p->first, "duplicate point " + io::quote(pname) + " in link " + io::quote(b.name));
        b.points.emplace_back(pname, read_xy(p->second, doc_.file, Quantity::length, "mm", "a point"));
      }
      b.angle_guess = link.quantity_or("angle", Quantity::angle, "deg", 0.0);
      if (auto pos = link.optional_node("position")) {
        b.position_guess = read_xy(*pos, doc_.file, Quantity::length, "mm", "the link's position");
        placed_.insert(static_cast<int>(mech_.model.bodies().size()));
      }
      b.mass = link.quantity_or("mass", Quantity::mass, "kg", 0.0);
      if (b.mass < 0) fail(link.node("mass"), "expected a mass >= 0");
      if (auto com = link.optional_node("centre_of_mass")) {
        if (com->IsScalar()) {
          const auto p = b.point(com->Scalar());
          if (!p) fail(*com, "expected a point of link " + io::quote(b.name) + " or [x, y], found " + io::quote(com->Scalar()));
          b.centre_of_mass = *p;
        } else {
          b.centre_of_mass = read_xy(*com, doc_.file, Quantity::length, "mm", "the centre of mass");
        }
      }
      b.inertia = link.quantity_or("inertia", Quantity::moment_of_inertia, "kg*m^2", 0.0);
      if (b.inertia < 0) fail(link.node("inertia"), "expected an inertia >= 0");
      link.finish();
      link_nodes_.push_back(it->first);
      mech_.model.add_body(std::move(b));
    }
  }

  // A moving link pinned at two differently named points that coincide has zero length: the
  // mechanism it belongs to is degenerate (a zero-length crank turns without moving anything, and
  // the Grashof classification would call it a crank). One point shared by several joints (a
  // compound pin) is fine.
  void check_link_length(const BodyPoint& p, const YAML::Node& ref) {
    if (p.body == kGround) return;
    const std::string text = scalar(ref, doc_.file, "a point reference 'link.point'");
    for (const auto& [local, other] : pins_[p.body]) {
      if (other == text || (local - p.local).norm() > 1e-9) continue;
      const std::string& link = mech_.model.bodies()[static_cast<std::size_t>(p.body)].name;
      fail(ref, fmt::format("link '{}' has zero length: its pins {} and {} are at the same point; give the link its "
                            "length, or use one point for a pin shared by several links", link, other, text));
    }
    pins_[p.body].emplace_back(p.local, text);
  }

  // "link.point" -> body and local coordinates.
  BodyPoint point_ref(const YAML::Node& node) const {
    return resolve_point(mech_.model, scalar(node, doc_.file, "a point reference 'link.point'"), mark_of(node, doc_.file));
  }

  int link_ref(const YAML::Node& node) const {
    return resolve_link(mech_.model, scalar(node, doc_.file, "a link name"), mark_of(node, doc_.file));
  }

  std::string unique_name(std::optional<std::string> name, const std::string& prefix, const YAML::Node& node) {
    std::string n = name ? *name : prefix + " " + std::to_string(mech_.model.constraints().size() + 1);
    if (mech_.model.constraint_index(n)) fail(node, "duplicate joint, element or driver name " + io::quote(n));
    return n;
  }

  double angle_of(int body) const {
    return body == kGround ? 0.0 : mech_.model.bodies()[static_cast<std::size_t>(body)].angle_guess;
  }

  void add(const std::string& name, std::shared_ptr<const kin::Constraint> c, const YAML::Node& node) {
    try {
      mech_.model.add_constraint(name, std::move(c));
    } catch (const std::invalid_argument& e) {
      fail(node, e.what());
    }
  }

  void read_joint(const YAML::Node& node) {
    MapReader j(node, doc_.file, "joint");
    const std::string type = j.choice("type", builtin_joint_types());
    const std::string name = unique_name(j.optional_string("name"), type, node);
    if (type == "revolute") {
      const std::vector<YAML::Node> at = j.sequence("at");
      if (at.size() != 2) fail(j.node("at"), "expected 'at' as two point references [link.P, other.P]");
      const BodyPoint a = point_ref(at[0]), b = point_ref(at[1]);
      if (a.body == b.body) fail(j.node("at"), "a revolute joint needs two different links");
      check_link_length(a, at[0]);
      check_link_length(b, at[1]);
      add(name, std::make_shared<kin::Revolute>(a, b), node);
      revolutes_.push_back({a, b});
    } else if (type == "contact") {
      read_contact(j, name, node);
    } else {
      const BodyPoint moving = point_ref(j.node(type == "prismatic" ? "slider" : "pin"));
      const BodyPoint guide = point_ref(j.node(type == "prismatic" ? "guide" : "slot"));
      if (moving.body == guide.body) fail(node, "the two sides of joint " + io::quote(name) + " are the same link");
      const double axis = j.quantity("axis", Quantity::angle, "deg");
      const Eigen::Vector2d u(std::cos(axis), std::sin(axis));
      if (type == "prismatic") {
        add(name, std::make_shared<kin::Prismatic>(moving, guide, u, angle_of(moving.body) - angle_of(guide.body)), node);
        prismatics_[name] = {moving, guide, u};
        revolutes_.push_back({moving, guide});  // for placing the first guess only
      } else {
        add(name, std::make_shared<kin::PinInSlot>(moving, guide, u), node);
      }
    }
    read_friction(j, type, node);
    j.finish();
  }

  // A circle (radius 0: a point or an edge) of one link touching a line of another. Its side is
  // given (left/right of the line looking along its axis) or taken from the drawing once the
  // links are placed (place_links).
  void read_contact(MapReader& j, const std::string& name, const YAML::Node& node) {
    PendingContact c;
    c.circle = point_ref(j.node("circle"));
    c.line = point_ref(j.node("line"));
    if (c.circle.body == c.line.body) fail(node, "the two sides of joint " + io::quote(name) + " are the same link");
    c.radius = j.quantity_or("radius", Quantity::length, "mm", 0.0);
    if (!(c.radius >= 0.0)) fail(j.node("radius"), "expected a radius >= 0");
    const double axis = j.quantity("axis", Quantity::angle, "deg");
    c.axis = Eigen::Vector2d(std::cos(axis), std::sin(axis));
    if (j.has("side")) c.side = j.choice("side", {"left", "right"}) == "left" ? 1 : -1;
    c.node = node;
    c.constraint = static_cast<int>(mech_.model.constraints().size());
    add(name, std::make_shared<kin::Contact>(c.circle, c.radius, c.line, c.axis, c.side ? c.side : 1), node);
    contacts_.push_back(c);
  }

  // `friction: mu` on a joint, with the revolute's journal `radius` and the prismatic's bearing
  // `length`.
  void read_friction(MapReader& j, const std::string& type, const YAML::Node& node) {
    const bool journal = type == "revolute", bearing = type == "prismatic";
    if (!j.has("friction")) {
      if (journal && j.has("radius")) fail(j.node("radius"), "expected 'radius' (the journal radius) only with 'friction'");
      if (bearing && j.has("length")) fail(j.node("length"), "expected 'length' (the bearing length) only with 'friction'");
      return;
    }
    kin::JointFriction f;
    f.constraint = static_cast<int>(mech_.model.constraints().size()) - 1;
    f.mu = j.number("friction");
    if (!(f.mu >= 0.0)) fail(j.node("friction"), "expected a friction coefficient >= 0");
    if (journal) {
      if (!j.has("radius")) fail(node, "expected 'radius' (the journal radius of the friction circle) with 'friction'");
      f.radius = j.quantity("radius", Quantity::length, "mm");
      if (!(f.radius > 0.0)) fail(j.node("radius"), "expected a journal radius > 0");
    }
    if (bearing) {
      f.length = j.quantity_or("length", Quantity::length, "mm", 0.0);
      if (!(f.length >= 0.0)) fail(j.node("length"), "expected a bearing length >= 0");
    }
    try {
      mech_.model.add_friction(f);
    } catch (const std::invalid_argument& e) {
      fail(j.node("friction"), e.what());
    }
  }

  // Initial guesses: a link without an explicit position is placed so that its joint point
  // coincides with the already placed partner's point (breadth first from the ground).
  void place_links() {
    std::vector<kin::Body> bodies = mech_.model.bodies();
    std::set<int> placed = placed_;
    placed.insert(kGround);
    auto global = [&](const BodyPoint& p) {
      if (p.body == kGround) return p.local;
      const kin::Body& b = bodies[static_cast<std::size_t>(p.body)];
      return Eigen::Vector2d(b.position_guess + kin::rotate(b.angle_guess, p.local));
    };
    bool progress = true;
    while (progress) {
      progress = false;
      for (const auto& [a, b] : revolutes_) {
        for (const auto& [x, y] : {std::pair{a, b}, std::pair{b, a}}) {
          if (placed.count(x.body) || !placed.count(y.body)) continue;
          kin::Body& body = bodies[static_cast<std::size_t>(x.body)];
          body.position_guess = global(y) - kin::rotate(body.angle_guess, x.local);
          placed.insert(x.body);
          progress = true;
        }
      }
    }
    // Rebuild the model's bodies with the guesses (constraints refer to bodies by index).
    kin::Model m;
    m.ground() = mech_.model.ground();
    for (kin::Body& b : bodies) m.add_body(std::move(b));
    for (const kin::ModelConstraint& c : mech_.model.constraints()) m.add_constraint(c.name, c.constraint);
    for (const kin::JointFriction& f : mech_.model.frictions()) m.add_friction(f);
    mech_.model = std::move(m);
    for (const PendingContact& c : contacts_) set_contact_side(c);
  }

  // A contact without `side` touches from the side its circle is drawn on.
  void set_contact_side(const PendingContact& c) {
    if (c.side) return;
    const auto global = [&](const BodyPoint& p) {
      if (p.body == kGround) return p.local;
      const kin::Body& b = mech_.model.bodies()[static_cast<std::size_t>(p.body)];
      return Eigen::Vector2d(b.position_guess + kin::rotate(b.angle_guess, p.local));
    };
    const Eigen::Vector2d n = kin::rotate(angle_of(c.line.body), kin::perp(c.axis));
    const double distance = n.dot(global(c.circle) - global(c.line));
    const double scale = std::max(c.radius, 1e-3);  // 1 mm when the radius is 0
    if (std::abs(distance) < 1e-6 * scale)
      fail(c.node, "the contact's circle centre is drawn on its line: give 'side: left' or 'side: right' (the side of "
                   "the line, looking along its axis, the circle lies on)");
    kin::Model& m = mech_.model;
    kin::Model rebuilt;
    rebuilt.ground() = m.ground();
    for (const kin::Body& b : m.bodies()) rebuilt.add_body(b);
    for (std::size_t k = 0; k < m.constraints().size(); ++k) {
      const kin::ModelConstraint& mc = m.constraints()[k];
      if (static_cast<int>(k) == c.constraint)
        rebuilt.add_constraint(mc.name, std::make_shared<kin::Contact>(c.circle, c.radius, c.line, c.axis, distance > 0 ? 1 : -1));
      else
        rebuilt.add_constraint(mc.name, mc.constraint);
    }
    for (const kin::JointFriction& f : m.frictions()) rebuilt.add_friction(f);
    m = std::move(rebuilt);
  }

  void read_element(const YAML::Node& node) {
    MapReader keys(node, doc_.file, "element");
    const std::string type = keys.string("type");
    const ElementTypeSpec* spec = elements_ ? elements_(type) : nullptr;
    if (!spec || !spec->read)
      fail_at(keys.mark("type"), "unknown element type " + io::quote(type) + " (no loaded plugin provides it; see `gearkit plugins`)");
    const std::string name = unique_name(keys.optional_string("name"), type, node);
    MapReader element(node, doc_.file, type + " " + io::quote(name));
    element.string("type");
    element.optional_string("name");
    ElementReader reader(element, mech_.model);
    std::unique_ptr<kin::Constraint> c;
    try {
      c = spec->read(reader);
    } catch (const kin::ElementError& e) {
      fail_at(element.mark(e.field()), e.what());
    }
    if (!c) fail(node, "element type " + io::quote(type) + " built nothing");
    element.finish();
    add(name, std::shared_ptr<const kin::Constraint>(std::move(c)), node);
  }

  void read_driver(const YAML::Node& node) {
    MapReader d(node, doc_.file, "driver");
    const std::string type = d.choice("type", {"angle", "displacement", "point"});
    const std::string name = unique_name(d.optional_string("name"), type + " driver", node);
    MechanismDriver md;
    md.name = name;
    const bool angular = type == "angle";
    md.quantity = angular ? kin::DriverQuantity::angle : kin::DriverQuantity::displacement;
    const Quantity q = angular ? Quantity::angle : Quantity::length;
    const std::string unit = angular ? "deg" : "mm";
    kin::Motion motion;
    motion.speed = d.quantity_or("speed", angular ? Quantity::angular_velocity : Quantity::velocity,
                                 angular ? "rad/s" : "m/s", 1.0);
    motion.acceleration = d.quantity_or("acceleration", angular ? Quantity::angular_acceleration : Quantity::acceleration,
                                        angular ? "rad/s^2" : "m/s^2", 0.0);
    if (d.has("speed")) md.speed = motion.speed;
    double drawn = 0.0;
    std::shared_ptr<const kin::Constraint> c;
    if (angular) {
      const int body = link_ref(d.node("link"));
      if (body == kGround) fail(d.node("link"), "the ground cannot be driven");
      const int reference = d.has("relative_to") ? link_ref(d.node("relative_to")) : kGround;
      drawn = angle_of(body) - angle_of(reference);
      c = std::make_shared<kin::AngleDriver>(body, reference, motion);
    } else if (type == "point") {
      c = point_driver(d, motion, drawn);
    } else {
      const YAML::Node joint = d.node("joint");
      const std::string jname = scalar(joint, doc_.file, "a prismatic joint name");
      const auto it = prismatics_.find(jname);
      if (it == prismatics_.end()) fail(joint, "expected the name of a prismatic joint, found " + io::quote(jname));
      const auto& [slider, guide, axis] = it->second;
      c = std::make_shared<kin::DisplacementDriver>(slider, guide, axis, motion);
    }
    const double value = d.has("value") ? d.quantity("value", q, unit) : drawn;
    if (auto r = d.optional_node("range")) md.range = read_range(*r, q, unit);
    std::optional<double> effort;
    if (d.has("effort")) effort = d.quantity("effort", angular ? Quantity::torque : Quantity::force, angular ? "N*m" : "N");
    if (effort) effort_nodes_.push_back(d.node("effort"));
    d.finish();
    add(name, c, node);
    // The drawn input: where the drawing is assembled and every continuation starts (a sweep
    // reaches its range from there), so that the drawing picks the branch.
    mech_.model.set_driver(static_cast<int>(mech_.model.constraints().size()) - 1, md.quantity, value);
    if (effort) mech_.model.set_driver_effort(static_cast<int>(mech_.model.drivers().size()) - 1, *effort);
    mech_.drivers.push_back(md);
  }

  // A point of a link moved along a direction: u . (P - O) = f(t), with O a point (`from`,
  // default the ground's origin) and u at `axis` in O's link frame. Its drawn value is the
  // drawing's u . (P - O).
  std::shared_ptr<const kin::Constraint> point_driver(MapReader& d, const kin::Motion& motion, double& drawn) {
    const BodyPoint p = point_ref(d.node("point"));
    const BodyPoint from = d.has("from") ? point_ref(d.node("from")) : BodyPoint{kGround, Eigen::Vector2d::Zero()};
    if (p.body == kGround) fail(d.node("point"), "expected a point of a moving link, found a ground point");
    if (p.body == from.body) fail(d.node("from"), "expected 'from' on another link than the driven point");
    const double axis = d.quantity("axis", Quantity::angle, "deg");
    const Eigen::Vector2d u(std::cos(axis), std::sin(axis));
    const auto global = [&](const BodyPoint& x) {
      if (x.body == kGround) return x.local;
      const kin::Body& b = mech_.model.bodies()[static_cast<std::size_t>(x.body)];
      return Eigen::Vector2d(b.position_guess + kin::rotate(b.angle_guess, x.local));
    };
    drawn = kin::rotate(angle_of(from.body), u).dot(global(p) - global(from));
    return std::make_shared<kin::DisplacementDriver>(p, from, u, motion);
  }

  DriverRange read_range(const YAML::Node& r, Quantity q, const std::string& unit) {
    if (!r.IsSequence() || (r.size() != 2 && r.size() != 3)) fail(r, "expected 'range' as [start, end] or [start, end, step]");
    DriverRange range;
    range.start = scalar_quantity(r[0], doc_.file, q, unit);
    range.end = scalar_quantity(r[1], doc_.file, q, unit);
    range.step = r.size() == 3 ? scalar_quantity(r[2], doc_.file, q, unit) : std::abs(range.end - range.start) / 100.0;
    if (!(range.step > 0.0) || range.start == range.end) fail(r, "expected a range with start != end and a step > 0");
    if (std::abs(range.end - range.start) / range.step + 1 > io::limits::kSweepPositions)
      fail(r, fmt::format("expected at most {:.0f} positions in the range", io::limits::kSweepPositions));
    return range;
  }

  void read_loads(const YAML::Node& node) {
    MapReader l(node, doc_.file, "loads");
    if (auto g = l.optional_node("gravity")) {
      if (g->IsScalar())
        mech_.model.set_gravity({0.0, -scalar_quantity(*g, doc_.file, Quantity::acceleration, "m/s^2")});
      else
        mech_.model.set_gravity(read_xy(*g, doc_.file, Quantity::acceleration, "m/s^2", "gravity"));
    }
    if (l.has("forces"))
      for (const YAML::Node& f : l.sequence("forces", io::limits::kMechanismItems, "forces")) {
        MapReader r(f, doc_.file, "force");
        kin::PointForce pf;
        pf.at = point_ref(r.node("at"));
        pf.unknown = r.boolean_or("unknown", false);
        if (pf.unknown) {  // inverse kinetostatics: the magnitude along `direction` is solved
          const double a = r.quantity("direction", Quantity::angle, "deg");
          pf.force = {std::cos(a), std::sin(a)};
          unknown_nodes_.push_back(f);
        } else {
          pf.force = read_xy(r.node("force"), doc_.file, Quantity::force, "N", "a force");
        }
        pf.name = r.optional_string("name").value_or("force " + std::to_string(mech_.model.forces().size() + 1));
        r.finish();
        mech_.model.add_force(pf);
      }
    if (l.has("torques"))
      for (const YAML::Node& t : l.sequence("torques", io::limits::kMechanismItems, "torques")) {
        MapReader r(t, doc_.file, "torque");
        kin::BodyTorque bt;
        bt.body = link_ref(r.node("link"));
        bt.unknown = r.boolean_or("unknown", false);
        bt.torque = bt.unknown ? 1.0 : r.quantity("torque", Quantity::torque, "N*m");
        if (bt.unknown) unknown_nodes_.push_back(t);
        bt.name = r.optional_string("name").value_or("torque " + std::to_string(mech_.model.torques().size() + 1));
        r.finish();
        mech_.model.add_torque(bt);
      }
    if (l.has("springs"))
      for (const YAML::Node& s : l.sequence("springs", io::limits::kMechanismItems, "springs")) {
        MapReader r(s, doc_.file, "spring");
        kin::Spring sp;
        const std::vector<YAML::Node> between = r.sequence("between");
        if (between.size() != 2) fail(r.node("between"), "expected 'between' as two point references");
        sp.a = point_ref(between[0]);
        sp.b = point_ref(between[1]);
        sp.stiffness = r.quantity("stiffness", Quantity::stiffness, "N/m");
        sp.free_length = r.quantity("free_length", Quantity::length, "mm");
        sp.preload = r.quantity_or("preload", Quantity::force, "N", 0.0);
        sp.name = r.optional_string("name").value_or("spring " + std::to_string(mech_.model.springs().size() + 1));
        r.finish();
        mech_.model.add_spring(sp);
      }
    l.finish();
  }

  // Inverse kinetostatics: one unknown load per driver with a given effort.
  void check_unknown_loads() const {
    if (unknown_nodes_.size() == effort_nodes_.size()) return;
    if (unknown_nodes_.size() > effort_nodes_.size())
      fail(unknown_nodes_[effort_nodes_.size()], fmt::format("expected one driver with a given 'effort' per unknown load, found "
                                                             "{} unknown load(s) and {} effort(s)", unknown_nodes_.size(), effort_nodes_.size()));
    fail(effort_nodes_[unknown_nodes_.size()], fmt::format("expected one unknown load (unknown: true) per driver with a given "
                                                           "'effort', found {} effort(s) and {} unknown load(s)", effort_nodes_.size(), unknown_nodes_.size()));
  }

  void read_output(const YAML::Node& node) {
    MapReader r(node, doc_.file, "output");
    kin::Output o;
    o.name = r.string("name");
    for (const kin::Output& other : mech_.outputs)
      if (other.name == o.name) fail(r.node("name"), "duplicate output " + io::quote(o.name));
    const std::string type = r.choice("type", {"x", "y", "angle", "slider", "speed", "acceleration"});
    if (type == "x" || type == "y") {
      o.kind = type == "x" ? kin::OutputKind::point_x : kin::OutputKind::point_y;
      o.point = point_ref(r.node("point"));
      if (r.has("from")) o.from = point_ref(r.node("from"));
    } else if (type == "speed" || type == "acceleration") {
      o.kind = type == "speed" ? kin::OutputKind::point_speed : kin::OutputKind::point_acceleration;
      o.point = point_ref(r.node("point"));
    } else if (type == "angle") {
      read_angle_output(r, o);
    } else {
      o.kind = kin::OutputKind::slider_displacement;
      const YAML::Node joint = r.node("joint");
      const std::string jname = scalar(joint, doc_.file, "a prismatic joint name");
      if (!prismatics_.count(jname)) fail(joint, "expected the name of a prismatic joint, found " + io::quote(jname));
      o.constraint = *mech_.model.constraint_index(jname);
    }
    r.finish();
    mech_.outputs.push_back(o);
  }

  // An angle output: of `link`'s x axis, or `along: [link.A, link.B]` (the direction A -> B),
  // relative to `relative_to`, measured from `zero` (90 deg: from the vertical), `clockwise`.
  void read_angle_output(MapReader& r, kin::Output& o) const {
    o.kind = kin::OutputKind::body_angle;
    if (r.has("along")) {
      const YAML::Node along = r.node("along");
      if (!along.IsSequence() || along.size() != 2) fail(along, "expected 'along' as two points [link.A, link.B]");
      const BodyPoint a = point_ref(along[0]), b = point_ref(along[1]);
      if (a.body != b.body || a.body == kGround) fail(along, "expected two points of one moving link");
      if ((b.local - a.local).norm() < 1e-12) fail(along, "expected two distinct points");
      o.body = a.body;
      o.offset = std::atan2(b.local.y() - a.local.y(), b.local.x() - a.local.x());
      if (r.has("link") && link_ref(r.node("link")) != o.body) fail(r.node("link"), "expected the link of the 'along' points");
    } else {
      o.body = link_ref(r.node("link"));
    }
    o.reference = r.has("relative_to") ? link_ref(r.node("relative_to")) : kGround;
    o.zero = r.quantity_or("zero", Quantity::angle, "deg", 0.0);
    o.sense = r.boolean_or("clockwise", false) ? -1 : 1;
  }

  const io::YamlDocument& doc_;
  const ElementTypeLookup& elements_;
  Mechanism mech_;
  std::vector<YAML::Node> link_nodes_;
  std::set<int> placed_;
  std::vector<std::pair<BodyPoint, BodyPoint>> revolutes_;
  std::map<int, std::vector<std::pair<Eigen::Vector2d, std::string>>> pins_;  // per link: pin points and their references
  struct PrismaticInfo {
    BodyPoint slider, guide;
    Eigen::Vector2d axis;
  };
  std::map<std::string, PrismaticInfo> prismatics_;
  std::vector<PendingContact> contacts_;
  std::vector<YAML::Node> unknown_nodes_, effort_nodes_;  // inverse kinetostatics
};

}  // namespace

const std::vector<std::string>& builtin_joint_types() {
  static const std::vector<std::string> types{"revolute", "prismatic", "pin_in_slot", "contact"};
  return types;
}

Mechanism read_mechanism(const io::YamlDocument& document, const ElementTypeLookup& elements) {
  return Reader(document, elements).read();
}

Mechanism load_mechanism(const std::string& path, const ElementTypeLookup& elements) {
  return read_mechanism(io::load_yaml_file(path), elements);
}

}  // namespace gearkit::mechanism
