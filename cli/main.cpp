// gearkit: command-line entry point. Global options, plugin loading, dispatch to a built-in or
// plugin command, and the error policy: bad input -> one line on stderr and status 2; an
// internal failure -> one line and status 1; never a backtrace.
#include "builtin_commands.hpp"
#include "kin_command.hpp"

#include <gearkit/io/error.hpp>
#include <gearkit/kin/plugin_host.hpp>

#include <boost/program_options.hpp>
#include <fmt/format.h>

#include <iostream>
#include <map>
#include <new>
#include <string>
#include <vector>

namespace {

namespace po = boost::program_options;
namespace kin = gearkit::kin;
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

void print_help(std::ostream& out, const po::options_description& global, const kin::PluginHost& host) {
  out << kUsage << "\n\n" << "gearkit " << GEARKIT_VERSION_STRING
      << ": gear and transmission design around a planar kinematics solver.\n\n"
      << global << "\nCommands:\n";
  std::map<std::string, std::string> all;
  for (const auto& b : kBuiltins) all[b.name] = b.summary;
  for (const auto& [name, spec] : host.commands()) all.emplace(name, spec.summary);
  for (const auto& [name, summary] : all) out << fmt::format("  {:<10} {}\n", name, summary);
  out << "\nEvery command takes --help, --format text|json|csv|md and --output FILE.\n"
         "Exit status: 0 success, 2 bad input or usage, 3 warnings under --strict, 1 internal failure.\n";
}

int run(int argc, char** argv) {
  // Global options stop at the command word: everything after it belongs to the command, so
  // `gearkit gear --help` is the gear command's help, not the tool's.
  std::vector<std::string> global_args, command_args;
  std::string command;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (command.empty() && (a == "--plugin") && i + 1 < argc) {
      global_args.push_back(a);
      global_args.push_back(argv[++i]);
    } else if (command.empty() && !a.empty() && a[0] == '-') {
      global_args.push_back(a);
    } else if (command.empty()) {
      command = a;
    } else {
      command_args.push_back(a);
    }
  }

  po::options_description global("Global options");
  global.add_options()("help,h", "show this help and exit")("version", "show the version and exit")(
      "plugin", po::value<std::vector<std::string>>()->value_name("FILE"),
      "also load this plugin file (an error if it cannot be loaded)");
  po::variables_map vm;
  try {
    po::store(po::command_line_parser(global_args).options(global).run(), vm);
    po::notify(vm);
  } catch (const po::error& e) {
    throw gearkit::io::InputError(fmt::format("{}; see 'gearkit --help'", e.what()));
  }
  if (vm.count("version")) {
    std::cout << "gearkit " << GEARKIT_VERSION_STRING << " (plugin API " << kin::kPluginApiVersion << ")\n";
    return 0;
  }

  kin::PluginHost host;
  if (vm.count("plugin")) {
    for (const auto& f : vm["plugin"].as<std::vector<std::string>>()) {
      try {
        host.load(f);
      } catch (const kin::PluginError& e) {
        throw gearkit::io::InputError(fmt::format("option '--plugin': {}", e.what()));
      }
    }
  }
  auto locations = kin::default_plugin_locations(kin::current_executable());
  std::vector<kin::PluginError> load_errors = host.load_all(locations);
  if (command != "plugins")
    for (const auto& e : load_errors) std::cerr << "gearkit: warning: " << e.what() << "\n";

  if (vm.count("help") || command.empty()) {
    if (command.empty() && !vm.count("help")) {
      std::cerr << "gearkit: expected a command; see 'gearkit --help'\n";
      return 2;
    }
    print_help(std::cout, global, host);
    return 0;
  }

  if (command == "help") {
    if (command_args.empty()) {
      print_help(std::cout, global, host);
      return 0;
    }
    command = command_args.front();
    command_args = {"--help"};
  }

  kin::CommandContext context{command_args, std::cout, std::cerr};
  if (command == "plugins") return cli::run_plugins_command(context, host, load_errors, locations);
  if (command == "demo") return cli::run_demo_command(context, host);
  if (command == "kin") return cli::run_kin_command(context, host);
  if (const kin::CommandSpec* spec = host.find_command(command)) return spec->run(context);

  std::vector<std::string> names;
  for (const auto& b : kBuiltins) names.emplace_back(b.name);
  for (const auto& [name, spec] : host.commands()) names.push_back(name);
  std::sort(names.begin(), names.end());
  throw gearkit::io::InputError(
      fmt::format("unknown command '{}'; expected one of: {}", command, fmt::join(names, ", ")));
}

}  // namespace

int main(int argc, char** argv) {
  try {
    int status = run(argc, argv);
    std::cout.flush();
    if (!std::cout) {
      std::cerr << "gearkit: cannot write to standard output\n";
      return 1;
    }
    return status;
  } catch (const gearkit::io::InputError& e) {
    std::cout.flush();
    std::cerr << "gearkit: " << e.what() << "\n";
    return 2;
  } catch (const gearkit::kin::PluginError& e) {
    std::cerr << "gearkit: " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << "gearkit: internal error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "gearkit: internal error: " << e.what() << "\n";
    return 1;
  } catch (...) {
    std::cerr << "gearkit: internal error: unknown exception\n";
    return 1;
  }
}
