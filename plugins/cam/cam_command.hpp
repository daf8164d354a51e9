#pragma once
#include <gearkit/plugin/plugin.hpp>

namespace gearkit::plugins::cam {

/// `gearkit cam ...`: returns the exit status; throws gearkit::io::InputError on bad input.
int run_cam_command(plugin::CommandContext& context);

}  // namespace gearkit::plugins::cam
