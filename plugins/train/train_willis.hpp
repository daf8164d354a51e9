#pragma once
// `gearkit train FILE --willis M1,M2,...`: Willis' equation of each simple stage written in the
// user's velocity vector u = {w_M1, w_M2, ...}, planets eliminated (libtrain stage_relations).
#include <gearkit/io/report.hpp>
#include <gearkit/train/model.hpp>

#include <string>

namespace gearkit::plugins::train {

/// Adds the table "Willis equations in u = {...}" and JSON "willis_in_vector". Only the stages
/// whose members all belong to the vector are written; a member of the vector that no such stage
/// relates is named in a warning.
/// @throws io::InputError naming --willis for an unknown or repeated member, or a planet.
void add_willis_in_vector(io::Report& report, const gearkit::train::TrainModel& model, const std::string& members);

}  // namespace gearkit::plugins::train
