#include "builtin_commands.hpp"

#include <gearkit/io/command_line.hpp>
#include <gearkit/io/report.hpp>

#include <fmt/format.h>

namespace gearkit::cli {

namespace {

io::Table loaded_table(const plugin::PluginHost& host, nlohmann::json& json) {
  io::Table table{"", {"plugin", "version", "commands", "element types", "file"}, {}};
  json = nlohmann::json::array();
  for (const auto& p : host.plugins()) {
    table.add_row({p.name, p.version, fmt::format("{}", fmt::join(p.commands, " ")),
                   fmt::format("{}", fmt::join(p.element_types, " ")), p.file.string()});
    json.push_back({{"name", p.name},
                    {"version", p.version},
                    {"summary", p.summary},
                    {"file", p.file.string()},
                    {"commands", p.commands},
                    {"element_types", p.element_types}});
  }
  return table;
}

io::Table failed_table(const plugin::PluginHost& host, nlohmann::json& json) {
  io::Table table{"Failed to load", {"file", "reason"}, {}};
  json = nlohmann::json::array();
  for (const auto& e : host.failures()) {
    table.add_row({e.file().string(), e.reason()});
    json.push_back({{"file", e.file().string()}, {"reason", e.reason()}, {"error", e.what()}});
  }
  return table;
}

}  // namespace

int run_plugins_command(plugin::CommandContext& context, const plugin::PluginHost& host,
                        const std::vector<std::filesystem::path>& locations) {
  io::po::options_description desc("gearkit plugins options");
  io::add_common_options(desc);
  io::po::positional_options_description none;
  io::po::variables_map vm;
  if (!io::parse_command_line(context.args, desc, none, vm, "gearkit plugins [--format text|json|csv|md|html]",
                              context.out))
    return 0;
  const io::CommonOptions common = io::common_options(vm);

  io::Report report;
  report.title = fmt::format("gearkit {} plugins (plugin API {})", GEARKIT_VERSION_STRING, plugin::kApiVersion);
  nlohmann::json plugins, errors;
  report.tables.push_back(loaded_table(host, plugins));
  if (!host.failures().empty()) report.tables.push_back(failed_table(host, errors));
  std::vector<std::string> where;
  for (const auto& l : locations) where.push_back(l.string());
  report.notes.push_back(fmt::format("Searched: {}", fmt::join(where, ":")));
  report.json = {{"api_version", plugin::kApiVersion},
                 {"plugins", plugins},
                 {"errors", host.failures().empty() ? nlohmann::json::array() : errors},
                 {"search_path", where}};
  // Failures are this command's errors: main prints one line each and exits 2.
  return io::emit(report, common, context.out);
}

}  // namespace gearkit::cli
