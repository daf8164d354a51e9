// gearkit: command-line entry point. Global options, plugin loading, dispatch to a built-in or
// plugin command, and the error policy of docs/cli.md: bad input -> one line on stderr and
// status 2; an internal failure (a bug, out of memory) -> one line and status 1; warnings are
// lines "gearkit: warning: ..."; never a backtrace or an abort.
#include "builtin_commands.hpp"
#include "kin_command.hpp"

#include <gearkit/io/command_line.hpp>
#include <gearkit/io/error.hpp>
#include <gearkit/io/output.hpp>
#include <gearkit/mechanism/reader.hpp>
#include <gearkit/plugin/plugin_host.hpp>

#include <boost/program_options.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <iostream>
#include <map>
#include <new>
#include <string>
#include <string_view>
#include <vector>
#include <fcntl.h>
#include <unistd.h>

namespace {

namespace po = boost::program_options;
namespace plugin = gearkit::plugin;
namespace cli = gearkit::cli;

constexpr const char* kUsage =
    "usage: gearkit [--plugin FILE]... <command> [options]\n"
    "       gearkit --help | --version | help <command>";

struct Builtin {
  const char* name;
  const char* summary;
};
constexpr Builtin kBuiltins[] = {
    {"demo", "Run the demonstration: a gear table, an epicyclic train and a cam (DXF+SVG)"},
    {"help", "Show help for a command: gearkit help <command>"},
    {"kin", "Planar mechanism analysis: positions, velocities, accelerations, dead points, forces"},
    {"plugins", "List the loaded plugins with their versions, commands and element types"},
};

/// The stderr rule (docs/cli.md, "Messages and exit status"): every problem is one line that
/// starts "gearkit: "; line breaks and control characters inside a message are shown escaped and
/// a message is cut at 500 characters, so a bad value can never flood the terminal.
void print_diagnostic(std::ostream& err, std::string_view message) {
  while (message.starts_with("gearkit: ")) message.remove_prefix(9);  // never "gearkit: gearkit: "
  std::string line = gearkit::io::quote(message, 500);
  err << "gearkit: " << std::string_view(line).substr(1, line.size() - 2) << "\n";
  err.flush();
}

/// Standard output redirected to a full disk or a closed pipe is the environment's problem,
/// reported like bad input (status 2), never as an internal error.
void flush_standard_output() {
  errno = 0;
  std::cout.flush();
  if (!std::cout)
    throw gearkit::io::InputError(errno != 0 ? fmt::format("cannot write to standard output: {}", std::strerror(errno))
                                             : "cannot write to standard output");
}

// Out of memory must end as "gearkit: internal error: out of memory" and status 1, never as an
// abort or a crash. Unwinding from a failed allocation is not safe with the JSON library we use:
// nlohmann::json 3.11.2 destroys a half-built array through a null pointer (a segmentation
// fault seen at one memory limit of tests/cli/test_out_of_memory.cpp). So the first failed
// allocation ends the process where it happens, as a kill would: destinations are untouched and
// a temporary file left beside one is removed by the next run that writes there (docs/cli.md).
[[noreturn]] void on_allocation_failure() {
  static constexpr char line[] = "gearkit: internal error: out of memory\n";
  [[maybe_unused]] const auto written = ::write(STDERR_FILENO, line, sizeof line - 1);
  std::_Exit(1);
}

// Anything that still reaches std::terminate (an exception escaping a noexcept function) is
// reported as one line and status 1, never as an abort with a core dump.
[[noreturn]] void on_terminate() {
  const char* what = "unknown exception";
  try {
    if (auto e = std::current_exception()) std::rethrow_exception(e);
  } catch (const std::bad_alloc&) {
    what = "out of memory";
  } catch (const std::exception& e) {
    what = e.what();
  } catch (...) {
  }
  const char* prefix = "gearkit: internal error: ";
  [[maybe_unused]] auto written = ::write(STDERR_FILENO, prefix, std::strlen(prefix));
  written = ::write(STDERR_FILENO, what, std::strlen(what));
  written = ::write(STDERR_FILENO, "\n", 1);
  std::_Exit(1);
}

/// Opens /dev/null on each of standard input, output and error that the caller closed
/// (`gearkit ... >&-`). Otherwise the first file the run opens would get descriptor 1 and the
/// report would be written into it (a closed stdout appended the text report to `--svg t.svg`).
void open_closed_standard_streams() {
  for (int fd = 0; fd <= 2; ++fd) {
    if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
    const int opened = ::open("/dev/null", O_RDWR);  // the lowest free descriptor: `fd` itself
    if (opened < 0) std::_Exit(1);                     // no /dev/null: nothing safe to write with
    if (opened != fd) {
      ::dup2(opened, fd);
      ::close(opened);
    }
  }
}

void install_out_of_memory_handling() {
  std::set_new_handler(on_allocation_failure);
  std::set_terminate(on_terminate);
}

// What no plugin may register: the commands above and the joint types of mechanism files.
plugin::BuiltinNames builtin_names() {
  plugin::BuiltinNames names;
  for (const auto& b : kBuiltins) names.commands.emplace_back(b.name);
  names.element_types = gearkit::mechanism::builtin_joint_types();
  return names;
}

void print_help(std::ostream& out, const po::options_description& global, const plugin::PluginHost& host) {
  out << kUsage << "\n\n" << "gearkit " << GEARKIT_VERSION_STRING
      << ": gear and transmission design around a planar kinematics solver.\n\n"
      << global << "\nCommands:\n";
  std::map<std::string, std::string> all;
  for (const auto& b : kBuiltins) all[b.name] = b.summary;
  for (const auto& [name, spec] : host.commands()) all.emplace(name, spec.summary);
  for (const auto& [name, summary] : all) out << fmt::format("  {:<10} {}\n", name, summary);
  out << "\nEvery command but demo takes --help, --format text|json|csv|md|html, --output FILE and --strict.\n"
         "Exit status: 0 success, 2 bad input or usage, 3 warnings under --strict, 1 internal failure.\n";
}

/// The words of the command line split at the command word: global options before it, the
/// command's own words after it (so `gearkit gear --help` is the gear command's help).
struct CommandLine {
  std::vector<std::string> global_args, command_args;
  std::string command;
};

CommandLine split_command_line(int argc, char** argv) {
  CommandLine line;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (line.command.empty() && (a == "--plugin") && i + 1 < argc) {
      line.global_args.push_back(a);
      line.global_args.push_back(argv[++i]);
    } else if (line.command.empty() && !a.empty() && a[0] == '-') {
      line.global_args.push_back(a);
    } else if (line.command.empty()) {
      line.command = a;
    } else {
      line.command_args.push_back(a);
    }
  }
  return line;
}

