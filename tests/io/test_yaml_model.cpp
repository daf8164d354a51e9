// Tests for gearkit/io/yaml_model.hpp: loading and field-by-field reading with exact
// file:line:column marks (1-based, as editors show them).
#include <gearkit/io/yaml_model.hpp>

#include <run_gearkit.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

using gearkit::io::InputError;
using gearkit::io::load_yaml_file;
using gearkit::io::load_yaml_text;
using gearkit::io::MapReader;
using gearkit::io::Quantity;

namespace {

std::filesystem::path write(const std::filesystem::path& dir, const std::string& name, const std::string& text) {
  std::filesystem::path p = dir / name;
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

// The message of the InputError thrown by f, or "" if none was thrown.
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(YamlModel, ReadsQuantitiesWithUnitsAndDefaults) {
  auto doc = load_yaml_text("module: 3 mm\nangle: 20\nspeed: 2950 rpm\nz: 12\nname: pinion\n", "m.yaml");
  MapReader r(doc.root, doc.file, "gear");
  EXPECT_DOUBLE_EQ(r.quantity("module", Quantity::length, "mm"), 0.003);
  EXPECT_DOUBLE_EQ(r.quantity("angle", Quantity::angle, "deg"), 20 * std::numbers::pi / 180);
  EXPECT_DOUBLE_EQ(r.quantity("speed", Quantity::angular_velocity, "rpm"), 2950 * std::numbers::pi / 30);
  EXPECT_EQ(r.integer("z"), 12);
  EXPECT_EQ(r.string("name"), "pinion");
  EXPECT_FALSE(r.optional_quantity("helix", Quantity::angle, "deg").has_value());
  EXPECT_NO_THROW(r.finish());
}

TEST(YamlModel, UnknownKeyIsReportedAtItsPosition) {
  auto doc = load_yaml_text("z: 12\nmodulus: 3\n", "m.yaml");
  MapReader r(doc.root, doc.file, "gear");
  r.integer("z");
  r.optional_quantity("module", Quantity::length, "mm");
  std::string msg = error_of([&] { r.finish(); });
  EXPECT_NE(msg.find("m.yaml:2:1: unknown key 'modulus' in gear"), std::string::npos) << msg;
  EXPECT_NE(msg.find("module"), std::string::npos) << msg;  // the keys it knows are listed
}

// "{module: 2,5 mm}" is split by YAML at the comma into module: 2 and a key "5 mm"; the message
// must say decimal comma, not "unknown key".
TEST(YamlModel, DecimalCommaInAFlowMappingIsNamed) {
  auto doc = load_yaml_text("gear: {z: 12, module: 2,5 mm}\n", "m.yaml");
  MapReader top(doc.root, doc.file, "file");
  MapReader r = top.map("gear");
  r.integer("z");
  r.optional_quantity("module", Quantity::length, "mm");
  std::string msg = error_of([&] { r.finish(); });
  EXPECT_NE(msg.find("m.yaml:1:25: expected a decimal point, found a decimal comma before '5 mm'"),
            std::string::npos) << msg;
  EXPECT_EQ(msg.find("unknown key"), std::string::npos) << msg;
}

TEST(YamlModel, MismatchedUnitNamesFileLineColumn) {
  auto doc = load_yaml_text("gear:\n  module: 20 deg\n", "m.yaml");
  MapReader top(doc.root, doc.file, "model");
  MapReader g = top.map("gear");
  std::string msg = error_of([&] { g.quantity("module", Quantity::length, "mm"); });
  EXPECT_NE(msg.find("m.yaml:2:11: 'module': expected a length"), std::string::npos) << msg;
}

TEST(YamlModel, WrongTypesAreErrors) {
  auto doc = load_yaml_text("z: 12.5\nlist: 3\nsub: [1, 2]\nflag: maybe\nmode: sideways\n", "m.yaml");
  MapReader r(doc.root, doc.file, "gear");
  EXPECT_NE(error_of([&] { r.integer("z"); }).find("m.yaml:1:4: 'z': expected a whole number, found '12.5'"),
            std::string::npos);
  EXPECT_NE(error_of([&] { r.sequence("list"); }).find("m.yaml:2:7: 'list': expected a list"), std::string::npos);
  EXPECT_NE(error_of([&] { r.map("sub"); }).find("m.yaml:3:6: expected a mapping"), std::string::npos);
  EXPECT_NE(error_of([&] { r.boolean("flag"); }).find("expected true or false, found 'maybe'"), std::string::npos);
  EXPECT_NE(error_of([&] { r.choice("mode", {"external", "internal"}); })
                .find("expected one of external, internal, found 'sideways'"),
            std::string::npos);
  EXPECT_NE(error_of([&] { r.integer("missing"); }).find("missing key 'missing' in gear"), std::string::npos);
}

TEST(YamlModel, DuplicateKeysAreErrors) {
  auto doc = load_yaml_text("z: 12\nz: 13\n", "m.yaml");
  std::string msg = error_of([&] { MapReader r(doc.root, doc.file, "gear"); });
  EXPECT_NE(msg.find("m.yaml:2:1: duplicate key 'z'"), std::string::npos) << msg;
}

TEST(YamlModel, MalformedYamlGivesParserPosition) {
  // The unclosed flow sequence opened at line 1, column 4 is found wanting at line 2, column 2
  // (libyaml's problem and context marks).
  std::string msg = error_of([] { load_yaml_text("a: [1, 2\nb: 3\n", "bad.yaml"); });
  EXPECT_NE(msg.find("bad.yaml:2:2: malformed YAML: did not find expected ',' or ']'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("flow sequence at line 1, column 4"), std::string::npos) << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  // An unterminated quoted scalar is an error, not a value running to the end of the file.
  msg = error_of([] { load_yaml_text("a: \"unterminated\n", "quote.yaml"); });
  EXPECT_NE(msg.find("quote.yaml:2:1: malformed YAML"), std::string::npos) << msg;
  EXPECT_NE(error_of([] { load_yaml_text("a: *nowhere\n", "alias.yaml"); }).find("alias.yaml:1:4: malformed YAML"),
            std::string::npos);
}

TEST(YamlModel, NodesFollowTheYamlRulesTheReadersExpect) {
  // YAML 1.1 (yaml.org/type/null.html): ~, null, Null, NULL and nothing are null when plain;
  // quoted they are strings. Block scalars keep their line breaks (YAML 1.2 section 8.1).
  const auto doc = load_yaml_text(
      "a: ~\nb: null\nc:\nd: \"null\"\ne: 'NULL'\nf: |\n  two\n  lines\ng: &pair [1, 2]\nh: *pair\n"
      "gear:\n  z: 12\n",
      "m.yaml");
  for (const char* key : {"a", "b", "c"}) EXPECT_TRUE(doc.root[key].IsNull()) << key;
  EXPECT_EQ(doc.root["d"].as<std::string>(), "null");
  EXPECT_EQ(doc.root["e"].as<std::string>(), "NULL");
  EXPECT_EQ(doc.root["f"].as<std::string>(), "two\nlines\n");
  ASSERT_TRUE(doc.root["h"].IsSequence());
  EXPECT_EQ(doc.root["h"].size(), 2u);
  EXPECT_EQ(doc.root["h"][1].as<int>(), 2);  // an alias is its anchor's node
  // Marks are the node's first character, 1-based as editors show them: "12" at line 12, column 6.
  const gearkit::io::SourceMark m = gearkit::io::mark_of(doc.root["gear"]["z"], doc.file);
  EXPECT_EQ(m.line, 12);
  EXPECT_EQ(m.column, 6);
  EXPECT_EQ(gearkit::io::mark_of(doc.root["gear"], doc.file).line, 12);  // a block mapping starts at its first key
}

TEST(YamlModel, NestingIsLimitedTo500Levels) {
  // docs/cli.md, Limits: 500 levels of collections are read, the 501st is refused where it opens.
  const auto nested = [](int levels) { return "a: " + std::string(levels - 1, '[') + std::string(levels - 1, ']') + "\n"; };
  EXPECT_EQ(error_of([&] { load_yaml_text(nested(500), "ok.yaml"); }), "");
  const std::string msg = error_of([&] { load_yaml_text(nested(501), "deep.yaml"); });
  EXPECT_NE(msg.find("deep.yaml:1:503: expected YAML nested at most 500 levels deep"), std::string::npos) << msg;
}

TEST(YamlModel, FileProblemsAreOneLineErrors) {
  auto dir = gearkit::testing::scratch_dir("yaml_model");
  EXPECT_NE(error_of([&] { load_yaml_file((dir / "absent.yaml").string()); }).find("no such file"), std::string::npos);
  EXPECT_NE(error_of([&] { load_yaml_file(dir.string()); }).find("found a directory"), std::string::npos);
  auto empty = write(dir, "empty.yaml", "");
  EXPECT_NE(error_of([&] { load_yaml_file(empty.string()); }).find("empty file"), std::string::npos);
  auto comments = write(dir, "comments.yaml", "# only a comment\n\n");
  EXPECT_NE(error_of([&] { load_yaml_file(comments.string()); }).find("empty file"), std::string::npos);
  std::string garbage("\x7f" "ELF\x02\x01\x01\0\0\0\xff\xfe", 12);
  auto bin = write(dir, "garbage.yaml", garbage);
  EXPECT_NE(error_of([&] { load_yaml_file(bin.string()); }).find("binary data"), std::string::npos);
  auto latin1 = write(dir, "latin1.yaml", "name: pi\xf1on\n");
  EXPECT_NE(error_of([&] { load_yaml_file(latin1.string()); }).find("latin1.yaml:1:9: expected a YAML text file"),
            std::string::npos);
  auto fifo = dir / "fifo.yaml";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_NE(error_of([&] { load_yaml_file(fifo.string()); }).find("special file"), std::string::npos);
  if (::geteuid() != 0) {  // root reads anything, so the permission case only exists for others
    auto locked = write(dir, "locked.yaml", "a: 1\n");
    std::filesystem::permissions(locked, std::filesystem::perms::none);
    EXPECT_NE(error_of([&] { load_yaml_file(locked.string()); }).find("readable"), std::string::npos);
  }
  auto big = write(dir, "big.yaml", std::string(2 << 20, ' ') + "a: 1\n");
  EXPECT_NE(error_of([&] { load_yaml_file(big.string(), 1 << 20); }).find("at most 1 MiB"), std::string::npos);
}

TEST(YamlModel, DeeplyNestedSequencesAreRefusedNotCrashing) {
  // 10 MB of nested flow sequences: must end in an error (the depth limit), not a stack overflow.
  std::string text(5u << 20, '[');
  text += std::string(5u << 20, ']');
  std::string msg = error_of([&] { load_yaml_text(text, "deep.yaml"); });
  EXPECT_NE(msg.find("deep.yaml:1:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("nest"), std::string::npos) << msg;
}
