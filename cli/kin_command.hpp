#pragma once
#include <gearkit/plugin/plugin.hpp>

namespace gearkit::cli {

/// `gearkit kin FILE.yaml ...`: planar mechanism analysis. Built into the executable because the
/// solver is central; element types of mechanism files come from the loaded plugins
/// (context.host).
int run_kin_command(plugin::CommandContext& context);

}  // namespace gearkit::cli