po::variables_map parse_global_options(const std::vector<std::string>& args, const po::options_description& global) {
  po::variables_map vm;
  try {
    po::store(po::command_line_parser(args).options(global).style(gearkit::io::command_line_style()).run(), vm);
    po::notify(vm);
  } catch (const po::error& e) {
    // A suggestion ends in '?': "did you mean '--version'? See ..." reads better than "?; see".
    const std::string reason = gearkit::io::option_error_message(e, global, args);
    throw gearkit::io::InputError(fmt::format("{}{} 'gearkit --help'", reason, reason.ends_with('?') ? " See" : "; see"));
  }
  return vm;
}

/// Loads the plugins of --plugin (an error if one fails) and of the default locations (a
/// warning line each, except for `plugins`, whose job is to say so).
std::vector<std::filesystem::path> load_plugins(plugin::PluginHost& host, const po::variables_map& vm,
                                                const std::string& command) {
  if (vm.count("plugin")) {
    for (const auto& f : vm["plugin"].as<std::vector<std::string>>()) {
      try {
        host.load(f);
      } catch (const plugin::PluginError& e) {
        throw gearkit::io::InputError(fmt::format("option '--plugin': {}", e.what()));
      }
    }
  }
  auto locations = plugin::default_plugin_locations(plugin::current_executable());
  host.load_all(locations);
  // A plugin that fails to load costs every command but `plugins` one warning line, and only
  // that (docs/design.md, "Plugins"); `plugins`, whose job is to say so, exits 2 (after dispatch).
  if (command != "plugins")
    for (const auto& e : host.failures())
      print_diagnostic(std::cerr, fmt::format("warning: {} (not loaded)", e.what()));
  return locations;
}

