// Tests for gearkit/io/command_line.hpp.
#include <gearkit/io/command_line.hpp>

#include <gearkit/io/error.hpp>

#include <gtest/gtest.h>

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
  desc.add_options()("z1", po::value<int>(), "teeth");
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
  EXPECT_EQ(error_of({"--format", "xml"}), "option '--format': expected text, json, csv or md, found 'xml'");
  EXPECT_NE(error_of({"a.yaml", "b.yaml"}).find("unexpected argument"), std::string::npos);
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
