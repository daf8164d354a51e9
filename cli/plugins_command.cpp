#include "builtin_commands.hpp"

#include <gearkit/io/command_line.hpp>
#include <gearkit/io/report.hpp>

#include <fmt/format.h>

namespace gearkit::cli {

int run_plugins_command(kin::CommandContext& context, const kin::PluginHost& host,
                        const std::vector<kin::PluginError>& load_errors,
                        const std::vector<std::filesystem::path>& locations) {
  io::po::options_description desc("gearkit plugins options");
  io::add_common_options(desc);
  io::po::positional_options_description none;
  io::po::variables_map vm;
  if (!io::parse_command_line(context.args, desc, none, vm, "gearkit plugins [--format text|json|csv|md]",
                              context.out))
    return 0;
  io::CommonOptions common = io::common_options(vm);

  io::Report report;
  report.title = fmt::format("gearkit {} plugins (plugin API {})", GEARKIT_VERSION_STRING, kin::kPluginApiVersion);
  io::Table table{"", {"plugin", "version", "commands", "element types", "file"}, {}};
  nlohmann::json plugins = nlohmann::json::array();
  for (const auto& p : host.plugins()) {
    table.add_row({p.name, p.version, fmt::format("{}", fmt::join(p.commands, " ")),
                   fmt::format("{}", fmt::join(p.element_types, " ")), p.file.string()});
    plugins.push_back({{"name", p.name},
                       {"version", p.version},
                       {"summary", p.summary},
                       {"file", p.file.string()},
                       {"commands", p.commands},
                       {"element_types", p.element_types}});
  }
  report.tables.push_back(std::move(table));
  nlohmann::json errors = nlohmann::json::array();
  for (const auto& e : load_errors) {
    report.warnings.push_back(e.what());
    errors.push_back({{"file", e.file().string()}, {"error", e.what()}});
  }
  std::vector<std::string> where;
  for (const auto& l : locations) where.push_back(l.string());
  report.notes.push_back(fmt::format("Searched: {}", fmt::join(where, ":")));
  report.json = {{"api_version", kin::kPluginApiVersion},
                 {"plugins", plugins},
                 {"errors", errors},
                 {"search_path", where}};
  int status = io::emit(report, common, context.out);
  return load_errors.empty() ? status : 2;
}

}  // namespace gearkit::cli
