#pragma once
// A mechanism as read from a file: the solver's model plus what the file says about how to
// analyse it (driver ranges, named outputs). Built by reader.hpp or by hand from C++.
#include <gearkit/kin/model.hpp>
#include <gearkit/kin/output.hpp>

#include <optional>
#include <string>
#include <vector>

namespace gearkit::mechanism {

/// A driver's sweep range as written in the file: start, end, step in SI (rad or m).
struct DriverRange {
  double start = 0.0, end = 0.0, step = 0.0;
};

struct MechanismDriver {
  std::string name;
  kin::DriverQuantity quantity = kin::DriverQuantity::angle;
  std::optional<DriverRange> range;
  /// The `speed:` the file gives [rad/s or m/s] (the solver then uses 1 when absent): the
  /// animation's loop time when --speed is not given.
  std::optional<double> speed;
};

struct Mechanism {
  std::string title;
  std::string file;
  kin::Model model;
  std::vector<MechanismDriver> drivers;  ///< in model.drivers() order
  std::vector<kin::Output> outputs;
};

}  // namespace gearkit::mechanism
