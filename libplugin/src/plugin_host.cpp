#include <gearkit/plugin/plugin_host.hpp>

#include "plugin_stamp.hpp"

#include <dlfcn.h>
#include <sys/stat.h>

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <system_error>

namespace gearkit::plugin {

namespace fs = std::filesystem;

PluginError::PluginError(const fs::path& file, const std::string& reason)
    : std::runtime_error("plugin '" + file.string() + "': " + reason), file_(file), reason_(reason) {}
PluginError::~PluginError() = default;

// What one plugin registers, held apart until the whole registration is checked: nothing
// reaches the host unless all of it is valid and clashes with nothing already loaded.
struct PluginHost::Registration final : PluginRegistrar {
  void add_command(CommandSpec command) override { commands.push_back(std::move(command)); }
  void add_element_type_built_with(std::uint64_t element_abi, mechanism::ElementTypeSpec& element) override {
    if (element_abi != mechanism::kElementAbi) {
      wrong_element_abi = element_abi;  // the element's layout may differ: read nothing of it
      return;
    }
    elements.push_back(std::move(element));
  }
  std::vector<CommandSpec> commands;
  std::vector<mechanism::ElementTypeSpec> elements;
  std::uint64_t wrong_element_abi = 0;
};

namespace {

using InfoFn = const PluginInfo* (*)();
using RegisterFn = void (*)(PluginRegistrar&);

void* symbol(void* handle, const char* name) {
  dlerror();
  return dlsym(handle, name);
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// An absolute path, taken once: a bare name is the file in the working directory (dlopen would
// search the library path for it instead).
fs::path absolute_path(const fs::path& file) {
  std::error_code ec;
  fs::path p = fs::absolute(file, ec);
  return ec ? file : p.lexically_normal();
}

/// Why a plugin whose file or folder others than its owner may write must not be loaded: anyone
/// in that group (or anyone at all) could replace it by code that runs in every gearkit command.
/// Empty when the file, its folder and, for a symbolic link, the link's folder are all safe (the
/// rule ssh applies to its keys; a sticky /tmp is no exception: its files can still be added).
std::string writable_by_others(const fs::path& file) {
  std::error_code ec;
  const fs::path real = fs::canonical(file, ec);
  std::vector<fs::path> checked{ec ? file : real};
  checked.push_back(checked.front().parent_path());
  if (file.parent_path() != checked.back()) checked.push_back(file.parent_path());
  for (const auto& p : checked) {
    struct stat st{};
    if (::stat(p.c_str(), &st) != 0) continue;  // a missing file is refused elsewhere
    if ((st.st_mode & (S_IWGRP | S_IWOTH)) == 0) continue;
    const bool is_file = p == checked.front();
    return fmt::format("{} '{}' is writable by {} (mode {:04o}); refusing to load code others can replace "
                       "(chmod go-w '{}')",
                       is_file ? "the file" : "its folder", p.string(),
                       (st.st_mode & S_IWOTH) ? "everyone" : "its group", st.st_mode & 07777, p.string());
  }
  return {};
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
  if (!executable.empty()) out.push_back((executable.parent_path() / GEARKIT_PLUGIN_DIR_FROM_BIN).lexically_normal());
  return out;
}

PluginHost::PluginHost(BuiltinNames builtins) : builtins_(std::move(builtins)) {}

PluginHost::~PluginHost() {
  // Registered std::function objects live in the host but their code lives in the modules:
  // drop them before unloading.
  commands_.clear();
  element_types_.clear();
  for (void* h : handles_) dlclose(h);
}

void PluginHost::check_registration(const fs::path& file, const Registration& reg) const {
  auto owner = [&](const std::string& key) {
    const auto it = owner_.find(key);
    return it == owner_.end() ? std::string() : it->second.string();
  };
  if (reg.wrong_element_abi)
    throw PluginError(file, fmt::format("registers element types built with another element ABI (fingerprint {:016x}, "
                                        "this gearkit has {:016x}); rebuild the plugin against this gearkit",
                                        reg.wrong_element_abi, mechanism::kElementAbi));
  for (const auto& c : reg.commands) {
    if (c.name.empty() || !c.run) throw PluginError(file, "registers a command without a name or a function");
    if (contains(builtins_.commands, c.name))
      throw PluginError(file, fmt::format("registers the command '{}', which is built into gearkit", c.name));
    if (const std::string other = owner("command " + c.name); !other.empty())
      throw PluginError(file, fmt::format("registers the command '{}', already registered by plugin '{}'", c.name, other));
  }
  for (const auto& e : reg.elements) {
    if (e.name.empty() || !e.read) throw PluginError(file, "registers an element type without a name or a read function");
    if (contains(builtins_.element_types, e.name))
      throw PluginError(file, fmt::format("registers the element type '{}', which is built into gearkit", e.name));
    if (const std::string other = owner("element " + e.name); !other.empty())
      throw PluginError(file, fmt::format("registers the element type '{}', already registered by plugin '{}'", e.name,
                                          other));
  }
  auto repeated = [](auto names) {
    std::sort(names.begin(), names.end());
    return std::adjacent_find(names.begin(), names.end()) != names.end();
  };
  std::vector<std::string> commands, elements;
  for (const auto& c : reg.commands) commands.push_back(c.name);
  for (const auto& e : reg.elements) elements.push_back(e.name);
  if (repeated(commands) || repeated(elements)) throw PluginError(file, "registers the same name twice");
}

void PluginHost::commit(const fs::path& file, const PluginInfo& info, Registration& reg, void* handle) {
  LoadedPlugin loaded{info.name, info.version ? info.version : "", info.summary ? info.summary : "", file, {}, {}};
  for (auto& c : reg.commands) {
    loaded.commands.push_back(c.name);
    owner_.emplace("command " + c.name, file);
    std::string name = c.name;
    commands_.emplace(std::move(name), std::move(c));
  }
  for (auto& e : reg.elements) {
    loaded.element_types.push_back(e.name);
    owner_.emplace("element " + e.name, file);
    std::string name = e.name;
    element_types_.emplace(std::move(name), std::move(e));
  }
  plugins_.push_back(std::move(loaded));
  handles_.push_back(handle);
}

void PluginHost::load(const fs::path& given) {
  const fs::path file = absolute_path(given);
  std::error_code ec;
  if (!fs::exists(file, ec)) throw PluginError(file, "no such file");
  if (const std::string why = writable_by_others(file); !why.empty()) throw PluginError(file, why);
  const auto stamp = read_plugin_stamp(file);
  if (const auto* why = std::get_if<std::string>(&stamp)) throw PluginError(file, *why);
  if (const std::string why = stamp_mismatch(std::get<PluginStamp>(stamp)); !why.empty()) throw PluginError(file, why);

  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = dlerror();
    throw PluginError(file, std::string("not a loadable plugin module: ") + (why ? why : "unknown reason"));
  }
  // What the plugin registered holds code from the module (std::function targets and their
  // destructors): it must be destroyed before the module is unloaded.
  auto reg = std::make_unique<Registration>();
  auto reject = [&](const PluginError& e) {
    reg.reset();
    dlclose(handle);
    throw e;
  };
  const auto info_fn = reinterpret_cast<InfoFn>(symbol(handle, "gearkit_plugin_info"));
  const auto register_fn = reinterpret_cast<RegisterFn>(symbol(handle, "gearkit_plugin_register"));
  if (!info_fn) reject(PluginError(file, "missing symbol 'gearkit_plugin_info'"));
  if (!register_fn) reject(PluginError(file, "missing symbol 'gearkit_plugin_register'"));
  const PluginInfo* info = info_fn();
  if (!info || !info->name || !*info->name) reject(PluginError(file, "gearkit_plugin_info() gave no plugin name"));
  for (const auto& p : plugins_)
    if (p.name == info->name)
      reject(PluginError(file, fmt::format("is plugin '{}', already loaded from '{}'", p.name, p.file.string())));
  try {
    register_fn(*reg);
    check_registration(file, *reg);
  } catch (const PluginError& e) {
    reject(e);
  } catch (const std::exception& e) {
    reject(PluginError(file, std::string("registration failed: ") + e.what()));
  } catch (...) {
    reject(PluginError(file, "registration failed with an unknown exception"));
  }
  commit(file, *info, *reg, handle);
}

void PluginHost::load_all(const std::vector<fs::path>& locations) {
  std::vector<fs::path> seen;
  auto try_load = [&](const fs::path& f) {
    std::error_code ec;
    const fs::path canon = fs::weakly_canonical(absolute_path(f), ec);
    if (std::find(seen.begin(), seen.end(), canon) != seen.end()) return;
    seen.push_back(canon);
    // A plugin with the name of one already loaded is a copy elsewhere on the path (a build
    // tree and an install): the first location wins.
    const std::string stem = f.stem().string();
    for (const auto& p : plugins_)
      if ("gearkit-" + p.name == stem) return;
    try {
      load(f);
    } catch (const PluginError& e) {
      failures_.push_back(e);
    }
  };
  for (const auto& loc : locations) {
    std::error_code ec;
    if (loc.is_relative()) {
      // Resolved against the working folder, it would load whatever the folder a command runs in holds.
      failures_.emplace_back(loc, "a relative entry of the plugin path is ignored (give an absolute path)");
      continue;
    }
    if (fs::is_directory(loc, ec)) {
      std::vector<fs::path> files;
      for (const auto& entry : fs::directory_iterator(loc, ec))
        if (entry.path().extension() == ".so") files.push_back(entry.path());
      std::sort(files.begin(), files.end());  // deterministic order
      for (const auto& f : files) try_load(f);
    } else if (fs::exists(fs::symlink_status(loc, ec))) {
      try_load(loc);
    }
    // A folder on the path that does not exist is not an error: the defaults include the
    // install prefix, which a build tree lacks.
  }
}

const CommandSpec* PluginHost::find_command(std::string_view name) const {
  auto it = commands_.find(name);
  return it == commands_.end() ? nullptr : &it->second;
}

const mechanism::ElementTypeSpec* PluginHost::find_element_type(std::string_view name) const {
  auto it = element_types_.find(name);
  return it == element_types_.end() ? nullptr : &it->second;
}

}  // namespace gearkit::plugin
