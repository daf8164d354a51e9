#include <gearkit/io/command_line.hpp>

#include <gearkit/io/error.hpp>
#include <gearkit/io/quantity.hpp>
#include <gearkit/io/report_output.hpp>

#include <fmt/format.h>

#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iostream>
#include <limits>
#include <ostream>

namespace gearkit::io {

void add_common_options(po::options_description& desc) {
  desc.add_options()
      ("help,h", "show this help and exit")
      ("format", po::value<std::string>()->default_value("text")->value_name("text|json|csv|md|html"),
       "output format (html: one self-contained page with the pictures written)")
      ("table", po::value<std::string>()->value_name("NAME"),
       "write only the table NAME (csv: needed when the report has several; 'all': every table)")
      ("output,o", po::value<std::string>()->value_name("FILE"),
       "write the report to FILE instead of standard output ('-'); see docs/cli.md, Output files")
      ("strict", "exit with status 3 when the report has warnings");
}

bool OptionRange::contains(double value) const {
  const bool above = low_open ? value > low : value >= low;
  const bool below = high_open ? value < high : value <= high;
  return above && below;
}

std::string OptionRange::describe() const {
  if (!expected.empty()) return std::string(expected);
  return fmt::format("a value in {}{:g}, {:g}{}", low_open ? '(' : '[', low, high, high_open ? ')' : ']');
}

namespace {

/// po::value<double> that carries its range for reject_empty_values to check.
class RangedNumber : public po::typed_value<double> {
 public:
  explicit RangedNumber(const OptionRange& range) : po::typed_value<double>(nullptr), range_(range) {}
  const OptionRange& range() const { return range_; }

