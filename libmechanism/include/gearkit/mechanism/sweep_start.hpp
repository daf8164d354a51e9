#pragma once
// How a front end starts a sweep of a mechanism read from a file: the sweep's options and the
// way from the drawn configuration to the sweep's first position on the drawing's own branch.
// Shared by `gearkit kin` (cli/kin_analysis.cpp) and the Python module (python/src/kin.cpp), so
// that both follow the same branch and give the same numbers.
#include <gearkit/kin/data.hpp>
#include <gearkit/kin/sweep.hpp>
#include <gearkit/mechanism/mechanism.hpp>

namespace gearkit::mechanism {

/// A sweep of driver `driver` from `from` to `to` by `step` [rad or m], dead points located to
/// 1e-9 of its span (min_step); positions only unless `velocities`; the other branch at change
/// points if `switch_branch`.
kin::SweepOptions sweep_options(int driver, double from, double to, double step, bool velocities, bool switch_branch);

/// Moves `data` from the drawing to just past the sweep's start (kin::change_point_offset) by
/// continuation in steps of 2 deg (or 2 mm), so that the sweep's first Newton solve starts next
/// to the start on the drawing's own branch: from the drawing itself Newton may jump to another
/// branch, and at a start on a change point it could not tell which branch the drawing is on.
/// [in,out] data.q, data.inputs(driver). Left at the drawing when the way is blocked (a dead
/// point: the sweep's own fallbacks then apply). @throws std::invalid_argument for a driver
/// index outside mech.drivers.
void approach_start(const Mechanism& mech, kin::Data& data, int driver, const kin::SweepOptions& sweep);

}  // namespace gearkit::mechanism
