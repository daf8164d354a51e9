#pragma once
// The temporaries an OutputSet has open, readable from a signal handler: a signal that ends the
// process (SIGINT, SIGTERM, SIGHUP, SIGPIPE) removes them before the process dies
// (remove_temporaries_on_signals() in gearkit/io/output.hpp installs the handlers).

namespace gearkit::io::detail {

/// Records `path` (a temporary about to be created) for the signal handler. Returns the slot
/// to give to forget_temporary(), or -1 when every slot is taken or the path is too long (the
/// temporary is then only removed by the next run writing into its folder).
int remember_temporary(const char* path) noexcept;

/// Forgets a slot of remember_temporary() (the temporary was renamed or removed); -1 is ignored.
void forget_temporary(int slot) noexcept;

}  // namespace gearkit::io::detail
