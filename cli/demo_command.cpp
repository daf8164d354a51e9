#include "builtin_commands.hpp"
#include "demo_models.hpp"

#include <gearkit/io/atomic_file.hpp>
#include <gearkit/io/command_line.hpp>
#include <gearkit/io/error.hpp>

#include <fmt/format.h>

#include <filesystem>
#include <ostream>
#include <sstream>

namespace gearkit::cli {

namespace fs = std::filesystem;

int run_demo_command(plugin::CommandContext& context, const plugin::PluginHost& host) {
  io::po::options_description desc("gearkit demo options");
  desc.add_options()("help,h", "show this help and exit")(
      "output,o", io::po::value<std::string>()->default_value("gearkit-demo")->value_name("DIR"),
      "folder the demo writes into (created if missing)");
  io::po::positional_options_description none;
  io::po::variables_map vm;
  if (!io::parse_command_line(context.args, desc, none, vm, "gearkit demo [--output DIR]", context.out)) return 0;
  const fs::path dir = vm["output"].as<std::string>();

  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    io::fail_option("--output", fmt::format("cannot create folder '{}': {}", dir.string(),
                                            ec ? ec.message() : "a file of that name exists"));

  for (const auto& model : demo_models()) {
    io::write_file_atomic((dir / model.file).string(), model.text, "--output");
  }
  context.out << fmt::format("gearkit demo: writing into {}\n\n", fs::absolute(dir).lexically_normal().string());
  for (const auto& step : demo_steps()) {
    const plugin::CommandSpec* spec = host.find_command(step.command);
    if (!spec) {
      throw io::InputError(fmt::format("demo: the '{}' plugin is not loaded; see 'gearkit plugins'", step.command));
    }
    std::vector<std::string> args;
    for (const auto& a : step.args) {
      std::string s = a;
      // "{dir}" in an embedded command line stands for the demo folder.
      for (std::size_t pos; (pos = s.find("{dir}")) != std::string::npos;) s.replace(pos, 5, dir.string());
      args.push_back(s);
    }
    std::ostringstream captured;
    plugin::CommandContext sub{args, captured, context.err, context.host};
    int status = spec->run(sub);
    context.out << "== " << step.title << " ==\n" << captured.str() << "\n";
    if (!step.report_file.empty())
      io::write_file_atomic((dir / step.report_file).string(), captured.str(), "--output");
    if (status != 0) {
      context.err << fmt::format("gearkit: demo: step '{}' failed with status {}\n", step.title, status);
      return 1;
    }
  }
  context.out << "Files written:\n";
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir)) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  for (const auto& f : files) context.out << "  " << f.string() << "\n";
  return 0;
}

}  // namespace gearkit::cli
