#pragma once
// `gearkit train FILE --torque ... --rate`: the load capacity (libgear rating.hpp) of every mesh
// of a train from the torques and speeds the train analysis computes (docs/rating.md, docs/train.md).
#include <gearkit/io/report.hpp>
#include <gearkit/train/kinematics.hpp>
#include <gearkit/train/model.hpp>

#include <string>
#include <vector>

namespace gearkit::plugins::train {

/// Rates every mesh: gear torques from the ideal torque solution for `given_torque_Nm` on
/// `given_member` (load at `output`), speeds relative to each mesh's carrier from `speeds` and
/// `input_speeds_rad_s`. Face widths and materials come from the gears of `file` (`face_width`,
/// `material`) or its `rating:` section, which also holds the life and the other load options.
/// @throws io::InputError at file:line:column for missing or bad rating data.
void add_mesh_ratings(io::Report& report, const std::string& file, const gearkit::train::TrainModel& model,
                      const gearkit::train::SpeedSolution& speeds, const std::vector<gearkit::train::Condition>& conditions,
                      const std::vector<double>& input_speeds_rad_s, gearkit::train::MemberId output,
                      gearkit::train::MemberId given_member, double given_torque_Nm);

}  // namespace gearkit::plugins::train
