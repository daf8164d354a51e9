// Registers the built-in joint type `revolute` as an element type: refused.
#include <gearkit/mechanism/element_type.hpp>
#include <gearkit/plugin/plugin.hpp>

GEARKIT_PLUGIN("test-builtin-element", "1.0", "tries to take over 'revolute'")

GEARKIT_PLUGIN_EXPORT void gearkit_plugin_register(gearkit::plugin::PluginRegistrar& registrar) {
  registrar.add_element_type({"revolute", "not the real revolute",
                              [](gearkit::mechanism::ElementReader&) -> std::unique_ptr<gearkit::kin::Constraint> {
                                return nullptr;
                              }});
}
