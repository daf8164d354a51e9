#pragma once
// The plugin API: what a plugin module exports and what it may register.
//
// A plugin is a shared MODULE (built with gearkit_add_plugin in-tree, or
// gearkit_add_external_plugin out of tree after find_package(gearkit)) that exports three C
// symbols, all declared by GEARKIT_PLUGIN below:
//   int  gearkit_plugin_api_version();       // must equal kPluginApiVersion of the host
//   const gearkit::kin::PluginInfo* gearkit_plugin_info();
//   void gearkit_plugin_register(gearkit::kin::PluginRegistrar&);
// The host checks the API version before calling anything else, so a plugin built against
// another version is rejected with a message naming its file instead of crashing.
// C++ types cross the boundary, so plugins must be built with the same compiler and standard
// library as the host; the API version is bumped whenever these types change.
#include <gearkit/kin/element.hpp>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace gearkit::kin {

/// Bumped whenever anything in plugin.hpp, element.hpp or constraint.hpp changes layout or
/// meaning. 2: BodyState carries the cosine and sine of theta.
inline constexpr int kPluginApiVersion = 2;

struct PluginInfo {
  const char* name;     ///< short name, e.g. "gear"
  const char* version;  ///< the plugin's own version, e.g. "0.1.0"
  const char* summary;  ///< one line
};

/// What a command receives: the words after its name, and where to print.
struct CommandContext {
  std::vector<std::string> args;
  std::ostream& out;
  std::ostream& err;
};

/// A command returns its exit status: 0 success, 3 warnings under --strict. Bad input is
/// reported by throwing gearkit::io::InputError (the host prints it and exits with 2).
using CommandFunction = std::function<int(CommandContext&)>;

struct CommandSpec {
  std::string name;     ///< the word after `gearkit`, e.g. "gear"
  std::string summary;  ///< one line for `gearkit --help`
  CommandFunction run;
};

/// Handed to gearkit_plugin_register: the plugin adds its commands and element types.
class PluginRegistrar {
 public:
  virtual ~PluginRegistrar() = default;
  virtual void add_command(CommandSpec command) = 0;
  virtual void add_element_type(ElementTypeSpec element) = 0;
};

}  // namespace gearkit::kin

#define GEARKIT_PLUGIN_EXPORT extern "C" __attribute__((visibility("default")))

/// Declares a plugin's version and info symbols. The plugin then defines
/// `GEARKIT_PLUGIN_EXPORT void gearkit_plugin_register(gearkit::kin::PluginRegistrar& r) {...}`.
#define GEARKIT_PLUGIN(NAME, VERSION, SUMMARY)                                  \
  GEARKIT_PLUGIN_EXPORT int gearkit_plugin_api_version() {                      \
    return ::gearkit::kin::kPluginApiVersion;                                   \
  }                                                                             \
  GEARKIT_PLUGIN_EXPORT const ::gearkit::kin::PluginInfo* gearkit_plugin_info() { \
    static const ::gearkit::kin::PluginInfo info{NAME, VERSION, SUMMARY};       \
    return &info;                                                               \
  }
