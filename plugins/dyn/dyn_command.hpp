#pragma once
#include <gearkit/kin/plugin.hpp>

namespace gearkit::plugins::dyn {

/// `gearkit dyn FILE.yaml ...`: returns the exit status; throws gearkit::io::InputError on bad input.
int run_dyn_command(kin::CommandContext& context);

}  // namespace gearkit::plugins::dyn
