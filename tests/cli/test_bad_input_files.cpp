// Every command that reads a model file must meet bad files the same way: one line on stderr
// naming the file (and line:column where there is one), exit status 2, no crash, no hang,
// and no output file left behind.
#include <run_gearkit.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sys/stat.h>

using gearkit::testing::count_lines;
using gearkit::testing::run_gearkit;
using gearkit::testing::shell_quote;

namespace fs = std::filesystem;

namespace {

// Writes the bad file `name` into `dir` (only the one a test needs: one of them is 10 MB).
fs::path make_bad_file(const fs::path& dir, const std::string& name) {
  fs::path p = dir / name;
  std::ofstream out;
  if (name != "a_directory.yaml" && name != "does_not_exist.yaml") out.open(p, std::ios::binary);
  if (name == "malformed.yaml") out << "members: [ground, sun\ngears:\n  - {z: 20\n";
  if (name == "garbage.yaml") out << std::string("\x7f" "ELF\x02\x01\x01\0\0\0\xff\xfe\x80\x81", 15);
  if (name == "scalar.yaml") out << "just a sentence\n";
  if (name == "nested.yaml") out << std::string(5u << 20, '[') << std::string(5u << 20, ']');  // 10 MB
  if (name == "a_directory.yaml") fs::create_directories(p);
  return p;
}

class BadModelFile : public ::testing::TestWithParam<std::tuple<std::string, std::string, std::string>> {};

TEST_P(BadModelFile, OneLineStatus2) {
  const auto& [command, file, part] = GetParam();
  fs::path dir = gearkit::testing::scratch_dir("bad_input_" + command);
  fs::path path = make_bad_file(dir, file);
  fs::path out = dir / "report.json";
  auto r = run_gearkit(command + " " + shell_quote(path.string()) + " --format json --output " +
                       shell_quote(out.string()));
  EXPECT_EQ(r.status, 2) << command << " " << file << ": " << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(path.string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out)) << "a report was written for a bad file";
  fs::remove_all(dir);
}

std::vector<std::tuple<std::string, std::string, std::string>> cases() {
  std::vector<std::tuple<std::string, std::string, std::string>> v;
  for (std::string cmd : {"train", "cam", "kin", "dyn"}) {
    v.emplace_back(cmd, "malformed.yaml", "malformed YAML");
    v.emplace_back(cmd, "empty.yaml", "empty file");
    v.emplace_back(cmd, "garbage.yaml", "binary data");
    v.emplace_back(cmd, "scalar.yaml", "expected a mapping");
    v.emplace_back(cmd, "nested.yaml", "nest");
    v.emplace_back(cmd, "a_directory.yaml", "found a directory");
    v.emplace_back(cmd, "does_not_exist.yaml", "no such file");
  }
  return v;
}

INSTANTIATE_TEST_SUITE_P(AllCommands, BadModelFile, ::testing::ValuesIn(cases()),
                         [](const auto& param_info) {
                           std::string n = std::get<0>(param_info.param) + "_" + std::get<1>(param_info.param);
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

}  // namespace
