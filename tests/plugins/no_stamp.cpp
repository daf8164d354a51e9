// A shared library with gearkit's function names but no stamp (what a plugin for API 2 or any
// other *.so looks like): refused from the file, its static constructor never run.
#include "marker.hpp"

#include <gearkit/plugin/plugin.hpp>

GEARKIT_TEST_MARKER("no_stamp")

GEARKIT_PLUGIN_EXPORT int gearkit_plugin_api_version() { return 2; }
GEARKIT_PLUGIN_EXPORT const gearkit::plugin::PluginInfo* gearkit_plugin_info() {
  static const gearkit::plugin::PluginInfo info{"test-no-stamp", "1.0", "no stamp"};
  return &info;
}
GEARKIT_PLUGIN_EXPORT void gearkit_plugin_register(gearkit::plugin::PluginRegistrar&) { __builtin_trap(); }
