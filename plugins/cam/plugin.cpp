// The cam plugin: adapts gearkit::cam to the CLI (command 'cam') and to the solver's element types.
#include "cam_command.hpp"
#include "cam_elements.hpp"

#include <gearkit/plugin/plugin.hpp>

GEARKIT_PLUGIN("cam", "0.1.0", "Cams: motion laws, followers, profiles by CGAL offsets, DXF/SVG export (libcam)")

GEARKIT_PLUGIN_EXPORT void gearkit_plugin_register(gearkit::plugin::PluginRegistrar& registrar) {
  registrar.add_command({"cam", "Cam profile from a motion program: checks, DXF/SVG/CSV export", &gearkit::plugins::cam::run_cam_command});
  gearkit::plugins::cam::register_elements(registrar);
}
