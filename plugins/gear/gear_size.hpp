#pragma once
// `gearkit gear size`: rough sizing of a gear pair for a torque and a life (docs/rating.md):
// the smallest pairs over standard modules, pinion tooth counts for a ratio, V-0 shift splits
// and the face width that meets S_Hmin and S_Fmin, shown as a table of the best candidates.
#include <gearkit/plugin/plugin.hpp>

namespace gearkit::plugins::gear {

int run_gear_size_command(plugin::CommandContext& context);

}  // namespace gearkit::plugins::gear
