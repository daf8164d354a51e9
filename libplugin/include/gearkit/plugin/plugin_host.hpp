#pragma once
// Finding, checking, loading and listing plugins, and the registry of their commands and
// element types. The rules (docs/design.md, "Plugins"):
//  - files: a plugin is opened by its absolute path (a bare name is taken relative to the
//    working directory, never searched on the library path), only if it is a regular file
//    whose stamp (plugin.hpp) shows this API version and command ABI;
//  - registry: names the host builds in (commands such as `kin`, joint types such as
//    `revolute`) can never be registered, so built-ins always win; a command or element type
//    registered by two plugins refuses the later plugin with a message naming both files; a
//    plugin registers all or nothing;
//  - search: a plugin whose name is already loaded from an earlier location is skipped (a build
//    tree and an install do not clash); every other failure is collected, not printed.
#include <gearkit/mechanism/element_type.hpp>
#include <gearkit/plugin/plugin.hpp>

#include <filesystem>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace gearkit::plugin {

/// A plugin file that could not be loaded. what() is "plugin 'FILE': REASON".
class PluginError : public std::runtime_error {
 public:
  /// @param file  the plugin file; @param reason  one line, what was expected and what found
  PluginError(const std::filesystem::path& file, const std::string& reason);
  ~PluginError() override;
  const std::filesystem::path& file() const { return file_; }
  const std::string& reason() const { return reason_; }

 private:
  std::filesystem::path file_;
  std::string reason_;
};

struct LoadedPlugin {
  std::string name;
  std::string version;
  std::string summary;
  std::filesystem::path file;  ///< absolute
  std::vector<std::string> commands;
  std::vector<std::string> element_types;
};

/// The names the host itself provides: no plugin may register them.
struct BuiltinNames {
  std::vector<std::string> commands;       ///< e.g. demo, help, kin, plugins
  std::vector<std::string> element_types;  ///< e.g. mechanism::builtin_joint_types()
};

/// Where plugins are looked for, in order: each entry of GEARKIT_PLUGIN_PATH (':'-separated,
/// folders or files; empty entries ignored), then `<exe dir>/../lib/gearkit/plugins` (the build
/// tree and the install share this layout).
/// @param executable  the running executable's path (current_executable()); empty: only the
///   environment's entries. @throws std::bad_alloc only (relative entries are returned as they
///   are; load_all refuses them).
std::vector<std::filesystem::path> default_plugin_locations(const std::filesystem::path& executable);

/// The path of the running executable (/proc/self/exe), or empty if unknown. @throws
/// std::bad_alloc only.
std::filesystem::path current_executable();

/// Loads plugins and keeps them loaded for the life of the host (their code backs the
/// registered commands and element types). Not copyable. Serves HostServices to commands.
class PluginHost final : public HostServices {
 public:
  /// @param builtins  names no plugin may register. @throws std::bad_alloc only.
  explicit PluginHost(BuiltinNames builtins = {});
  ~PluginHost();
  PluginHost(const PluginHost&) = delete;
  PluginHost& operator=(const PluginHost&) = delete;

  /// Loads one plugin file (a path; a bare name is relative to the working directory).
  /// @throws PluginError if the file is missing, writable by its group or by everyone (so is its
  ///         folder, or the folder of a symbolic link to it), not a regular file, is not a gearkit plugin
  ///         for this machine (no stamp), was built for another API version or ABI, lacks a
  ///         gearkit symbol, registers nothing valid (an empty or built-in name, a null
  ///         function, an element type of another element ABI), fails in registration, has
  ///         the name of a loaded plugin, or registers a name another plugin registered (the
  ///         message names both files).
  void load(const std::filesystem::path& file);

  /// Loads every `*.so` in `locations` (a folder is scanned in name order, a file loaded).
  /// Copies of an already loaded plugin further down the path are skipped; other failures
  /// are added to failures(), one per file, and do not stop the scan. Folders that do not
  /// exist are skipped silently (the install folder is absent from a build tree); a relative
  /// location is not searched and is added to failures(). Never throws a PluginError (each is
  /// collected); @throws std::bad_alloc only.
  void load_all(const std::vector<std::filesystem::path>& locations);

  /// The files load_all could not load, with the reason, in the order met.
  const std::vector<PluginError>& failures() const { return failures_; }
  const std::vector<LoadedPlugin>& plugins() const { return plugins_; }
  /// nullptr if no plugin registers `name`. Never throws (nor does find_element_type).
  const CommandSpec* find_command(std::string_view name) const;
  const mechanism::ElementTypeSpec* find_element_type(std::string_view name) const override;
  const std::map<std::string, CommandSpec, std::less<>>& commands() const { return commands_; }
  const std::map<std::string, mechanism::ElementTypeSpec, std::less<>>& element_types() const {
    return element_types_;
  }

 private:
  struct Registration;
  void check_registration(const std::filesystem::path& file, const Registration& reg) const;
  void commit(const std::filesystem::path& file, const PluginInfo& info, Registration& reg, void* handle);

  BuiltinNames builtins_;
  std::vector<LoadedPlugin> plugins_;
  std::vector<PluginError> failures_;
  std::map<std::string, CommandSpec, std::less<>> commands_;
  std::map<std::string, mechanism::ElementTypeSpec, std::less<>> element_types_;
  std::map<std::string, std::filesystem::path, std::less<>> owner_;  // registered name -> plugin file
  std::vector<void*> handles_;
};

}  // namespace gearkit::plugin
