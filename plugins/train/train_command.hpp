#pragma once
#include <gearkit/plugin/plugin.hpp>

namespace gearkit::plugins::train {

/// `gearkit train ...`: returns the exit status; throws gearkit::io::InputError on bad input.
int run_train_command(plugin::CommandContext& context);

}  // namespace gearkit::plugins::train
