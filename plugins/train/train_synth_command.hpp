#pragma once
#include <gearkit/kin/plugin.hpp>

#include <string>
#include <vector>

namespace gearkit::plugins::train {

/// `gearkit train synth reducer|planetary ...`: tooth counts for a target ratio.
/// @throws io::InputError for bad options.
int run_train_synth_command(kin::CommandContext& context, const std::vector<std::string>& args);

}  // namespace gearkit::plugins::train
