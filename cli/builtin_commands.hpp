#pragma once
// Commands built into the executable (the others come from plugins).
#include <gearkit/kin/plugin.hpp>
#include <gearkit/kin/plugin_host.hpp>

#include <filesystem>
#include <vector>

namespace gearkit::cli {

/// `gearkit plugins`: every plugin with its version, file, commands and element types, and the
/// plugins that failed to load (then the exit status is 2).
int run_plugins_command(kin::CommandContext& context, const kin::PluginHost& host,
                        const std::vector<kin::PluginError>& load_errors,
                        const std::vector<std::filesystem::path>& locations);

/// `gearkit demo [--output DIR]`: a gear table, a compound epicyclic train and a cam profile
/// (DXF and SVG), from embedded models, all written into DIR.
int run_demo_command(kin::CommandContext& context, const kin::PluginHost& host);

}  // namespace gearkit::cli
