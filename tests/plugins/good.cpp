// A minimal well-formed plugin for the plugin-host tests: one command, one element type.
#include <gearkit/kin/plugin.hpp>

#include <ostream>

GEARKIT_PLUGIN("test-good", "9.8.7", "Test plugin that loads")

GEARKIT_PLUGIN_EXPORT void gearkit_plugin_register(gearkit::kin::PluginRegistrar& registrar) {
  registrar.add_command({"hello-test", "Prints a greeting and its arguments", [](gearkit::kin::CommandContext& c) {
                           c.out << "hello from test plugin";
                           for (const auto& a : c.args) c.out << " " << a;
                           c.out << "\n";
                           return 0;
                         }});
  registrar.add_element_type({"test_element", "An element type that builds nothing", nullptr});
}
