// Registers the element type of the good test plugin: refused, naming both files.
#include <gearkit/mechanism/element_type.hpp>
#include <gearkit/plugin/plugin.hpp>

GEARKIT_PLUGIN("test-clash-element", "1.0", "registers 'test_element' again")

GEARKIT_PLUGIN_EXPORT void gearkit_plugin_register(gearkit::plugin::PluginRegistrar& registrar) {
  registrar.add_element_type({"test_element", "a second test_element",
                              [](gearkit::mechanism::ElementReader&) -> std::unique_ptr<gearkit::kin::Constraint> {
                                return nullptr;
                              }});
}
