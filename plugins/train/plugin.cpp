// The train plugin: adapts gearkit::train to the CLI (command 'train') and to the solver's element types.
#include "train_command.hpp"
#include "train_elements.hpp"

#include <gearkit/plugin/plugin.hpp>

GEARKIT_PLUGIN("train", "0.1.0", "Gear trains: Willis equations, exact ratios, torques, synthesis (libtrain)")

GEARKIT_PLUGIN_EXPORT void gearkit_plugin_register(gearkit::plugin::PluginRegistrar& registrar) {
  registrar.add_command({"train", "Solve an ordinary or epicyclic gear train from a YAML model; 'train synth' for tooth counts", &gearkit::plugins::train::run_train_command});
  gearkit::plugins::train::register_elements(registrar);
}
