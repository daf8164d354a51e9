// Registers an element type as a plugin built against another element ABI would (simulated by
// passing another fingerprint): refused without reading the element.
#include <gearkit/mechanism/element_type.hpp>
#include <gearkit/plugin/plugin.hpp>

GEARKIT_PLUGIN("test-element-abi", "1.0", "element types of another layout")

namespace {
// Reaches the protected entry point, as an old inline add_element_type would have called it.
struct OldRegistrar : gearkit::plugin::PluginRegistrar {
  using gearkit::plugin::PluginRegistrar::add_element_type_built_with;
};
}  // namespace

GEARKIT_PLUGIN_EXPORT void gearkit_plugin_register(gearkit::plugin::PluginRegistrar& registrar) {
  gearkit::mechanism::ElementTypeSpec spec{"old_element", "built against another layout", nullptr};
  const auto entry = &OldRegistrar::add_element_type_built_with;  // a member of PluginRegistrar
  (registrar.*entry)(gearkit::mechanism::kElementAbi ^ 1u, spec);
}
