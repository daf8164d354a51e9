// A plugin stamped with the right API version but another command ABI fingerprint (a layout
// change that forgot to bump the version): refused from the file, never run.
#include "marker.hpp"

#include <gearkit/plugin/plugin.hpp>

GEARKIT_TEST_MARKER("wrong_abi")

extern "C" {
extern const gearkit::plugin::PluginStamp gearkit_plugin_stamp;
__attribute__((visibility("default"), used, section(".gearkit_plugin"))) const gearkit::plugin::PluginStamp
    gearkit_plugin_stamp = {{'g', 'e', 'a', 'r', 'k', 'i', 't', '\0'},
                            gearkit::plugin::kApiVersion,
                            sizeof(gearkit::plugin::PluginStamp),
                            gearkit::plugin::kCommandAbi ^ 1u};
}
GEARKIT_PLUGIN_EXPORT const gearkit::plugin::PluginInfo* gearkit_plugin_info() {
  static const gearkit::plugin::PluginInfo info{"test-wrong-abi", "1.0", "another layout"};
  return &info;
}
GEARKIT_PLUGIN_EXPORT void gearkit_plugin_register(gearkit::plugin::PluginRegistrar&) { __builtin_trap(); }
