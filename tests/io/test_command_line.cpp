// Tests for gearkit/io/command_line.hpp.
#include <gearkit/io/command_line.hpp>

#include <gearkit/io/error.hpp>

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <sstream>

using namespace gearkit::io;

namespace {
struct Parsed {
  bool proceed;
  po::variables_map vm;
  std::string out;
};
Parsed parse(std::vector<std::string> args) {
  po::options_description desc("test");
  add_common_options(desc);
  desc.add_options()("z1", po::value<int>(), "teeth")("eta", po::value<double>(), "efficiency")(
      "svg", po::value<std::string>(), "drawing");
  po::positional_options_description pos;
  pos.add("file", 1);
  desc.add_options()("file", po::value<std::string>(), "model");
  Parsed p;
  std::ostringstream out;
  p.proceed = parse_command_line(args, desc, pos, p.vm, "gearkit test FILE", out);
  p.out = out.str();
  return p;
}
std::string error_of(std::vector<std::string> args) {
  try {
    parse(std::move(args));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(CommandLine, ParsesCommonOptions) {
  auto p = parse({"m.yaml", "--format", "json", "--output", "r.json", "--strict", "--z1", "12"});
  ASSERT_TRUE(p.proceed);
  CommonOptions c = common_options(p.vm);
  EXPECT_EQ(c.format, Format::json);
  EXPECT_EQ(c.output, "r.json");
  EXPECT_TRUE(c.strict);
  EXPECT_EQ(p.vm["z1"].as<int>(), 12);
  EXPECT_EQ(p.vm["file"].as<std::string>(), "m.yaml");
}

TEST(CommandLine, HelpStopsWithUsage) {
  auto p = parse({"--help"});
  EXPECT_FALSE(p.proceed);
  EXPECT_NE(p.out.find("usage: gearkit test FILE"), std::string::npos);
  EXPECT_NE(p.out.find("--format"), std::string::npos);
}

TEST(CommandLine, ErrorsNameTheOption) {
  EXPECT_NE(error_of({"--z1"}).find("--z1"), std::string::npos);
  EXPECT_NE(error_of({"--z1", "twelve"}).find("--z1"), std::string::npos);
  EXPECT_NE(error_of({"--frobnicate"}).find("--frobnicate"), std::string::npos);
  EXPECT_EQ(error_of({"--format", "xml"}), "option '--format': expected text, json, csv, md or html, found 'xml'");
  EXPECT_NE(error_of({"a.yaml", "b.yaml"}).find("unexpected argument"), std::string::npos);
}

// Issue 26, section 3: the message named no argument and quoted a usage of 512 characters.
TEST(CommandLine, AnUnexpectedArgumentIsNamedAndTheUsageKeptShort) {
  EXPECT_EQ(error_of({"a.yaml", "b.yaml"}).rfind("unexpected argument 'b.yaml'; usage: gearkit test FILE", 0), 0u)
      << error_of({"a.yaml", "b.yaml"});
  EXPECT_EQ(error_of({"a.yaml", "--z1", "12", "c.yaml", "d.yaml"}).rfind("unexpected argument 'c.yaml';", 0), 0u)
      << error_of({"a.yaml", "--z1", "12", "c.yaml", "d.yaml"});
}

TEST(CommandLine, StrictTurnsWarningsIntoStatus3) {
  Report r;
  r.warnings.push_back("pointed tip");
  std::ostringstream out;
  CommonOptions lax;
  EXPECT_EQ(emit(r, lax, out), 0);
  CommonOptions strict;
  strict.strict = true;
  EXPECT_EQ(emit(r, strict, out), 3);
  r.warnings.clear();
  EXPECT_EQ(emit(r, strict, out), 0);
}

// Issue 11 items 6, 7, 11: an empty value is refused, not read as "not given"; Boost's double
// options take nan, inf and 1e300, which would reach the computation; a missing positional
// argument is named as the usage shows it, not as the internal option '--file'.
TEST(CommandLine, EmptyNonFiniteAndMissingValuesAreRefusedWhereTheyEnter) {
  EXPECT_EQ(error_of({"a.yaml", "--svg", ""}), "option '--svg': expected a value, found an empty one");
  EXPECT_EQ(error_of({""}), "the FILE argument: expected a value, found an empty one");
  EXPECT_NE(error_of({"a.yaml", "--output="}).find("'--output'"), std::string::npos);
  for (const char* bad : {"nan", "inf", "-inf", "1e300", "1e-300"})
    EXPECT_NE(error_of({"a.yaml", "--eta", bad}).find("option '--eta': expected a finite number of size 0 or between"),
              std::string::npos)
        << bad;
  EXPECT_EQ(error_of({"a.yaml", "--eta", "0.9"}), "");
  EXPECT_EQ(error_of({"a.yaml", "--strict"}), "");  // a flag has no value to be empty
}

TEST(CommandLine, ABadValueIsQuotedShortOnOneLine) {
  const std::string m = error_of({"a.yaml", "--z1", std::string(100000, '9') + "\nx"});
  EXPECT_NE(m.find("'--z1'"), std::string::npos) << m;
  EXPECT_LT(m.size(), 200u) << m;
  EXPECT_EQ(m.find('\n'), std::string::npos) << m;
}

TEST(CommandLine, AMissingPositionalArgumentIsNamedAsInTheUsage) {
  po::options_description desc("test");
  desc.add_options()("file", po::value<std::string>()->required(), "model");
  po::positional_options_description pos;
  pos.add("file", 1);
  po::variables_map vm;
  std::ostringstream out;
  try {
    parse_command_line({}, desc, pos, vm, "gearkit test FILE", out);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "expected the FILE argument, found none; usage: gearkit test FILE");
  }
}

TEST(CommandLine, PositionalArgumentsOfTheSharedHelper) {
  const auto parse_two = [](std::vector<std::string> args, po::variables_map& vm) {
    po::options_description desc("test");
    po::positional_options_description pos;
    add_positional_argument(desc, pos, "task", "TASK", "the task");
    add_positional_argument(desc, pos, "file", "FILE", "the task file");
    add_positional_argument(desc, pos, "extra", "EXTRA", "an optional one", false);
    std::ostringstream out;
    return parse_command_line(args, desc, pos, vm, "gearkit test TASK FILE [EXTRA]", out);
  };
  po::variables_map vm;
  ASSERT_TRUE(parse_two({"path", "p.yaml"}, vm));
  EXPECT_EQ(vm["task"].as<std::string>(), "path");
  EXPECT_EQ(vm["file"].as<std::string>(), "p.yaml");
  EXPECT_EQ(vm.count("extra"), 0u);
  for (const auto& [args, message] :
       {std::pair{std::vector<std::string>{}, "expected the TASK argument, found none; usage: gearkit test TASK FILE [EXTRA]"},
        std::pair{std::vector<std::string>{"path"}, "expected the FILE argument, found none; usage: gearkit test TASK FILE [EXTRA]"}}) {
    po::variables_map missing;
    try {
      parse_two(args, missing);
      ADD_FAILURE() << message;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), message);
    }
  }
}

