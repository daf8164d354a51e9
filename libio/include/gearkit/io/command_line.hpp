#pragma once
// Shared command-line handling for the built-in and plugin commands (Boost.Program_options):
// the common options, --help, and option errors turned into InputError.
#include <gearkit/io/output.hpp>
#include <gearkit/io/quantity.hpp>
#include <gearkit/io/report.hpp>
#include <boost/program_options.hpp>
#include <iosfwd>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gearkit::io {

namespace po = boost::program_options;

/// Options every command has.
struct CommonOptions {
  Format format = Format::text;
  std::string output = "-";  ///< --output FILE: where the report goes ("-": standard output)
  bool strict = false; ///< --strict: warnings make the exit status 3
  std::string table = {};  ///< --table NAME: the one table to write (report_output.hpp)
};

/// The values an option accepts when they are narrower than the generic sizes of quantity.hpp
/// (magnitude_range), in the unit of the option's bare numbers. The shared parsing checks it
/// before the generic sizes, so that a refusal states the option's own range ("expected a basic
/// efficiency in (0, 1]"), never the generic one.
struct OptionRange {
  double low = -std::numeric_limits<double>::infinity();
  double high = std::numeric_limits<double>::infinity();
  bool low_open = false, high_open = false;
  /// How a message says it ("a basic efficiency in (0, 1]"); empty: "a value in [low, high]".
  std::string_view expected = {};

  bool contains(double value) const;
  std::string describe() const;
};

/// A number option (as po::value<double>) with its range: parse_command_line refuses a value
/// outside it with "option '--x': expected <range>, found <value>".
po::typed_value<double>* number_in(const OptionRange& range);

/// The SI value of a quantity option given as text ("2 mm", "200 mm/min"), nullopt when it is not
/// given. `name` without dashes; `default_unit` applies to a bare number and is the unit of
/// `range`, except that a bare number of a quantity that option_needs_unit (power, torque, speed)
/// is refused (quantity.hpp, parse_option_quantity_si). @throws InputError naming the option for
/// a malformed value, a bare number refused, the wrong dimension, a value outside `range`
/// (checked first) or outside magnitude_range.
std::optional<double> quantity_option(const po::variables_map& vm, const char* name, Quantity q,
                                      std::string_view default_unit, const std::optional<OptionRange>& range = {});

/// Adds --help, --format, --output and --strict to `desc`.
void add_common_options(po::options_description& desc);

/// Adds a positional argument at the next position: `name` is its key in the variables map
/// ("file") and, upper-cased, its name in messages. A required one missing from the command line
/// is refused by parse_command_line with "expected the FILE argument, found none; usage: ...".
/// @param value_name what --help shows for it ("FILE", "PAIR.yaml").
void add_positional_argument(po::options_description& desc, po::positional_options_description& positional,
                             const char* name, const char* value_name, const char* description, bool required = true);

/// The edit distance between `a` and `b` (optimal string alignment: an insertion, a deletion, a
/// substitution or a swap of two neighbouring characters each count 1; "modlue" to "module" is 1).
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The long option of `desc` that an unknown `typed` ("--modlue", "modlue") was most likely meant
/// to be, with its dashes ("--module"): the nearest by edit_distance when that is at most a third
/// of typed's length (at least 1; the first of equals in `desc`'s order), else the only option
/// whose name begins with `typed` ("--helix" -> "--helix-angle"); nothing when neither exists.
/// Never used to accept an option: parse_command_line refuses any name it does not know exactly.
std::optional<std::string> nearest_option(std::string_view typed, const po::options_description& desc);

/// The style every command line is parsed with: Boost's default without allow_guessing, so that an
/// abbreviation ("--modul" for "--module") is an unknown option, never a silent guess.
int command_line_style();

/// Parses `args` (the words after the command name). Returns false if --help was given, after
/// printing "usage" and `desc` to `out`; the caller then returns 0.
/// @throws InputError for unknown options (naming nearest_option when there is one), missing
///         values, bad --format, extra words.
bool parse_command_line(const std::vector<std::string>& args, const po::options_description& desc,
                        const po::positional_options_description& positional, po::variables_map& vm,
                        std::string_view usage, std::ostream& out);

/// Boost.Program_options' error `e` from parsing `args` against `desc`, in the documented form
/// "option '--x': expected ..., found ..." (docs/cli.md, "Messages and exit status"): a value of
/// the wrong type, an option given twice, an unknown, ambiguous or misused option. Other errors
/// keep Boost's wording, shortened to one line. parse_command_line uses it for every command.
std::string option_error_message(const po::error& e, const po::options_description& desc,
                                 const std::vector<std::string>& args);

/// The common options from a parsed command line.
CommonOptions common_options(const po::variables_map& vm);

/// Writes the report to stdout or --output and returns the exit status (0, or 3 under --strict
/// when there are warnings).
int emit(const Report& report, const CommonOptions& options, std::ostream& out);

/// Adds the report to `outputs` (the command's other files: --svg, --dxf...), commits them all
/// together and returns the exit status as above.
/// @throws InputError when a destination is refused or a write fails; nothing is then changed.
int emit(const Report& report, const CommonOptions& options, OutputSet& outputs);

/// The exit status for a report: 3 under --strict when it has warnings, else 0.
int exit_status(const Report& report, const CommonOptions& options);

}  // namespace gearkit::io
