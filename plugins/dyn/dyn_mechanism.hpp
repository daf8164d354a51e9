#pragma once
// The bridge from a mechanism model of `gearkit kin` to the dynamics: the reduced inertia of the
// linkage at its driving shaft, tabulated over one turn from the solver's velocity coefficients.
#include <gearkit/dyn/reduction.hpp>
#include <gearkit/io/error.hpp>
#include <gearkit/mechanism/element_type.hpp>

#include <string>

namespace gearkit::plugins::dyn {

/// Reduced inertia I(theta) = sum_i m_i |dr_Gi/dtheta|^2 + I_Gi (dphi_i/dtheta)^2 of the links of
/// the mechanism file `path` (docs/kin.md) at its first driver, which must be an angle: the load
/// shaft. The driver turns one revolution from 0 in `intervals` steps; the solver keeps the
/// assembly branch of the drawing.
/// @param where the model-file position that named the mechanism, for messages
/// @param elements the host's element types (gear meshes, cam followers, epicyclic trains)
/// @throws io::InputError if the file is bad (its own file:line:column), has no angle driver,
///         has no link with mass, or cannot turn a full revolution (a dead point on the way).
gearkit::dyn::InertiaTable mechanism_inertia_table(const std::string& path, int intervals,
                                                   const io::SourceMark& where,
                                                   const mechanism::ElementTypeLookup& elements);

}  // namespace gearkit::plugins::dyn
