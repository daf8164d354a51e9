#pragma once
// Commands built into the executable (the others come from plugins).
#include <gearkit/plugin/plugin.hpp>
#include <gearkit/plugin/plugin_host.hpp>

#include <filesystem>
#include <vector>

namespace gearkit::cli {

/// `gearkit plugins`: every plugin with its version, file, commands and element types, and every
/// file that failed to load with the reason (main then prints one `gearkit:` line per failure
/// and exits 2).
int run_plugins_command(plugin::CommandContext& context, const plugin::PluginHost& host,
                        const std::vector<std::filesystem::path>& locations);

/// `gearkit demo [--output DIR]`: a gear table, a compound epicyclic train and a cam profile
/// (DXF and SVG), from embedded models, all written into DIR.
int run_demo_command(plugin::CommandContext& context, const plugin::PluginHost& host);

}  // namespace gearkit::cli
