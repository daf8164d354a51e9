#pragma once
// Reading a plugin's stamp (the `.gearkit_plugin` section GEARKIT_PLUGIN writes) from the file,
// without loading it, so that no code of a wrong file runs in the gearkit process.
#include <gearkit/plugin/plugin.hpp>

#include <filesystem>
#include <string>
#include <variant>

namespace gearkit::plugin {

/// The stamp of the ELF shared object `file`, or the reason there is none: not a regular file,
/// unreadable, not an ELF shared object for this machine, no `.gearkit_plugin` section, or a
/// section of the wrong size or magic.
std::variant<PluginStamp, std::string> read_plugin_stamp(const std::filesystem::path& file);

/// Why `stamp` does not fit this gearkit (API version or command ABI), or empty if it fits.
std::string stamp_mismatch(const PluginStamp& stamp);

}  // namespace gearkit::plugin
