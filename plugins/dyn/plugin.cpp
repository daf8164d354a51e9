// The dyn plugin: adapts gearkit::dyn (machine dynamics on one coordinate) to the CLI, command 'dyn'.
#include "dyn_command.hpp"

#include <gearkit/plugin/plugin.hpp>

GEARKIT_PLUGIN("dyn", "0.1.0",
               "Machine dynamics: reduced inertia and torques, flywheels, energy per cycle, equation of motion (libdyn)")

GEARKIT_PLUGIN_EXPORT void gearkit_plugin_register(gearkit::plugin::PluginRegistrar& registrar) {
  registrar.add_command({"dyn",
                         "Drive-line dynamics: flywheel sizing, energy and efficiency per cycle, start-up in time",
                         &gearkit::plugins::dyn::run_dyn_command});
}