/// Runs a built-in or plugin command.
int dispatch(const std::string& command, plugin::CommandContext& context, const plugin::PluginHost& host,
             const std::vector<std::filesystem::path>& locations) {
  if (command == "plugins") {
    const int status = cli::run_plugins_command(context, host, locations);
    const auto& failures = host.failures();
    if (failures.empty()) return status;
    // One error line per file that failed; the last one is the reason for the status.
    for (std::size_t i = 0; i + 1 < failures.size(); ++i) print_diagnostic(std::cerr, failures[i].what());
    throw gearkit::io::InputError(failures.back().what());
  }
  if (command == "demo") return cli::run_demo_command(context, host);
  if (command == "kin") return cli::run_kin_command(context);
  if (const plugin::CommandSpec* spec = host.find_command(command)) return spec->run(context);

  std::vector<std::string> names;
  for (const auto& b : kBuiltins) names.emplace_back(b.name);
  for (const auto& [name, spec] : host.commands()) names.push_back(name);
  std::sort(names.begin(), names.end());
  throw gearkit::io::InputError(
      fmt::format("unknown command {}; expected one of: {}", gearkit::io::quote(command), fmt::join(names, ", ")));
}

int run(int argc, char** argv) {
  CommandLine line = split_command_line(argc, argv);
  po::options_description global("Global options");
  global.add_options()("help,h", "show this help and exit")("version", "show the version and exit")(
      "plugin", po::value<std::vector<std::string>>()->value_name("FILE"),
      "also load this plugin file (an error if it cannot be loaded)");
  const po::variables_map vm = parse_global_options(line.global_args, global);
  if (vm.count("version")) {
    std::cout << "gearkit " << GEARKIT_VERSION_STRING << " (plugin API " << plugin::kApiVersion << ")\n";
    return 0;
  }

  plugin::PluginHost host(builtin_names());
  const std::vector<std::filesystem::path> locations = load_plugins(host, vm, line.command);
  if (vm.count("help") || line.command.empty()) {
    if (line.command.empty() && !vm.count("help"))
      throw gearkit::io::InputError("expected a command; see 'gearkit --help'");
    print_help(std::cout, global, host);
    return 0;
  }
  if (line.command == "help") {
    if (line.command_args.empty()) {
      print_help(std::cout, global, host);
      return 0;
    }
    line.command = line.command_args.front();
    line.command_args = {"--help"};
  }
  plugin::CommandContext context{line.command_args, std::cout, std::cerr, host};
  return dispatch(line.command, context, host, locations);
}

}  // namespace

int main(int argc, char** argv) {
  open_closed_standard_streams();
  gearkit::io::remove_temporaries_on_signals();
  install_out_of_memory_handling();
  try {
    int status = run(argc, argv);
    flush_standard_output();
    return status;
  } catch (const gearkit::io::InputError& e) {
    // The report may be half-streamed to standard output: it goes out before the reason.
    std::cout.flush();
    print_diagnostic(std::cerr, e.what());
    return 2;
  } catch (const gearkit::plugin::PluginError& e) {
    print_diagnostic(std::cerr, e.what());
    return 2;
  } catch (const std::bad_alloc&) {
    print_diagnostic(std::cerr, "internal error: out of memory");
    return 1;
  } catch (const std::exception& e) {
    print_diagnostic(std::cerr, fmt::format("internal error: {}", e.what()));
    return 1;
  } catch (...) {
    print_diagnostic(std::cerr, "internal error: unknown exception");
    return 1;
  }
}
