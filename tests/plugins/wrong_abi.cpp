// A plugin stamped with the right API version but another command ABI fingerprint (a layout
// change that forgot to bump the version): refused from the file, never run.
#include "marker.hpp"

#include <gearkit/plugin/plugin.hpp>

GEARKIT_TEST_MARKER("wrong_abi")

GEARKIT_PLUGIN_STAMP(gearkit::plugin::kApiVersion, gearkit::plugin::kCommandAbi ^ 1u)
GEARKIT_PLUGIN_EXPORT const gearkit::plugin::PluginInfo* gearkit_plugin_info() {
  static const gearkit::plugin::PluginInfo info{"test-wrong-abi", "1.0", "another layout"};
  return &info;
}
GEARKIT_PLUGIN_EXPORT void gearkit_plugin_register(gearkit::plugin::PluginRegistrar&) { __builtin_trap(); }
