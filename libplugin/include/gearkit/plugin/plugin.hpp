#pragma once
// The plugin API: what a plugin module exports and what it may register. This header needs
// nothing but the standard library, so a plugin that only adds commands links neither the
// solver nor Eigen (examples/plugin-hello). A plugin that adds element types for mechanism
// models also includes <gearkit/mechanism/element_type.hpp> and links gearkit::mechanism.
//
// A plugin is a shared MODULE (gearkit_add_plugin in-tree, gearkit_add_external_plugin out of
// tree after find_package(gearkit)) that declares itself with GEARKIT_PLUGIN(name, version,
// summary) and defines
//   GEARKIT_PLUGIN_EXPORT void gearkit_plugin_register(gearkit::plugin::PluginRegistrar&);
//
// What the host guarantees when it loads a file (docs/design.md, "Plugins"):
//  1. It opens regular files only, by absolute path, and reads the plugin's stamp (the
//     `.gearkit_plugin` ELF section written by GEARKIT_PLUGIN: API version and ABI fingerprint)
//     from the file without loading it. A file without a stamp, or with another API version or
//     fingerprint, is refused before any of its code runs.
//  2. Then dlopen runs the module's static constructors (and those of the libraries it links):
//     gearkit cannot check anything between dlopen and them, so a plugin must do no work there.
//  3. Only then does the host call gearkit_plugin_info and gearkit_plugin_register. What the
//     plugin registers is committed only if all of it is valid (names not empty and not built
//     in, functions not null, element types built against this element ABI) and nothing clashes
//     with another plugin; otherwise the whole plugin is refused with a message naming its file
//     (and the other plugin's file for a clash).
// C++ types cross the boundary, so plugins are built with the same compiler and standard
// library as the host. kApiVersion is bumped when the meaning of the interface changes; the
// fingerprints catch a layout change that forgot the bump.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace gearkit::mechanism {
struct ElementTypeSpec;  // <gearkit/mechanism/element_type.hpp>
}

namespace gearkit::plugin {

/// 3: gearkit::plugin namespace, host services, stamp section, ABI fingerprints, element readers
/// and element reactions. 4: kin::Constraint::drawing (a new virtual function: the vtable the
/// host calls changed, which no fingerprint of sizes sees), with the flat face of a cam's drawing.
inline constexpr std::uint32_t kApiVersion = 4;

struct PluginInfo {
  const char* name;     ///< short name, e.g. "gear"
  const char* version;  ///< the plugin's own version, e.g. "0.1.0"
  const char* summary;  ///< one line
};

/// What the host offers a running command.
class HostServices {
 public:
  /// The element type a loaded plugin registered under `name` (e.g. "gear_mesh"), or nullptr;
  /// pass it to gearkit::mechanism::load_mechanism so that a command reads every mechanism file
  /// `gearkit kin` reads. Never throws.
  virtual const mechanism::ElementTypeSpec* find_element_type(std::string_view name) const = 0;

 protected:
  ~HostServices() = default;
};

/// What a command receives: the words after its name, where to print, and the host.
struct CommandContext {
  std::vector<std::string> args;
  std::ostream& out;
  std::ostream& err;
  const HostServices& host;
};

/// A command returns its exit status: 0 success, 3 warnings under --strict. Bad input is
/// reported by throwing gearkit::io::InputError (the host prints it and exits with 2).
using CommandFunction = std::function<int(CommandContext&)>;

struct CommandSpec {
  std::string name;     ///< the word after `gearkit`, e.g. "gear"; not a built-in command
  std::string summary;  ///< one line for `gearkit --help`
  CommandFunction run;  ///< not null
};

/// Handed to gearkit_plugin_register: the plugin adds its commands and element types.
class PluginRegistrar {
 public:
  /// Adds a command. Nothing is checked here: the host checks everything the plugin registered
  /// when gearkit_plugin_register returns (PluginHost::load), and refuses the whole plugin
  /// then. @throws std::bad_alloc only.
  virtual void add_command(CommandSpec command) = 0;
  /// Adds an element type for mechanism files. Defined inline in
  /// <gearkit/mechanism/element_type.hpp>, which a plugin with element types includes: it
  /// passes the element ABI fingerprint of the plugin's build along for the host to check.
  /// Checked like add_command, after registration. @throws std::bad_alloc only.
  void add_element_type(mechanism::ElementTypeSpec element);

