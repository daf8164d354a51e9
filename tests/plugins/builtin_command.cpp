// Registers the built-in command `kin`: refused (built-ins always win).
#include <gearkit/plugin/plugin.hpp>

GEARKIT_PLUGIN("test-builtin-command", "1.0", "tries to take over 'kin'")

GEARKIT_PLUGIN_EXPORT void gearkit_plugin_register(gearkit::plugin::PluginRegistrar& registrar) {
  registrar.add_command({"kin", "not the real kin", [](gearkit::plugin::CommandContext&) { return 42; }});
}
