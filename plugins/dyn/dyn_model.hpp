#pragma once
// The `gearkit dyn` model file (docs/dyn.md), read into plain structs with every value in SI and
// the place of every field kept, so that a problem found later is reported at its line.
#include "dyn_torque_law.hpp"

#include <gearkit/dyn/drive_line.hpp>
#include <gearkit/dyn/reduction.hpp>
#include <gearkit/io/error.hpp>
#include <gearkit/mechanism/element_type.hpp>

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace gearkit::plugins::dyn {

struct Motor {
  io::SourceMark mark;
  std::optional<double> speed;   ///< rad/s, nominal
  std::optional<double> power;   ///< W at the nominal speed
  std::optional<TorqueLaw> torque;
};

struct Load {
  io::SourceMark mark;
  std::string name = "load";
  std::optional<double> radius;        ///< m, drum or pulley
  std::optional<TorqueLaw> resisting;  ///< N*m on the load shaft
  double force = 0;                    ///< N resisting at the radius
  /// Reduced inertia of a linkage driven by the load shaft, against that shaft's angle (e.g. from
  /// a `gearkit kin` sweep), added to the shaft's constant inertia.
  std::optional<gd::InertiaTable> inertia_table;
  io::SourceMark inertia_table_mark;
};

struct FlywheelQuestion {
  io::SourceMark mark;
  double cycle = 0;        ///< rad of the load shaft
  double fluctuation = 0;  ///< delta
  io::SourceMark fluctuation_mark;
  std::optional<TorqueLaw> drive, resisting;
};

struct EnergyLoad {
  io::SourceMark mark;
  std::string name;
  std::optional<TorqueLaw> torque;
  double force = 0;          ///< N at the radius
  double energy = 0;         ///< J per cycle
  double mass_to_speed = 0;  ///< kg per cycle brought from rest to the rim speed
  bool useful = false;
};

struct EnergyPhase {
  io::SourceMark mark;
  std::string name;
  double from = 0, to = 0;  ///< rad of the load shaft
};

struct EnergyQuestion {
  io::SourceMark mark;
  std::optional<double> cycle;       ///< rad of the load shaft
  std::optional<double> cycle_time;  ///< s
  std::optional<double> report_time; ///< s
  std::vector<EnergyLoad> loads;
  std::vector<EnergyPhase> phases;
};

struct MotionQuestion {
  io::SourceMark mark;
  double speed = 0;         ///< rad/s of the motor shaft at t = 0
  double angle = 0;         ///< rad of the motor shaft at t = 0
  double t_end = 10;        ///< s
  double output_step = 0;   ///< s (0 = t_end / 2000)
  double steady_tolerance = 1e-6;
  std::vector<double> acceleration_at;  ///< rad/s of the motor shaft
  bool with_flywheel = false;  ///< add the flywheel sized by the flywheel question to the load shaft
  io::SourceMark with_flywheel_mark;
};

/// One term of a virtual-power balance at one instant: a force at a point, or a body's weight
/// and d'Alembert inertia force (-m a), with the velocity of the point or centre of mass.
struct ReducedForceTerm {
  io::SourceMark mark;
  std::string name;
  gd::Vec2 velocity;      ///< m/s
  gd::Vec2 force;         ///< N, applied force
  double mass = 0;        ///< kg: adds the weight (0, -m g) and -m a
  gd::Vec2 acceleration;  ///< m/s^2 of the centre of mass
  double gravity = gd::standard_gravity;
};

struct ReducedForceQuestion {
  io::SourceMark mark;
  std::string point = "A";
  gd::Vec2 point_velocity;            ///< m/s of the reduction point
  std::optional<double> shaft_speed;  ///< rad/s of a shaft to reduce to as a torque as well
  std::vector<ReducedForceTerm> terms;
};

struct Model {
  std::string file;
  std::string title;
  bool has_drive_line = false;  ///< the file describes a motor, stages or a load
  gd::DriveLine line;
  std::vector<io::SourceMark> stage_marks;
  Motor motor;
  Load load;
  std::optional<FlywheelQuestion> flywheel;
  std::optional<EnergyQuestion> energy;
  std::optional<MotionQuestion> motion;
  std::optional<ReducedForceQuestion> reduced_force;
};

/// Reads and checks a model file; `elements` finds the element types of a load's mechanism
/// file (the host's, so that every mechanism `gearkit kin` reads works here too).
/// @throws io::InputError (file:line:column) on bad input.
Model load_model(const std::string& path, const mechanism::ElementTypeLookup& elements);

}  // namespace gearkit::plugins::dyn
