#include "builtin_commands.hpp"
#include "demo_models.hpp"

#include <gearkit/io/command_line.hpp>
#include <gearkit/io/error.hpp>
#include <gearkit/io/output.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>

namespace gearkit::cli {

namespace fs = std::filesystem;

namespace {

// The demo is all or nothing (docs/cli.md, "Output files"): its steps run in a private folder,
// and every file they leave there goes into the user's folder through one OutputSet, committed
// only when every step has succeeded and every destination has been checked.
/// The folder for the demo's scratch folder: $TMPDIR when it names an existing folder by an
/// absolute path, else /tmp (docs/cli.md, "Output files"). fs::temp_directory_path() throws on a
/// TMPDIR that is not a folder and accepts a relative one, which would follow the working folder.
fs::path temporary_folder_root(std::ostream& err) {
  const char* env = std::getenv("TMPDIR");
  if (env == nullptr || *env == '\0') return "/tmp";
  const fs::path dir = env;
  std::error_code ec;
  if (dir.is_absolute() && fs::is_directory(dir, ec)) return dir;
  const char* why = !dir.is_absolute() ? "not an absolute path" : fs::exists(dir, ec) ? "not a folder" : "missing";
  err << fmt::format("gearkit: warning: TMPDIR {} is {}; demo uses /tmp\n", io::quote(env), why);
  return "/tmp";
}

class ScratchFolder {
 public:
  explicit ScratchFolder(std::ostream& err) {
    const fs::path root = temporary_folder_root(err);
    std::string pattern = (root / "gearkit-demo-XXXXXX").string();
    if (!::mkdtemp(pattern.data()))
      throw io::InputError(fmt::format("demo: cannot create a temporary folder in {}: {}", io::quote(root.string()),
                                       std::strerror(errno)));
    path_ = pattern;
  }
  ~ScratchFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Runs the demo's steps with "{dir}" standing for `folder`, printing each report; returns the
/// status of the first step that fails (0 if none), after saving each report in `folder`.
int run_steps(plugin::CommandContext& context, const plugin::PluginHost& host, const fs::path& folder) {
  for (const auto& step : demo_steps()) {
    const plugin::CommandSpec* spec = host.find_command(step.command);
    if (!spec) {
      throw io::InputError(fmt::format("demo: the '{}' plugin is not loaded; see 'gearkit plugins'", step.command));
    }
    std::vector<std::string> args;
    for (const auto& a : step.args) {
      std::string s = a;
      for (std::size_t pos; (pos = s.find("{dir}")) != std::string::npos;) s.replace(pos, 5, folder.string());
      args.push_back(s);
    }
    std::ostringstream captured;
    plugin::CommandContext sub{args, captured, context.err, context.host};
    int status = spec->run(sub);
    context.out << "== " << step.title << " ==\n" << captured.str() << "\n";
    if (!step.report_file.empty()) std::ofstream(folder / step.report_file, std::ios::binary) << captured.str();
    if (status != 0) {
      context.err << fmt::format("gearkit: demo: step '{}' failed with status {}\n", step.title, status);
      return 1;
    }
  }
  return 0;
}

/// Creates `dir` and the folders above it that are missing; returns those it created, deepest
/// first, so that a failed run can take them away again.
std::vector<fs::path> create_folder(const fs::path& dir) {
  std::vector<fs::path> created;
  for (fs::path p = fs::absolute(dir).lexically_normal(); !p.empty() && !fs::exists(p); p = p.parent_path()) {
    created.push_back(p);
    if (p == p.parent_path()) break;
  }
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    io::fail_option("--output", fmt::format("cannot create folder '{}': {}", dir.string(),
                                            ec ? ec.message() : "a file of that name exists"));
  return created;
}

/// Takes away the folders create_folder made, if they are still empty.
void remove_folders(const std::vector<fs::path>& created) {
  std::error_code ec;
  for (const auto& folder : created) fs::remove(folder, ec);
}

/// Puts every file of `scratch` into `dir` at once; returns the names written, sorted.
std::vector<std::string> commit_files(const fs::path& scratch, const fs::path& dir, std::ostream& out) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(scratch))
    if (entry.is_regular_file()) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  io::OutputSet outputs(out);
  for (const auto& name : names) outputs.add("--output", (dir / name).string(), slurp(scratch / name));
  outputs.commit();
  return names;
}

}  // namespace

int run_demo_command(plugin::CommandContext& context, const plugin::PluginHost& host) {
  io::po::options_description desc("gearkit demo options");
  desc.add_options()("help,h", "show this help and exit")(
      "output,o", io::po::value<std::string>()->default_value("gearkit-demo")->value_name("DIR"),
      "folder the demo writes into (created if missing)");
  io::po::positional_options_description none;
  io::po::variables_map vm;
  if (!io::parse_command_line(context.args, desc, none, vm, "gearkit demo [--output DIR]", context.out)) return 0;
  const fs::path dir = vm["output"].as<std::string>();
  const std::vector<fs::path> created = create_folder(dir);
  try {
    const ScratchFolder scratch(context.err);
    for (const auto& model : demo_models()) std::ofstream(scratch.path() / model.file, std::ios::binary) << model.text;
    context.out << fmt::format("gearkit demo: writing into {}\n\n", fs::absolute(dir).lexically_normal().string());
    if (const int status = run_steps(context, host, scratch.path()); status != 0) {
      remove_folders(created);
      return status;
    }
    const std::vector<std::string> written = commit_files(scratch.path(), dir, context.out);
    context.out << "Files written:\n";
    for (const auto& name : written) context.out << "  " << (dir / name).string() << "\n";
    return 0;
  } catch (...) {
    remove_folders(created);
    throw;
  }
}

}  // namespace gearkit::cli
