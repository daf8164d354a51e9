#pragma once
#include <gearkit/plugin/plugin.hpp>

namespace gearkit::plugins::dyn {

/// `gearkit dyn FILE.yaml ...`: returns the exit status; throws gearkit::io::InputError on bad input.
int run_dyn_command(plugin::CommandContext& context);

}  // namespace gearkit::plugins::dyn