 private:
  OptionRange range_;
};

}  // namespace

namespace {

/// What is wrong with `value` for an option of range `range` whose quantity has the generic sizes
/// [smallest, largest] (both in the option's unit), or nothing. A value the option's range takes
/// but the generic sizes refuse is described by both ("in (0, 1] and at least 1e-15").
std::optional<std::string> range_problem(double value, const OptionRange& range, double smallest, double largest) {
  if (!range.contains(value)) return fmt::format("expected {}", range.describe());
  const double size = std::abs(value);
  if (size < smallest && size > 0)
    return fmt::format("expected {} and {} {:g}", range.describe(),
                       range.contains(0.0) ? "of size 0 or at least" : range.low >= 0 ? "at least" : "of size at least",
                       smallest);
  if (size > largest) return fmt::format("expected {} and of size at most {:g}", range.describe(), largest);
  return std::nullopt;
}

}  // namespace

po::typed_value<double>* number_in(const OptionRange& range) { return new RangedNumber(range); }

std::optional<double> quantity_option(const po::variables_map& vm, const char* name, Quantity q,
                                      std::string_view default_unit, const std::optional<OptionRange>& range) {
  if (!vm.count(name)) return std::nullopt;
  const std::string option = fmt::format("--{}", name);
  const std::string& text = vm[name].as<std::string>();
  try {
    if (!range) return parse_option_quantity_si(text, q, default_unit);
    const double si = parse_option_quantity_si_any_size(text, q, default_unit);
    const double factor = default_unit.empty() ? 1.0 : unit_factor_si(default_unit, q);
    const MagnitudeRange sizes = magnitude_range(q);
    if (const auto problem = range_problem(si / factor, *range, sizes.smallest / factor, sizes.largest / factor))
      fail_option(option, fmt::format("{}, found {}", *problem, quote(text)));
    return si;
  } catch (const QuantityError& e) {
    fail_option(option, e.what());
  }
}

void add_positional_argument(po::options_description& desc, po::positional_options_description& positional,
                             const char* name, const char* value_name, const char* description, bool required) {
  auto* value = po::value<std::string>()->value_name(value_name);
  if (required) value->required();
  desc.add_options()(name, value, description);
  positional.add(name, 1);
}

namespace {

/// The names of the positional arguments ("file"), in order.
std::vector<std::string> positional_names(const po::positional_options_description& positional) {
  std::vector<std::string> names;
  const unsigned count = std::min(positional.max_total_count(), 8u);  // unbounded is UINT_MAX
  for (unsigned i = 0; i < count; ++i) {
    const std::string& name = positional.name_for_position(i);
    if (names.empty() || names.back() != name) names.push_back(name);
  }
  return names;
}

/// A usage of several lines (a command and its subcommands) is quoted in a message by its first.
std::string_view first_line(std::string_view usage) { return usage.substr(0, usage.find('\n')); }

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

/// Boost.Program_options quotes whole values ("the argument ('<1 MB>') for option '--at' is
/// invalid"): shorten every quoted part and show control characters, so the message stays one
/// short line.
std::string shorten_quoted_parts(std::string_view message) {
  std::string out;
  std::size_t i = 0;
  while (i < message.size()) {
    std::size_t open = message.find('\'', i);
    std::size_t close = open == std::string_view::npos ? open : message.find('\'', open + 1);
    if (close == std::string_view::npos) {
      std::string rest = quote(message.substr(i), 300);
      out += rest.substr(1, rest.size() - 2);
      break;
    }
    std::string before = quote(message.substr(i, open - i), 300);
    out += before.substr(1, before.size() - 2) + quote(message.substr(open + 1, close - open - 1));
    i = close + 1;
  }
  return out;
}

/// The value Boost.Program_options quotes in an error about it (its "%value%"), read from the
/// error's protected substitutions through a pointer to member of a derived class (legal: the
/// access is checked where the pointer is formed).
struct ErrorFields : po::error_with_option_name {
  static std::string value_of(const po::error_with_option_name& e) {
    const auto& substitutions = e.*(&ErrorFields::m_substitutions);
    const auto it = substitutions.find("value");
    return it == substitutions.end() ? std::string() : it->second;
  }
};

template <class T>
bool holds(const po::value_semantic* semantic) {
  return dynamic_cast<const po::typed_value<T>*>(semantic) != nullptr;
}

template <class T>
std::string whole_number_range() {
  return fmt::format("a whole number from {} to {}", std::numeric_limits<T>::min(), std::numeric_limits<T>::max());
}

/// What an option of `semantic` takes, for "expected ...": a number, a whole number (with its
/// bounds when `value` is all digits, so too large), or any value.
std::string expected_value(const po::value_semantic* semantic, const std::string& value) {
  if (holds<double>(semantic) || holds<float>(semantic)) return "a number";
  const bool digits = !value.empty() && value.find_first_not_of("+-0123456789") == std::string::npos;
  if (holds<int>(semantic)) return digits ? whole_number_range<int>() : "a whole number";
  if (holds<long>(semantic)) return digits ? whole_number_range<long>() : "a whole number";
  if (holds<long long>(semantic)) return digits ? whole_number_range<long long>() : "a whole number";
  if (holds<unsigned>(semantic)) return digits ? whole_number_range<unsigned>() : "a whole number";
  return "a valid value";
}

/// How many times `option` ("--fix") is among `args` ("--fix x" or "--fix=x").
std::size_t occurrences(const std::vector<std::string>& args, const std::string& option) {
  return static_cast<std::size_t>(std::count_if(args.begin(), args.end(), [&](const std::string& a) {
    return a == option || a.starts_with(option + "=");
  }));
}

std::string dashed(std::string name) { return name.starts_with("-") ? name : "--" + name; }

/// "option '--dxf'" or, for a positional argument, "the FILE argument".
std::string label(const std::string& name, const std::vector<std::string>& positionals) {
  if (std::find(positionals.begin(), positionals.end(), name) != positionals.end())
    return fmt::format("the {} argument", upper(name));
  return fmt::format("option '--{}'", name);
}

/// Options read as double by Boost take "nan", "inf" and 1e300: the same range as a plain number
/// in a model file applies (quantity.hpp, magnitude_range).
void check_plain_number(double value, const std::string& where) {
  const MagnitudeRange range = magnitude_range(Quantity::dimensionless);
  const double size = std::abs(value);
  if (!std::isfinite(value) || size > range.largest || (size > 0.0 && size < range.smallest))
    throw InputError(fmt::format("{}: expected a finite number of size 0 or between {:g} and {:g}, found {:g}", where,
                                 range.smallest, range.largest, value));
}

/// An empty value ("--output ''") would otherwise mean "not given" to most commands.
void reject_empty_values(const po::variables_map& vm, const po::options_description& desc,
                         const std::vector<std::string>& positionals) {
  for (const auto& [name, value] : vm) {
    if (value.defaulted() || value.empty()) continue;
    const po::option_description* option = desc.find_nothrow(name, false);
    if (option && option->semantic()->max_tokens() == 0) continue;  // a flag such as --strict
    bool empty = false;
    if (const auto* s = boost::any_cast<std::string>(&value.value())) empty = s->empty();
    else if (const auto* v = boost::any_cast<std::vector<std::string>>(&value.value()))
      empty = std::any_of(v->begin(), v->end(), [](const std::string& x) { return x.empty(); });
    if (empty) throw InputError(fmt::format("{}: expected a value, found an empty one", label(name, positionals)));
    const auto* d = boost::any_cast<double>(&value.value());
    if (!d) continue;
    // An option's own range first, so that the message states it; then the generic sizes.
    const auto* ranged = option ? dynamic_cast<const RangedNumber*>(option->semantic().get()) : nullptr;
    const MagnitudeRange sizes = magnitude_range(Quantity::dimensionless);
    if (ranged && std::isfinite(*d))
      if (const auto problem = range_problem(*d, ranged->range(), sizes.smallest, sizes.largest))
        throw InputError(fmt::format("{}: {}, found {:g}", label(name, positionals), *problem, *d));
    check_plain_number(*d, label(name, positionals));
  }
}

}  // namespace

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // d[i][j]: distance between the first i characters of a and the first j of b, three rows kept.
  std::vector<std::size_t> before(b.size() + 1), previous(b.size() + 1), current(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        current[j] = std::min(current[j], before[j - 2] + 1);
    }
    before.swap(previous);
    previous.swap(current);
  }
  return previous[b.size()];
}

