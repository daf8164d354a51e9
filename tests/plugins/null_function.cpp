// Registers an element type without a read function: refused.
#include <gearkit/mechanism/element_type.hpp>
#include <gearkit/plugin/plugin.hpp>

GEARKIT_PLUGIN("test-null-function", "1.0", "an element type that cannot be read")

GEARKIT_PLUGIN_EXPORT void gearkit_plugin_register(gearkit::plugin::PluginRegistrar& registrar) {
  registrar.add_element_type({"null_element", "no read function", nullptr});
}
