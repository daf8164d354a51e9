// A plugin without gearkit_plugin_register.
#include <gearkit/plugin/plugin.hpp>

GEARKIT_PLUGIN("test-missing-symbol", "1.0", "lacks its register function")
