#pragma once
#include <gearkit/plugin/plugin.hpp>

namespace gearkit::plugins::synth {

/// `gearkit synth TASK FILE.yaml [options]` (docs/synthesis.md).
int run_synth_command(plugin::CommandContext& context);

}  // namespace gearkit::plugins::synth
