#pragma once
#include <gearkit/kin/plugin.hpp>

namespace gearkit::plugins::train {

/// Registers this plugin's element types for mechanism models (see gearkit/kin/element.hpp).
void register_elements(kin::PluginRegistrar& registrar);

}  // namespace gearkit::plugins::train
