#pragma once
#include <gearkit/kin/plugin.hpp>

namespace gearkit::plugins::cam {

/// `gearkit cam ...`: returns the exit status; throws gearkit::io::InputError on bad input.
int run_cam_command(kin::CommandContext& context);

}  // namespace gearkit::plugins::cam
