// The smallest useful gearkit plugin: one command with options, using gearkit::io for the
// command line and the report, so it gets --help, --format and --output like every command.
#include <gearkit/io/command_line.hpp>
#include <gearkit/plugin/plugin.hpp>

#include <fmt/format.h>

namespace {

int run_hello(gearkit::plugin::CommandContext& context) {
  namespace io = gearkit::io;
  io::po::options_description desc("gearkit hello options");
  desc.add_options()("name", io::po::value<std::string>()->default_value("world")->value_name("NAME"), "who to greet");
  io::add_common_options(desc);
  io::po::variables_map vm;
  if (!io::parse_command_line(context.args, desc, {}, vm, "gearkit hello [--name NAME]", context.out)) return 0;
  io::Report report;
  report.title = fmt::format("hello, {}", vm["name"].as<std::string>());
  report.json = {{"greeting", report.title}};
  return io::emit(report, io::common_options(vm), context.out);
}

}  // namespace

GEARKIT_PLUGIN("hello", "1.0.0", "Example out-of-tree plugin")

GEARKIT_PLUGIN_EXPORT void gearkit_plugin_register(gearkit::plugin::PluginRegistrar& registrar) {
  registrar.add_command({"hello", "Greets (example of an out-of-tree plugin)", &run_hello});
}
