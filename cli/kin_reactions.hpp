#pragma once
// `gearkit kin`: how the reactions of the constraints are reported. Joints give a force on
// their first link; elements add the quantities they name (Constraint::reaction), such as a gear
// mesh's tooth forces or a cam's contact force.
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

}  // namespace gearkit::cli