namespace {

/// The word of a typed option: "--tabel=x" -> "tabel".
std::string_view typed_word(std::string_view typed) {
  const std::string_view name = typed.substr(std::min(typed.size(), typed.find_first_not_of('-')));
  return name.substr(0, name.find('='));
}

/// The options whose name begins with what was typed ("--helix" -> --helix-angle,
/// --helix-modification), for an unknown option that no single name is near.
std::vector<std::string> options_extending(std::string_view typed, const po::options_description& desc) {
  const std::string_view word = typed_word(typed);
  std::vector<std::string> names;
  if (word.size() < 2) return names;
  for (const auto& option : desc.options())
    if (!option->long_name().empty() && option->long_name().starts_with(word)) names.push_back("--" + option->long_name());
  return names;
}

}  // namespace

std::optional<std::string> nearest_option(std::string_view typed, const po::options_description& desc) {
  const std::string_view word = typed_word(typed);
  if (word.size() < 2) return std::nullopt;  // "-x": too short to say what was meant
  const std::size_t threshold = std::max<std::size_t>(1, word.size() / 3);
  std::optional<std::string> nearest;
  std::size_t best = threshold + 1;
  std::vector<std::string> extensions;
  for (const auto& option : desc.options()) {
    const std::string& candidate = option->long_name();
    if (candidate.empty()) continue;
    if (const std::size_t d = edit_distance(word, candidate); d < best) {
      best = d;
      nearest = candidate;
    }
    if (candidate.starts_with(word)) extensions.push_back(candidate);
  }
  if (!nearest && extensions.size() == 1) nearest = extensions.front();
  if (!nearest) return std::nullopt;
  return "--" + *nearest;
}

