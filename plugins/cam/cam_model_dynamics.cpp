// The cam model's `dynamics:` and `contact:` sections and the conjugate cam's second roller.
#include "cam_model.hpp"

#include <gearkit/io/error.hpp>

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace gearkit::plugins::cam {

namespace gc = gearkit::cam;

namespace {

constexpr double kRpm = std::numbers::pi / 30;

/// A quantity that must be >= 0 (or > 0), with its unit for the message.
double non_negative(io::MapReader& r, const std::string& key, const char* unit, double factor, double value,
                    bool strictly = false) {
  if (!std::isfinite(value) || value < 0 || (strictly && value == 0))
    io::fail_at(r.mark(key), fmt::format("expected {} {} 0 {}, found {:.6g} {}", key, strictly ? ">" : ">=", unit,
                                         value / factor, unit));
  return value;
}

/// The follower's quantities: translating in N, kg, N/mm...; oscillating in N*m, kg*m^2, N*m/rad...
struct TrainUnits {
  io::Quantity mass, spring, force, damping;
  const char *mass_unit, *spring_unit, *force_unit, *damping_unit;
  double spring_factor;  // SI per unit shown in messages
};

TrainUnits units_of(bool oscillating) {
  if (oscillating)
    return {io::Quantity::moment_of_inertia, io::Quantity::torsional_stiffness, io::Quantity::torque,
            io::Quantity::torsional_damping, "kg*m^2", "N*m/rad", "N*m", "N*m*s/rad", 1};
  return {io::Quantity::mass, io::Quantity::stiffness, io::Quantity::force, io::Quantity::damping,
          "kg", "N/mm", "N", "N*s/m", 1000};
}

void read_train(io::MapReader& r, bool oscillating, DynamicsInput& in) {
  const TrainUnits u = units_of(oscillating);
  gc::FollowerTrain& t = in.train;
  const std::string mass_key = oscillating ? "inertia" : "mass";
  t.mass = non_negative(r, mass_key, u.mass_unit, 1, r.quantity(mass_key, u.mass, u.mass_unit), true);
  if (const auto k = r.optional_quantity("spring_rate", u.spring, u.spring_unit))
    in.spring_rate = non_negative(r, "spring_rate", u.spring_unit, u.spring_factor, *k);
  if (const auto f = r.optional_quantity("preload", u.force, u.force_unit))
    in.preload = non_negative(r, "preload", u.force_unit, 1, *f);
  if (r.has("damping") && r.has("damping_ratio"))
    io::fail_at(r.mark("damping_ratio"), "expected damping or damping_ratio, not both");
  if (const auto z = r.optional_number("damping_ratio")) {
    if (!(*z >= 0 && *z <= 10)) io::fail_at(r.mark("damping_ratio"), fmt::format("expected a damping ratio from 0 to 10, found {:.6g}", *z));
    in.damping_ratio = *z;
  }
  t.damping = non_negative(r, "damping", u.damping_unit, 1, r.quantity_or("damping", u.damping, u.damping_unit, 0));
  t.load = r.quantity_or("load", u.force, u.force_unit, 0);
  t.friction = r.optional_number("friction").value_or(0);
  if (!(t.friction >= 0 && t.friction <= 2))
    io::fail_at(r.mark("friction"), fmt::format("expected a friction coefficient from 0 to 2, found {:.6g}", t.friction));
  t.stiffness = non_negative(r, "follower_stiffness", u.spring_unit, u.spring_factor,
                             r.quantity_or("follower_stiffness", u.spring, u.spring_unit, 0));
  t.roller_inertia = non_negative(r, "roller_inertia", "kg*m^2", 1,
                                  r.quantity_or("roller_inertia", io::Quantity::moment_of_inertia, "kg*m^2", 0));
}

}  // namespace

std::optional<std::string> jump_margin_problem(double design_speed, double margin) {
  if (!(margin >= 1 && margin <= kMaxJumpMargin))
    return fmt::format("expected a jump margin from 1 to {:g} (a factor over the design speed), found {:.6g}", kMaxJumpMargin, margin);
  if (!(design_speed * margin <= kMaxSpeedRpm * kRpm))
    return fmt::format("expected the design speed times the jump margin up to {:.6g} rpm, found {:.6g} rpm", kMaxSpeedRpm,
                       design_speed * margin / kRpm);
  return std::nullopt;
}

namespace {

void read_speeds(io::MapReader& r, const CamModel& model, DynamicsInput& in) {
  const auto speed = r.optional_quantity("design_speed", io::Quantity::angular_velocity, "rpm");
  if (!speed && !model.omega)
    io::fail_at(r.mark(), "expected dynamics.design_speed or cam.speed: the dynamics needs a cam speed");
  in.design_speed = speed.value_or(model.omega.value_or(0));
  if (!(in.design_speed > 0 && in.design_speed <= kMaxSpeedRpm * kRpm))
    io::fail_at(r.mark("design_speed"), fmt::format("expected a design speed > 0 and up to {:.6g} rpm, found {:.6g} rpm",
                                                    kMaxSpeedRpm, in.design_speed / kRpm));
  in.jump_margin = r.optional_number("jump_margin").value_or(1.0);
  if (const auto problem = jump_margin_problem(in.design_speed, in.jump_margin)) io::fail_at(r.mark("jump_margin"), *problem);
  in.jump_search_to = r.quantity_or("jump_search_to", io::Quantity::angular_velocity, "rpm",
                                    std::min(20 * in.design_speed, kMaxSpeedRpm * kRpm));
  if (!(in.jump_search_to > 0 && in.jump_search_to <= kMaxSpeedRpm * kRpm))
    io::fail_at(r.mark("jump_search_to"), fmt::format("expected a speed > 0 and up to {:.6g} rpm, found {:.6g} rpm",
                                                      kMaxSpeedRpm, in.jump_search_to / kRpm));
  if (const auto node = r.optional_node("speed_sweep")) {
    io::MapReader s(*node, r.file(), "speed_sweep");
    SpeedSweepInput sweep;
    sweep.from = s.quantity_or("from", io::Quantity::angular_velocity, "rpm", 0);
    sweep.to = s.quantity("to", io::Quantity::angular_velocity, "rpm");
    const long long steps = s.optional_integer("steps").value_or(50);
    if (steps < 1 || steps > kMaxSweepSteps)
      io::fail_at(s.mark("steps"), fmt::format("expected from 1 to {} steps, found {}", kMaxSweepSteps, steps));
    sweep.steps = static_cast<int>(steps);
    if (!(sweep.from >= 0 && sweep.to > sweep.from && sweep.to <= kMaxSpeedRpm * kRpm))
      io::fail_at(s.mark("to"), fmt::format("expected 0 <= from < to <= {:.6g} rpm, found {:.6g} to {:.6g} rpm",
                                            kMaxSpeedRpm, sweep.from / kRpm, sweep.to / kRpm));
    s.finish();
    in.sweep = sweep;
  }
}

}  // namespace

void read_second_roller(io::MapReader& follower, CamModel& model) {
  const auto node = follower.optional_node("second_roller");
  if (!node) return;
  io::MapReader r(*node, follower.file(), "second_roller");
  gc::SecondRoller& s = model.design.follower.second;
  if (model.design.follower.motion == gc::FollowerMotion::oscillating) {
    s.arm_length = r.quantity("arm_length", io::Quantity::length, "mm") * 1000;
    s.arm_angle = r.quantity("arm_angle", io::Quantity::angle, "deg");
  } else {
    s.distance = r.quantity("distance", io::Quantity::length, "mm") * 1000;
  }
  s.roller_radius = r.quantity_or("roller_radius", io::Quantity::length, "mm", 0) * 1000;
  for (const char* key : {"arm_length", "distance", "roller_radius"}) {
    const double v = std::string(key) == "arm_length" ? s.arm_length : std::string(key) == "distance" ? s.distance : s.roller_radius;
    if (!(std::abs(v) <= kMaxLengthMm))
      io::fail_at(r.mark(key), fmt::format("expected a length of at most {} mm, found {:.6g} mm", kMaxLengthMm, v));
  }
  r.finish();
}

void read_dynamics(io::MapReader& root, CamModel& model) {
  const auto node = root.optional_node("dynamics");
  if (!node) return;
  io::MapReader r(*node, root.file(), "dynamics");
  DynamicsInput in;
  in.mark = r.has("preload") ? r.mark("preload") : r.mark();
  const bool oscillating = model.design.follower.motion == gc::FollowerMotion::oscillating;
  read_train(r, oscillating, in);
  in.min_force = r.quantity_or("min_contact_force", io::Quantity::force, "N", 0);
  if (!(in.min_force >= 0)) io::fail_at(r.mark("min_contact_force"), fmt::format("expected a force >= 0 N, found {:.6g} N", in.min_force));
  read_speeds(r, model, in);
  if (const auto n = r.optional_integer("samples")) {
    if (*n < kMinDynamicsSamples || *n > kMaxDynamicsSamples)
      io::fail_at(r.mark("samples"), fmt::format("expected from {} to {} samples, found {}", kMinDynamicsSamples,
                                                 kMaxDynamicsSamples, *n));
    in.samples = static_cast<int>(*n);
  }
  if (const auto delta = r.optional_number("fluctuation")) {
    if (!(*delta > 0 && *delta < 1))
      io::fail_at(r.mark("fluctuation"), fmt::format("expected a speed fluctuation between 0 and 1, found {:.6g}", *delta));
    in.fluctuation = *delta;
  }
  const bool spring = model.design.follower.closure == gc::Closure::spring;
  // c = 2 zeta sqrt(k M): without a spring (form closure, or a rate of 0) and without the
  // train's own stiffness there is no k for the ratio to refer to.
  if (in.damping_ratio && in.train.stiffness == 0 && (spring ? in.spring_rate == 0.0 : in.spring_rate.value_or(0) == 0))
    io::fail_at(r.mark("damping_ratio"),
                fmt::format("expected follower_stiffness (or a spring_rate > 0) with damping_ratio: the ratio is of the "
                            "critical damping 2 sqrt(k M) and this follower has no {}; or give the damping itself "
                            "(damping: ... {})",
                            spring ? "spring" : "spring (form closure)", units_of(oscillating).damping_unit));
  in.train.spring_rate = in.spring_rate.value_or(0);
  in.train.preload = in.preload.value_or(0);
  if (!spring && (!in.spring_rate || !in.preload)) {
    // Form closure needs no spring; one given is used as it is (a spring-assisted groove).
    in.spring_rate = in.spring_rate.value_or(0), in.preload = in.preload.value_or(0);
  }
  r.finish();
  model.dynamics = in;
}

void read_contact(io::MapReader& root, CamModel& model) {
  const auto node = root.optional_node("contact");
  if (!node) return;
  io::MapReader r(*node, root.file(), "contact");
  if (model.design.follower.contact == gc::Contact::knife_edge)
    io::fail_at(r.mark(), "a knife edge has no Hertz contact: contact stress needs a roller or a flat face");
  if (!model.dynamics) io::fail_at(r.mark(), "the contact stress needs the contact force: add a dynamics: section");
  ContactInput in;
  in.material.width = r.quantity("width", io::Quantity::length, "mm");
  if (!(in.material.width > 0 && in.material.width * 1000 <= kMaxLengthMm))
    io::fail_at(r.mark("width"), fmt::format("expected a contact width > 0 mm, found {:.6g} mm", in.material.width * 1000));
  auto material = [&](const char* key, double& E, double& nu) {
    const auto m = r.optional_node(key);
    if (!m) return;
    io::MapReader mr(*m, r.file(), key);
    E = mr.quantity_or("E", io::Quantity::pressure, "GPa", E);
    nu = mr.optional_number("poisson").value_or(nu);
    if (!(E > 0 && E <= 1e13)) io::fail_at(mr.mark("E"), fmt::format("expected a Young's modulus > 0 GPa, found {:.6g} GPa", E / 1e9));
    if (!(nu >= 0 && nu < 0.5)) io::fail_at(mr.mark("poisson"), fmt::format("expected a Poisson's ratio in [0, 0.5), found {:.6g}", nu));
    mr.finish();
  };
  material("cam", in.material.E_cam, in.material.nu_cam);
  material("follower", in.material.E_follower, in.material.nu_follower);
  if (const auto a = r.optional_quantity("allowable", io::Quantity::pressure, "MPa")) {
    if (!(*a > 0)) io::fail_at(r.mark("allowable"), fmt::format("expected an allowable stress > 0 MPa, found {:.6g} MPa", *a / 1e6));
    in.allowable = *a;
  }
  r.finish();
  model.contact = in;
}

}  // namespace gearkit::plugins::cam
