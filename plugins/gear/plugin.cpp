// The gear plugin: adapts gearkit::gear to the CLI (command 'gear') and to the solver's element types.
#include "gear_command.hpp"
#include "gear_elements.hpp"

#include <gearkit/plugin/plugin.hpp>

GEARKIT_PLUGIN("gear", "0.1.0", "Involute cylindrical gears: geometry with profile shift and gear tables (libgear)")

GEARKIT_PLUGIN_EXPORT void gearkit_plugin_register(gearkit::plugin::PluginRegistrar& registrar) {
  registrar.add_command({"gear", "Gear table of a cylindrical involute pair: geometry, checks, measurements", &gearkit::plugins::gear::run_gear_command});
  gearkit::plugins::gear::register_elements(registrar);
}