 protected:
  ~PluginRegistrar() = default;
  /// Reads `element` only if `element_abi` is the host's kElementAbi (else the plugin is refused
  /// after registration). @throws std::bad_alloc only.
  virtual void add_element_type_built_with(std::uint64_t element_abi, mechanism::ElementTypeSpec& element) = 0;
};

namespace abi {

/// FNV-1a over a list of sizes and offsets: equal lists give equal fingerprints, and a changed
/// size or offset changes it (with overwhelming probability). Never throws (constexpr).
/// @param layout  sizes and offsets [bytes]
constexpr std::uint64_t fingerprint(std::initializer_list<std::size_t> layout) {
  std::uint64_t h = 14695981039346656037ull;
  for (std::size_t v : layout)
    for (int byte = 0; byte < 8; ++byte) {
      h ^= (static_cast<std::uint64_t>(v) >> (8 * byte)) & 0xffu;
      h *= 1099511628211ull;
    }
  return h;
}

}  // namespace abi

// offsetof on classes with std::string members is conditionally supported; GCC and Clang give
// the offsets the compiler uses, which is what the fingerprint is about.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Winvalid-offsetof"
/// The layout of what crosses the boundary for commands, as the including compiler sees it.
inline constexpr std::uint64_t kCommandAbi = abi::fingerprint({
    kApiVersion, sizeof(void*), sizeof(std::string), sizeof(std::string_view), sizeof(std::vector<std::string>),
    sizeof(CommandFunction), alignof(CommandFunction), sizeof(PluginInfo), offsetof(PluginInfo, version),
    offsetof(PluginInfo, summary), sizeof(CommandContext), offsetof(CommandContext, out), offsetof(CommandContext, err),
    offsetof(CommandContext, host), sizeof(CommandSpec), offsetof(CommandSpec, summary), offsetof(CommandSpec, run),
    sizeof(HostServices), sizeof(PluginRegistrar)});
#pragma GCC diagnostic pop

/// The stamp GEARKIT_PLUGIN writes into the `.gearkit_plugin` section of the module. Its layout
/// never changes: the host reads it from the file before loading anything.
struct PluginStamp {
  char magic[8];              ///< "gearkit\0"
  std::uint32_t api_version;  ///< kApiVersion of the plugin's build
  std::uint32_t stamp_size;   ///< sizeof(PluginStamp)
  std::uint64_t command_abi;  ///< kCommandAbi of the plugin's build
};

}  // namespace gearkit::plugin

#define GEARKIT_PLUGIN_EXPORT extern "C" __attribute__((visibility("default")))

/// The stamp itself, with the API version and command ABI given (GEARKIT_PLUGIN uses this
/// build's; the host's tests stamp modules with others to check that they are refused).
#define GEARKIT_PLUGIN_STAMP(API_VERSION, COMMAND_ABI)                                                  \
  extern "C" {                                                                                          \
  __attribute__((visibility("default"))) extern const ::gearkit::plugin::PluginStamp gearkit_plugin_stamp; \
  __attribute__((used, section(".gearkit_plugin"))) const ::gearkit::plugin::PluginStamp             \
      gearkit_plugin_stamp = {{'g', 'e', 'a', 'r', 'k', 'i', 't', '\0'},                                \
                              (API_VERSION),                                                            \
                              sizeof(::gearkit::plugin::PluginStamp),                                    \
                              (COMMAND_ABI)};                                                           \
  }

/// Declares a plugin: its stamp (read from the file before loading it) and its info. The plugin
/// then defines `GEARKIT_PLUGIN_EXPORT void gearkit_plugin_register(gearkit::plugin::PluginRegistrar& r)`.
#define GEARKIT_PLUGIN(NAME, VERSION, SUMMARY)                                                          \
  GEARKIT_PLUGIN_STAMP(::gearkit::plugin::kApiVersion, ::gearkit::plugin::kCommandAbi)                  \
  GEARKIT_PLUGIN_EXPORT const ::gearkit::plugin::PluginInfo* gearkit_plugin_info() {                   \
    static const ::gearkit::plugin::PluginInfo info{NAME, VERSION, SUMMARY};                            \
    return &info;                                                                                       \
  }