TEST(CommandLine, AnOptionsOwnRangeIsCheckedBeforeTheGenericSizes) {
  const auto run = [](std::vector<std::string> args) -> std::string {
    po::options_description desc("test");
    desc.add_options()("eta", number_in({0, 1, true, false, "an efficiency in (0, 1]"}), "efficiency")(
        "k", number_in({-2, 2}), "a factor")("gap", po::value<std::string>(), "a length");
    po::positional_options_description none;
    po::variables_map vm;
    std::ostringstream out;
    try {
      parse_command_line(args, desc, none, vm, "gearkit test", out);
      const OptionRange range{0, 1, false, true, "a gap from 0 to 1 mm (not included)"};
      const auto gap = quantity_option(vm, "gap", Quantity::length, "mm", range);
      return gap ? fmt::format("{:g}", *gap) : "ok";
    } catch (const InputError& e) {
      return e.what();
    }
  };
  EXPECT_EQ(run({"--eta", "0.98", "--k", "-1.5"}), "ok");
  EXPECT_EQ(run({"--eta", "0"}), "option '--eta': expected an efficiency in (0, 1], found 0");
  EXPECT_EQ(run({"--eta", "1.5"}), "option '--eta': expected an efficiency in (0, 1], found 1.5");
  // Inside (0, 1] but below the smallest size of any plain number (quantity.hpp, 1e-15): both said.
  EXPECT_EQ(run({"--eta", "1e-300"}), "option '--eta': expected an efficiency in (0, 1] and at least 1e-15, found 1e-300");
  EXPECT_EQ(run({"--k", "3"}), "option '--k': expected a value in [-2, 2], found 3");
  EXPECT_EQ(run({"--k", "-1e-20"}), "option '--k': expected a value in [-2, 2] and of size 0 or at least 1e-15, found -1e-20");
  EXPECT_EQ(run({"--gap", "0.5"}), "0.0005");  // SI
  EXPECT_EQ(run({"--gap", "1 mm"}), "option '--gap': expected a gap from 0 to 1 mm (not included), found '1 mm'");
  EXPECT_EQ(run({"--gap", "1e300"}), "option '--gap': expected a gap from 0 to 1 mm (not included), found '1e300'");
  EXPECT_EQ(run({"--gap", "2 deg"}).rfind("option '--gap': expected a length", 0), 0u);
}

