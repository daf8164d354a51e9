#pragma once
#include <gearkit/plugin/plugin.hpp>

namespace gearkit::plugins::train {

/// Registers this plugin's element types for mechanism files (epicyclic_train).
void register_elements(plugin::PluginRegistrar& registrar);

}  // namespace gearkit::plugins::train
