#pragma once
#include <gearkit/plugin/plugin.hpp>

namespace gearkit::plugins::gear {

/// `gearkit gear ...`: returns the exit status; throws gearkit::io::InputError on bad input.
int run_gear_command(plugin::CommandContext& context);

}  // namespace gearkit::plugins::gear
