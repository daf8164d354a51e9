#include "kin_command.hpp"

#include <ostream>

namespace gearkit::cli {

int run_kin_command(kin::CommandContext& context, const kin::PluginHost&) {
  context.err << "gearkit kin: the mechanism solver is being built (see the libkin issue); nothing computed\n";
  return 1;
}

}  // namespace gearkit::cli
