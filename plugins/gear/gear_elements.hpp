#pragma once
#include <gearkit/plugin/plugin.hpp>

namespace gearkit::plugins::gear {

/// Registers this plugin's element types for mechanism files (gear_mesh).
void register_elements(plugin::PluginRegistrar& registrar);

}  // namespace gearkit::plugins::gear
