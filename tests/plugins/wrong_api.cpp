// A plugin stamped with another API version: the host must refuse it from the file, before
// loading it (its static constructor must never run).
#include "marker.hpp"

#include <gearkit/plugin/plugin.hpp>

GEARKIT_TEST_MARKER("wrong_api")

GEARKIT_PLUGIN_STAMP(gearkit::plugin::kApiVersion + 41, gearkit::plugin::kCommandAbi)
GEARKIT_PLUGIN_EXPORT const gearkit::plugin::PluginInfo* gearkit_plugin_info() {
  static const gearkit::plugin::PluginInfo info{"test-wrong-api", "1.0", "built for another API"};
  return &info;
}
GEARKIT_PLUGIN_EXPORT void gearkit_plugin_register(gearkit::plugin::PluginRegistrar&) {
  __builtin_trap();  // must never be called
}
