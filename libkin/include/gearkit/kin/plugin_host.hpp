#pragma once
// Finding, loading and listing plugins.
#include <gearkit/kin/plugin.hpp>
#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace gearkit::kin {

/// A plugin that could not be loaded. what() names the file and the reason.
class PluginError : public std::runtime_error {
 public:
  PluginError(const std::filesystem::path& file, const std::string& reason);
  ~PluginError() override;
  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
};

struct LoadedPlugin {
  std::string name;
  std::string version;
  std::string summary;
  std::filesystem::path file;
  std::vector<std::string> commands;
  std::vector<std::string> element_types;
};

/// Where plugins are looked for, in order: each entry of GEARKIT_PLUGIN_PATH (':'-separated,
/// folders or files), the `plugins` folder next to the executable, and the install prefix's
/// lib/gearkit/plugins (`<exe dir>/../lib/gearkit/plugins`).
std::vector<std::filesystem::path> default_plugin_locations(const std::filesystem::path& executable);

/// The path of the running executable (/proc/self/exe).
std::filesystem::path current_executable();

/// Loads plugins and keeps them loaded for the life of the host (their code backs the
/// registered commands). Not copyable.
class PluginHost {
 public:
  PluginHost();
  ~PluginHost();
  PluginHost(const PluginHost&) = delete;
  PluginHost& operator=(const PluginHost&) = delete;

  /// Loads one plugin file.
  /// @throws PluginError if the file is missing, not a loadable module, lacks a gearkit
  ///         symbol, was built for another API version, or registers a command or element
  ///         type that an earlier plugin already registered.
  void load(const std::filesystem::path& file);

  /// Loads every `*.so` found in `locations` (a folder is scanned, a file loaded). A plugin
  /// whose name is already loaded is skipped (the first location wins). Failures do not stop
  /// the scan; they are returned, one per file.
  std::vector<PluginError> load_all(const std::vector<std::filesystem::path>& locations);

  const std::vector<LoadedPlugin>& plugins() const { return plugins_; }
  /// nullptr if no plugin registers `name`.
  const CommandSpec* find_command(const std::string& name) const;
  const ElementTypeSpec* find_element_type(const std::string& name) const;
  const std::map<std::string, CommandSpec>& commands() const { return commands_; }
  const std::map<std::string, ElementTypeSpec>& element_types() const { return element_types_; }

 private:
  std::vector<LoadedPlugin> plugins_;
  std::map<std::string, CommandSpec> commands_;
  std::map<std::string, ElementTypeSpec> element_types_;
  std::vector<void*> handles_;
};

}  // namespace gearkit::kin
