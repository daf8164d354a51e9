// One of two plugins registering the same command and element type: the later one is refused
// with a message naming both files.
#include <gearkit/mechanism/element_type.hpp>
#include <gearkit/plugin/plugin.hpp>

GEARKIT_PLUGIN("test-clash-b", "1.0", "registers 'clash-test'")

GEARKIT_PLUGIN_EXPORT void gearkit_plugin_register(gearkit::plugin::PluginRegistrar& registrar) {
  registrar.add_command({"clash-test", "the b version", [](gearkit::plugin::CommandContext& c) {
                           c.out << "clash b\n";
                           return 0;
                         }});
}
