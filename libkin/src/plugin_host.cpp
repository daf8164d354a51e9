#include <gearkit/kin/plugin_host.hpp>

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <system_error>

namespace gearkit::kin {

namespace fs = std::filesystem;

PluginError::PluginError(const fs::path& file, const std::string& reason)
    : std::runtime_error("plugin '" + file.string() + "': " + reason), file_(file) {}
PluginError::~PluginError() = default;

namespace {

using ApiVersionFn = int (*)();
using InfoFn = const PluginInfo* (*)();
using RegisterFn = void (*)(PluginRegistrar&);

// Collects what one plugin registers, so nothing reaches the host unless the whole
// registration succeeded and clashes with nothing already loaded.
class CollectingRegistrar final : public PluginRegistrar {
 public:
  void add_command(CommandSpec command) override { commands.push_back(std::move(command)); }
  void add_element_type(ElementTypeSpec element) override { elements.push_back(std::move(element)); }
  std::vector<CommandSpec> commands;
  std::vector<ElementTypeSpec> elements;
};

void* symbol(void* handle, const char* name) {
  dlerror();
  return dlsym(handle, name);
}

}  // namespace

std::filesystem::path current_executable() {
  std::error_code ec;
  fs::path p = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : p;
}

std::vector<fs::path> default_plugin_locations(const fs::path& executable) {
  std::vector<fs::path> out;
  if (const char* env = std::getenv("GEARKIT_PLUGIN_PATH")) {
    std::stringstream ss(env);
    std::string item;
    while (std::getline(ss, item, ':'))
      if (!item.empty()) out.emplace_back(item);
  }
  if (!executable.empty()) {
    fs::path dir = executable.parent_path();
    out.push_back(dir / "plugins");
    out.push_back((dir / ".." / "lib" / "gearkit" / "plugins").lexically_normal());
  }
  return out;
}

PluginHost::PluginHost() = default;

PluginHost::~PluginHost() {
  // Registered std::function objects live in the host but their code lives in the modules:
  // drop them before unloading.
  commands_.clear();
  element_types_.clear();
  for (void* h : handles_) dlclose(h);
}

void PluginHost::load(const fs::path& file) {
  std::error_code ec;
  if (!fs::exists(file, ec)) throw PluginError(file, "no such file");
  if (fs::is_directory(file, ec)) throw PluginError(file, "is a directory, not a plugin file");

  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = dlerror();
    throw PluginError(file, std::string("not a loadable plugin module: ") + (why ? why : "unknown reason"));
  }
  // What the plugin registered holds code from the module (std::function targets, their
  // destructors): it must be destroyed before the module is unloaded.
  CollectingRegistrar reg;
  auto reject = [&](const std::string& reason) {
    reg.commands.clear();
    reg.elements.clear();
    dlclose(handle);
    throw PluginError(file, reason);
  };
  auto version_fn = reinterpret_cast<ApiVersionFn>(symbol(handle, "gearkit_plugin_api_version"));
  if (!version_fn) reject("missing symbol 'gearkit_plugin_api_version' (not a gearkit plugin?)");
  int version = version_fn();
  if (version != kPluginApiVersion)
    reject("built for plugin API version " + std::to_string(version) + ", this gearkit needs version " +
           std::to_string(kPluginApiVersion) + "; rebuild the plugin against this gearkit");
  auto info_fn = reinterpret_cast<InfoFn>(symbol(handle, "gearkit_plugin_info"));
  if (!info_fn) reject("missing symbol 'gearkit_plugin_info'");
  auto register_fn = reinterpret_cast<RegisterFn>(symbol(handle, "gearkit_plugin_register"));
  if (!register_fn) reject("missing symbol 'gearkit_plugin_register'");
  const PluginInfo* info = info_fn();
  if (!info || !info->name || !*info->name) reject("gearkit_plugin_info() gave no plugin name");

  try {
    register_fn(reg);
  } catch (const std::exception& e) {
    reject(std::string("registration failed: ") + e.what());
  } catch (...) {
    reject("registration failed with an unknown exception");
  }
  for (const auto& c : reg.commands) {
    if (c.name.empty() || !c.run) reject("registers a command without a name or a function");
    if (commands_.count(c.name)) reject("command '" + c.name + "' is already registered by another plugin");
  }
  for (const auto& e : reg.elements) {
    if (e.name.empty()) reject("registers an element type without a name");
    if (element_types_.count(e.name))
      reject("element type '" + e.name + "' is already registered by another plugin");
  }

  LoadedPlugin loaded{info->name, info->version ? info->version : "", info->summary ? info->summary : "",
                      file, {}, {}};
  for (auto& c : reg.commands) {
    loaded.commands.push_back(c.name);
    std::string name = c.name;
    commands_.emplace(std::move(name), std::move(c));
  }
  for (auto& e : reg.elements) {
    loaded.element_types.push_back(e.name);
    std::string name = e.name;
    element_types_.emplace(std::move(name), std::move(e));
  }
  plugins_.push_back(std::move(loaded));
  handles_.push_back(handle);
}

std::vector<PluginError> PluginHost::load_all(const std::vector<fs::path>& locations) {
  std::vector<PluginError> errors;
  std::vector<fs::path> seen;
  auto try_load = [&](const fs::path& f) {
    std::error_code ec;
    fs::path canon = fs::weakly_canonical(f, ec);
    if (std::find(seen.begin(), seen.end(), canon) != seen.end()) return;
    seen.push_back(canon);
    // A plugin with the name of one already loaded is a copy elsewhere on the path (a build
    // tree and an install): the first location wins.
    std::string stem = f.stem().string();
    for (const auto& p : plugins_)
      if ("gearkit-" + p.name == stem) return;
    try {
      load(f);
    } catch (const PluginError& e) {
      errors.push_back(e);
    }
  };
  for (const auto& loc : locations) {
    std::error_code ec;
    if (fs::is_directory(loc, ec)) {
      std::vector<fs::path> files;
      for (const auto& entry : fs::directory_iterator(loc, ec))
        if (entry.path().extension() == ".so") files.push_back(entry.path());
      std::sort(files.begin(), files.end());  // deterministic order
      for (const auto& f : files) try_load(f);
    } else if (fs::exists(loc, ec)) {
      try_load(loc);
    }
    // A folder on the path that does not exist is not an error: the defaults include the
    // install prefix, which a build tree lacks.
  }
  return errors;
}

const CommandSpec* PluginHost::find_command(const std::string& name) const {
  auto it = commands_.find(name);
  return it == commands_.end() ? nullptr : &it->second;
}

const ElementTypeSpec* PluginHost::find_element_type(const std::string& name) const {
  auto it = element_types_.find(name);
  return it == element_types_.end() ? nullptr : &it->second;
}

}  // namespace gearkit::kin