// Issue 11 item E: Boost.Program_options' own wording ("the argument ('x') for option '--eta' is
// invalid", "cannot be specified more than once") reached the user; every option error now has
// the documented form "option '--x': expected ..., found ...".
TEST(CommandLine, BoostErrorsAreSaidInTheDocumentedForm) {
  EXPECT_EQ(error_of({"a.yaml", "--eta", "x"}), "option '--eta': expected a number, found 'x'");
  EXPECT_EQ(error_of({"a.yaml", "--z1", "1e300"}), "option '--z1': expected a whole number, found '1e300'");
  EXPECT_EQ(error_of({"a.yaml", "--z1", "1.5"}), "option '--z1': expected a whole number, found '1.5'");
  EXPECT_EQ(error_of({"a.yaml", "--z1", "99999999999"}),
            "option '--z1': expected a whole number from -2147483648 to 2147483647, found '99999999999'");
  EXPECT_EQ(error_of({"a.yaml", "--z1", "12", "--z1=13"}), "option '--z1': expected it once, found it 2 times");
  EXPECT_EQ(error_of({"a.yaml", "--svg", "a.svg", "--svg", "b.svg", "--svg", "c.svg"}),
            "option '--svg': expected it once, found it 3 times");
  EXPECT_EQ(error_of({"a.yaml", "--frobnicate"}), "option '--frobnicate': expected an option listed by --help, found an unknown one");
  EXPECT_EQ(error_of({"a.yaml", "--z1"}), "option '--z1': expected a value, found none");
  EXPECT_EQ(error_of({"a.yaml", "--strict=yes"}), "option '--strict': expected no value (it is a switch), found one");
  // The beginning of two names is no name at all (Boost would call it ambiguous with guessing on).
  EXPECT_EQ(error_of({"a.yaml", "--s", "x"}), "option '--s': expected an option listed by --help, found an unknown one");
}

// Issue 25, 1: Boost.Program_options took the beginning of a name for the option ("--modul 3" was
// --module); parse_command_line turns that guessing off and names the nearest option instead.
TEST(CommandLine, AnAbbreviationIsRefusedAndTheWholeNameSuggested) {
  EXPECT_EQ(error_of({"a.yaml", "--stirct"}),
            "option '--stirct': expected an option listed by --help, found an unknown one; did you mean '--strict'?");
  EXPECT_EQ(error_of({"a.yaml", "--outpt", "x"}),
            "option '--outpt': expected an option listed by --help, found an unknown one; did you mean '--output'?");
  EXPECT_EQ(error_of({"a.yaml", "--tabel=x"}),
            "option '--tabel': expected an option listed by --help, found an unknown one; did you mean '--table'?");
  // "--z" begins only --z1 but is one letter: too short to say what was meant.
  EXPECT_EQ(error_of({"a.yaml", "--z", "12"}), "option '--z': expected an option listed by --help, found an unknown one");
  EXPECT_EQ(error_of({"a.yaml", "--sv", "a.svg"}),
            "option '--sv': expected an option listed by --help, found an unknown one; did you mean '--svg'?");
}

