// Every seed part listed in examples/seeds/parts.yaml: run its command, read the JSON value and
// compare it with the seed's printed answer at the printed precision (half a unit of the last
// printed digit). A `correct:` value documents a seed slip: gearkit must give the correct value
// and the printed one must really differ from it (docs/seeds.md explains each). A `text:` value
// is compared as written (strings such as "V-0", booleans, null).
#include <run_gearkit.hpp>

#include <nlohmann/json.hpp>
#include <yaml-cpp/yaml.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using gearkit::testing::run_gearkit;

namespace {

// Half a unit of the last digit of a printed number: "346.4" -> 0.05, "6.036e6" -> 500, "1" -> 0.5.
double half_unit(const std::string& printed) {
  const auto e = printed.find_first_of("eE");
  const std::string mantissa = printed.substr(0, e);
  const int exponent = e == std::string::npos ? 0 : std::stoi(printed.substr(e + 1));
  const auto dot = mantissa.find('.');
  const int decimals = dot == std::string::npos ? 0 : static_cast<int>(mantissa.size() - dot - 1);
  return 0.5 * std::pow(10.0, exponent - decimals);
}

double value_of(const nlohmann::json& j, const YAML::Node& check) {
  const nlohmann::json& v = j.at(nlohmann::json::json_pointer(check["json"].as<std::string>()));
  double x = 0;
  if (v.is_string()) {  // an exact fraction such as "-7/18"
    const std::string s = v.get<std::string>();
    const auto slash = s.find('/');
    x = slash == std::string::npos ? std::stod(s) : std::stod(s.substr(0, slash)) / std::stod(s.substr(slash + 1));
  } else {
    x = v.get<double>();
  }
  return x * (check["scale"] ? check["scale"].as<double>() : 1.0);
}

}  // namespace

TEST(SeedParts, EveryPrintedAnswerAtItsPrecision) {
  const YAML::Node manifest = YAML::LoadFile(std::string(GEARKIT_SOURCE_DIR) + "/examples/seeds/parts.yaml");
  int checked = 0, slips = 0;
  for (const YAML::Node& part : manifest["parts"]) {
    const std::string name = part["part"].as<std::string>();
    const auto r = run_gearkit(part["run"].as<std::string>() + " --format json", "cd " + std::string(GEARKIT_SOURCE_DIR) + " &&");
    ASSERT_EQ(r.status, 0) << name << ": " << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    for (const YAML::Node& check : part["checks"]) {
      if (check["text"]) {  // a string, a boolean or null: compared as written
        const nlohmann::json& v = j.at(nlohmann::json::json_pointer(check["json"].as<std::string>()));
        EXPECT_EQ(v.is_string() ? v.get<std::string>() : v.dump(), check["text"].as<std::string>())
            << name << " " << check["json"].as<std::string>();
        ++checked;
        continue;
      }
      const std::string printed = check["printed"].as<std::string>();
      const double value = value_of(j, check);
      const std::string where = name + " " + check["json"].as<std::string>();
      if (check["correct"]) {
        const std::string correct = check["correct"].as<std::string>();
        EXPECT_LE(std::abs(value - std::stod(correct)), half_unit(correct) * (1 + 1e-9)) << where << ": " << value;
        EXPECT_GT(std::abs(std::stod(printed) - value), half_unit(printed)) << where << ": the slip is not one";
        ++slips;
      } else {
        EXPECT_LE(std::abs(value - std::stod(printed)), half_unit(printed) * (1 + 1e-9))
            << where << ": gearkit " << value << ", printed " << printed;
      }
      ++checked;
    }
  }
  EXPECT_GE(checked, 90);
  EXPECT_EQ(slips, 5);
}
