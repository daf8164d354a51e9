#pragma once
// `gearkit gear rack`, `gearkit gear worm`, `gearkit gear crossed`: the tables and forces of a
// rack and pinion, a cylindrical worm pair and a crossed helical pair (libgear rack_pinion.hpp,
// worm.hpp, crossed_helical.hpp; docs/gear-types.md). Each returns the exit status and throws
// gearkit::io::InputError on bad input. context.args starts with the subcommand's name.
#include <gearkit/plugin/plugin.hpp>

namespace gearkit::plugins::gear {

int run_gear_rack_command(plugin::CommandContext& context);
int run_gear_worm_command(plugin::CommandContext& context);
int run_gear_crossed_command(plugin::CommandContext& context);

}  // namespace gearkit::plugins::gear
