// Opens the `kin --equations` module on first use (see kin_equations.hpp).
#include "kin_equations.hpp"

#include <gearkit/plugin/plugin_host.hpp>

#include <dlfcn.h>
#include <fmt/format.h>

#include <filesystem>
#include <stdexcept>

namespace gearkit::cli {

namespace {

AddEquationsSection open_equations_module() {
  namespace fs = std::filesystem;
  const fs::path exe = plugin::current_executable();
  if (exe.empty()) throw std::runtime_error("--equations: cannot find the executable's own folder (/proc/self/exe)");
  const fs::path module = (exe.parent_path() / GEARKIT_EQUATIONS_MODULE_FROM_BIN).lexically_normal();
  // RTLD_LOCAL keeps GiNaC's symbols inside the module. The handle is never closed: an exception
  // thrown by the module may still be alive when the caller reports it.
  void* handle = dlopen(module.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) throw std::runtime_error(fmt::format("--equations: cannot open the module '{}': {}", module.string(), dlerror()));
  void* entry = dlsym(handle, kAddEquationsSectionSymbol);
  if (!entry) throw std::runtime_error(fmt::format("--equations: '{}' has no {}", module.string(), kAddEquationsSectionSymbol));
  return reinterpret_cast<AddEquationsSection>(entry);
}

}  // namespace

void add_equations_section_from_module(io::Report& report, const mechanism::Mechanism& mech, const KinAnalysis& analysis,
                                       io::Format format) {
  static const AddEquationsSection add = open_equations_module();
  add(report, mech, analysis, format);
}

}  // namespace gearkit::cli
