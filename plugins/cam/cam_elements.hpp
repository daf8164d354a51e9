#pragma once
#include <gearkit/plugin/plugin.hpp>

namespace gearkit::plugins::cam {

/// Registers this plugin's element types for mechanism files (cam_follower).
void register_elements(plugin::PluginRegistrar& registrar);

}  // namespace gearkit::plugins::cam
