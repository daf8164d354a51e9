// The synth plugin: adapts gearkit::synth (linkage synthesis) to the CLI, command 'synth'.
#include "synth_command.hpp"

#include <gearkit/plugin/plugin.hpp>

GEARKIT_PLUGIN("synth", "0.1.0",
               "Linkage synthesis: function, motion and path generation, quick-return and dwell linkages (libsynth)")

GEARKIT_PLUGIN_EXPORT void gearkit_plugin_register(gearkit::plugin::PluginRegistrar& registrar) {
  registrar.add_command({"synth",
                         "Linkage synthesis from a task file: function, motion, path, crank-rocker, dwell",
                         &gearkit::plugins::synth::run_synth_command});
}
