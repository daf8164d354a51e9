#pragma once
#include <gearkit/kin/plugin.hpp>

namespace gearkit::plugins::synth {

/// `gearkit synth TASK FILE.yaml [options]` (docs/synthesis.md).
int run_synth_command(kin::CommandContext& context);

}  // namespace gearkit::plugins::synth
