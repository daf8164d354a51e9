#pragma once
// `gearkit gear bevel`: the table of a straight, Zerol or spiral bevel pair (libgear bevel.hpp)
// with its virtual gears and, for a torque, the forces on both gears (docs/bevel.md).
#include <gearkit/plugin/plugin.hpp>

namespace gearkit::plugins::gear {

/// Runs `gearkit gear bevel ARGS` (context.args starts with "bevel"); returns the exit status.
/// @throws gearkit::io::InputError on bad input, naming the option.
int run_gear_bevel_command(plugin::CommandContext& context);

}  // namespace gearkit::plugins::gear
