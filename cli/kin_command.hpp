#pragma once
#include <gearkit/kin/plugin.hpp>
#include <gearkit/kin/plugin_host.hpp>

namespace gearkit::cli {

/// `gearkit kin FILE.yaml ...`: planar mechanism analysis. Built into the executable because the
/// solver is central; element types of mechanism files come from the loaded plugins (`host`).
int run_kin_command(kin::CommandContext& context, const kin::PluginHost& host);

}  // namespace gearkit::cli