int command_line_style() {
  return po::command_line_style::default_style & ~po::command_line_style::allow_guessing;
}

std::string option_error_message(const po::error& e, const po::options_description& desc,
                                 const std::vector<std::string>& args) {
  const auto* named = dynamic_cast<const po::error_with_option_name*>(&e);
  if (!named) return shorten_quoted_parts(e.what());
  const std::string option = named->get_option_name();
  const std::string where = fmt::format("option {}", quote(option));
  if (const auto* invalid = dynamic_cast<const po::validation_error*>(&e)) {
    const std::string value = ErrorFields::value_of(*invalid);
    const po::option_description* description = desc.find_nothrow(option.substr(option.find_first_not_of('-')), false);
    if (invalid->kind() == po::validation_error::invalid_option_value && description)
      return fmt::format("{}: expected {}, found {}", where, expected_value(description->semantic().get(), value),
                         quote(value));
    if (invalid->kind() == po::validation_error::invalid_bool_value)
      return fmt::format("{}: expected true or false, found {}", where, quote(value));
    if (invalid->kind() == po::validation_error::multiple_values_not_allowed)
      return fmt::format("{}: expected one value, found several", where);
  }
  if (dynamic_cast<const po::multiple_occurrences*>(&e))
    return fmt::format("{}: expected it once, found it {} times", where, std::max<std::size_t>(2, occurrences(args, option)));
  if (dynamic_cast<const po::required_option*>(&e)) return fmt::format("{}: expected it (it is required), found none", where);
  if (dynamic_cast<const po::multiple_values*>(&e)) return fmt::format("{}: expected one value, found several", where);
  if (dynamic_cast<const po::unknown_option*>(&e)) {
    std::vector<std::string> meant;
    if (const std::optional<std::string> nearest = nearest_option(option, desc)) meant.push_back(*nearest);
    else meant = options_extending(option, desc);  // several begin with it: name them all, up to four
    std::vector<std::string> quoted;
    for (const std::string& m : meant) quoted.push_back(quote(m));
    // Boost names "--tabel=x" with its value: the option is the part before '='.
    return fmt::format("option {}: expected an option listed by --help, found an unknown one{}",
                       quote(option.substr(0, option.find('='))),
                       !meant.empty() && meant.size() <= 4 ? fmt::format("; did you mean {}?", fmt::join(quoted, " or "))
                                                           : std::string());
  }
  if (const auto* ambiguous = dynamic_cast<const po::ambiguous_option*>(&e)) {
    std::vector<std::string> names;
    for (const auto& a : ambiguous->alternatives()) names.push_back(quote(dashed(a)));
    return fmt::format("{}: expected a whole option name, found the beginning of {}", where, fmt::join(names, " and "));
  }
  if (const auto* syntax = dynamic_cast<const po::invalid_syntax*>(&e)) {
    if (syntax->kind() == po::invalid_syntax::missing_parameter)
      return fmt::format("{}: expected a value, found none", where);
    if (syntax->kind() == po::invalid_syntax::extra_parameter)
      return fmt::format("{}: expected no value (it is a switch), found one", where);
  }
  return shorten_quoted_parts(e.what());
}

