#include <gearkit/io/command_line.hpp>

#include <gearkit/io/atomic_file.hpp>
#include <gearkit/io/error.hpp>

#include <fmt/format.h>

#include <ostream>

namespace gearkit::io {

void add_common_options(po::options_description& desc) {
  desc.add_options()
      ("help,h", "show this help and exit")
      ("format", po::value<std::string>()->default_value("text")->value_name("text|json|csv|md"),
       "output format")
      ("output,o", po::value<std::string>()->value_name("FILE"),
       "write the report to FILE (atomically) instead of standard output")
      ("strict", "exit with status 3 when the report has warnings");
}

bool parse_command_line(const std::vector<std::string>& args, const po::options_description& desc,
                        const po::positional_options_description& positional, po::variables_map& vm,
                        std::string_view usage, std::ostream& out) {
  try {
    po::store(po::command_line_parser(args).options(desc).positional(positional).run(), vm);
    if (vm.count("help")) {
      out << "usage: " << usage << "\n\n" << desc << "\n";
      return false;
    }
    po::notify(vm);
  } catch (const po::too_many_positional_options_error&) {
    // Name the first word nobody asked for.
    throw InputError(fmt::format("unexpected argument; usage: {}", usage));
  } catch (const po::error_with_option_name& e) {
    throw InputError(e.what());
  } catch (const po::error& e) {
    throw InputError(e.what());
  }
  if (vm.count("format")) parse_format(vm["format"].as<std::string>());
  return true;
}

CommonOptions common_options(const po::variables_map& vm) {
  CommonOptions o;
  if (vm.count("format")) o.format = parse_format(vm["format"].as<std::string>());
  if (vm.count("output")) o.output = vm["output"].as<std::string>();
  o.strict = vm.count("strict") > 0;
  return o;
}

int emit(const Report& report, const CommonOptions& options, std::ostream& out) {
  if (options.output.empty()) {
    render(report, options.format, out);
  } else {
    write_file_atomic(options.output, render(report, options.format), "--output");
  }
  return options.strict && !report.warnings.empty() ? 3 : 0;
}

}  // namespace gearkit::io