// Edit distances counted by hand (one operation each): the optimal string alignment distance.
TEST(CommandLine, EditDistanceCountsInsertionsDeletionsSubstitutionsAndSwaps) {
  EXPECT_EQ(edit_distance("module", "module"), 0u);
  EXPECT_EQ(edit_distance("modul", "module"), 1u);     // one insertion
  EXPECT_EQ(edit_distance("modlue", "module"), 1u);    // one swap of neighbours (plain Levenshtein: 2)
  EXPECT_EQ(edit_distance("modale", "module"), 1u);    // one substitution
  EXPECT_EQ(edit_distance("moduule", "module"), 1u);   // one deletion
  EXPECT_EQ(edit_distance("", "svg"), 3u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);   // the textbook pair: k->s, e->i, +g
  EXPECT_EQ(edit_distance("ca", "abc"), 3u);           // OSA, unlike unrestricted Damerau (2), edits no swapped pair twice
}

TEST(CommandLine, NearestOptionIsWithinAThirdOfTheLengthOrTheOnlyExtension) {
  po::options_description desc("gear");
  desc.add_options()("module", po::value<std::string>()->value_name("LEN"), "m")(
      "helix-angle", po::value<std::string>()->value_name("ANGLE"), "beta")(
      "pressure-angle", po::value<std::string>()->value_name("ANGLE"), "alpha")(
      "pin-diameter1", po::value<std::string>()->value_name("LEN"), "D1")(
      "pin-diameter2", po::value<std::string>()->value_name("LEN"), "D2");
  EXPECT_EQ(nearest_option("--modul", desc), "--module");
  EXPECT_EQ(nearest_option("--modlue", desc), "--module");
  EXPECT_EQ(nearest_option("modlue=3", desc), "--module");
  EXPECT_EQ(nearest_option("--helix", desc), "--helix-angle");      // 6 edits away, but the only extension
  EXPECT_EQ(nearest_option("--pressure-angel", desc), "--pressure-angle");
  EXPECT_EQ(nearest_option("--pin-diameter3", desc), "--pin-diameter1");  // equals: the first declared
  EXPECT_EQ(nearest_option("--pin", desc), std::nullopt);           // begins two options, near none
  EXPECT_EQ(nearest_option("--mdl", desc), std::nullopt);           // 3 edits from module: more than 3/3 = 1
  EXPECT_EQ(nearest_option("--frobnicate", desc), std::nullopt);
  EXPECT_EQ(nearest_option("-m", desc), std::nullopt);
}

TEST(CommandLine, TheStyleHasNoGuessing) {
  EXPECT_EQ(command_line_style() & po::command_line_style::allow_guessing, 0);
  EXPECT_NE(command_line_style() & po::command_line_style::allow_long, 0);
}

// "--helix" once began only --helix-angle; with --helix-modification it begins two names, and the
// message names both rather than none (nearest_option stays silent: no single name is meant).
TEST(CommandLine, TheBeginningOfSeveralNamesIsAnsweredWithAllOfThem) {
  po::options_description desc("gear");
  desc.add_options()("pin-diameter1", po::value<std::string>(), "D1")("pin-diameter2", po::value<std::string>(), "D2");
  po::positional_options_description none;
  po::variables_map vm;
  std::ostringstream out;
  try {
    parse_command_line({"--pin", "3"}, desc, none, vm, "gearkit test", out);
    ADD_FAILURE() << "an unknown option was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "option '--pin': expected an option listed by --help, found an unknown one; "
                                     "did you mean '--pin-diameter1' or '--pin-diameter2'?");
  }
}
