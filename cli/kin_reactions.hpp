#pragma once
// `gearkit kin`: how the reactions of the constraints are reported. Joints give a force on
// their first link; elements add the quantities they name (Constraint::reaction), such as a gear
// mesh's tooth forces or a cam's contact force.
#include "kin_analysis.hpp"

#include <gearkit/io/json_writer.hpp>
#include <gearkit/io/report.hpp>
#include <gearkit/kin/kinetostatics.hpp>
#include <gearkit/kin/model.hpp>

#include <optional>

namespace gearkit::cli {

/// One entry of `reactions[]`: joint, kind, on, force_N, moment_Nm (when not zero) and, for an
/// element, `values` keyed by symbol and unit ("F_n_N", "T_2_Nm").
void write_reaction(io::JsonWriter& w, const kin::Model& model, const kin::ConstraintReaction& reaction);

/// The table "Element reactions" (element, kind, quantity, value, unit, meaning), or nullopt when
/// no constraint names a value.
std::optional<io::Table> element_reaction_table(const kin::ForceAnalysis& forces);

/// Adds to a position's JSON what the kinetostatics found beyond the reactions: the solved
/// `unknown_loads` (inverse kinetostatics) and, with friction, `friction` (joints, ideal effort,
/// `forward` and `reverse` senses with effort, efficiency, self-locking and the wedging
/// coefficients) and `force_warnings`, as an object of those members (empty when there are none).
/// Efforts that are not finite (a self-locking sense) are null.
nlohmann::json force_details_json(const kin::Model& model, const kin::ForceAnalysis& forces, int driver, bool angular);

/// The same for the report of a single position (with loads): tables "Unknown loads" and
/// "Friction", notes on both senses of motion, the warnings, and the free-body diagram of each
/// link (a table per link; JSON `free_bodies`).
void add_force_details_report(io::Report& report, const kin::Model& model, const KinPosition& position, int driver,
                              bool angular);

}  // namespace gearkit::cli
