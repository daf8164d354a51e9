#pragma once
#include <gearkit/plugin/plugin.hpp>

#include <string>
#include <vector>

namespace gearkit::plugins::train {

/// `gearkit train synth reducer|planetary ...`: tooth counts for a target ratio.
/// @throws io::InputError for bad options.
int run_train_synth_command(plugin::CommandContext& context, const std::vector<std::string>& args);

}  // namespace gearkit::plugins::train