namespace {

/// "unexpected argument 'x'; usage: ..." naming the first word beyond the positional arguments
/// the command takes, with the usage cut at a word to keep the line short (the whole usage is
/// in --help).
std::string unexpected_argument_message(const std::vector<std::string>& args, const po::options_description& desc,
                                        const po::positional_options_description& positional, std::string_view usage) {
  std::string word;
  try {
    const auto parsed = po::command_line_parser(args).options(desc).allow_unregistered().run();
    const auto words = po::collect_unrecognized(parsed.options, po::include_positional);
    std::vector<std::string> positional_words;
    for (const auto& w : words)
      if (w.empty() || w == "-" || w[0] != '-') positional_words.push_back(w);
    if (positional.max_total_count() < positional_words.size()) word = positional_words[positional.max_total_count()];
  } catch (const po::error&) {
  }
  std::string_view line = first_line(usage);
  std::string shown(line);
  if (line.size() > 120) {
    const std::size_t cut = line.rfind(' ', 116);
    shown = std::string(line.substr(0, cut == std::string_view::npos ? 116 : cut)) + " ...";
  }
  if (word.empty()) return fmt::format("unexpected argument; usage: {}", shown);
  return fmt::format("unexpected argument {}; usage: {}", quote(word), shown);
}

}  // namespace

bool parse_command_line(const std::vector<std::string>& args, const po::options_description& desc,
                        const po::positional_options_description& positional, po::variables_map& vm,
                        std::string_view usage, std::ostream& out) {
  const std::vector<std::string> positionals = positional_names(positional);
  try {
    po::store(po::command_line_parser(args).options(desc).positional(positional).style(command_line_style()).run(),
              vm);
    if (vm.count("help")) {
      out << "usage: " << usage << "\n\n" << desc << "\n";
      return false;
    }
    po::notify(vm);
  } catch (const po::too_many_positional_options_error&) {
    throw InputError(unexpected_argument_message(args, desc, positional, usage));
  } catch (const po::required_option& e) {
    std::string name = e.get_option_name();
    name.erase(0, name.find_first_not_of('-'));
    if (std::find(positionals.begin(), positionals.end(), name) != positionals.end()) {
      // Boost names the first missing one in alphabetical order; the user reads them in order.
      for (const std::string& p : positionals) {
        const po::option_description* option = desc.find_nothrow(p, false);
        if (!vm.count(p) && option && option->semantic()->is_required()) {
          name = p;
          break;
        }
      }
      throw InputError(fmt::format("expected the {} argument, found none; usage: {}", upper(name), first_line(usage)));
    }
    throw InputError(option_error_message(e, desc, args));
  } catch (const po::error& e) {
    throw InputError(option_error_message(e, desc, args));
  }
  reject_empty_values(vm, desc, positionals);
  if (vm.count("format")) parse_format(vm["format"].as<std::string>());
  return true;
}

CommonOptions common_options(const po::variables_map& vm) {
  CommonOptions o;
  if (vm.count("format")) o.format = parse_format(vm["format"].as<std::string>());
  if (vm.count("output")) o.output = vm["output"].as<std::string>();
  o.strict = vm.count("strict") > 0;
  if (vm.count("table")) o.table = vm["table"].as<std::string>();
  return o;
}

int exit_status(const Report& report, const CommonOptions& options) {
  return options.strict && !report.warnings.empty() ? 3 : 0;
}

int emit(const Report& report, const CommonOptions& options, OutputSet& outputs) {
  const Report* checked = &report;
  Report named;
  if (!non_finite_quantities(report).empty()) {  // rare: copy only then
    named = report;
    warn_non_finite(named);
    checked = &named;
  }
  // The report goes to standard output unless --output says otherwise: another output sent
  // there ("--svg -") is the one to blame, not the --output the user may never have typed.
  if (const auto other = outputs.standard_output_option(); other && options.output == "-")
    fail_option(*other, "cannot write '-': standard output receives the report; give --output FILE to write the "
                        "report elsewhere");
  outputs.add("--output", options.output, render_for_output(*checked, options, outputs));
  outputs.commit();
  print_moved_warnings(*checked, options, std::cerr);
  return exit_status(*checked, options);
}

int emit(const Report& report, const CommonOptions& options, std::ostream& out) {
  OutputSet outputs(out);
  return emit(report, options, outputs);
}

}  // namespace gearkit::io
