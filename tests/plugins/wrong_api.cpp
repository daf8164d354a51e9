// A plugin that claims another API version: the host must refuse it before calling anything else.
#include <gearkit/kin/plugin.hpp>

GEARKIT_PLUGIN_EXPORT int gearkit_plugin_api_version() { return gearkit::kin::kPluginApiVersion + 41; }
GEARKIT_PLUGIN_EXPORT const gearkit::kin::PluginInfo* gearkit_plugin_info() {
  static const gearkit::kin::PluginInfo info{"test-wrong-api", "1.0", "built for another API"};
  return &info;
}
GEARKIT_PLUGIN_EXPORT void gearkit_plugin_register(gearkit::kin::PluginRegistrar&) {
  // Must never be called: the host checks the version first.
  __builtin_trap();
}
