// Every element type a plugin registers, held to kin::testing::check_derivatives (issue 27,
// item 7): the plugins of the build are loaded as the executable loads them, every shipped
// mechanism file (examples/) and the cases below are read through their element types, and
// every constraint built is checked against finite differences of its own Phi. The test fails
// when a registered element type was checked by no file: a new type (a rack, a bevel stage)
// needs a case here or an example before it passes.
#include <gearkit/kin/testing.hpp>
#include <gearkit/mechanism/reader.hpp>
#include <gearkit/plugin/plugin_host.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>

namespace fs = std::filesystem;

namespace {

// Seed 004's train (as tests/kin/test_kin_animation.cpp): no example mechanism has one.
const char* kPlanetary = R"(ground: {O: [0, 0]}
links:
  sun: {points: {O: [0, 0]}}
  arm: {points: {O: [0, 0], planet: [40, 0]}}
  ring: {points: {O: [0, 0]}}
joints:
  - {type: revolute, at: [sun.O, ground.O]}
  - {type: revolute, at: [arm.O, ground.O]}
  - {type: revolute, at: [ring.O, ground.O]}
elements:
  - {name: fixed ring, type: epicyclic_train, input: sun, output: ground, arm: arm, driving: [30, 45], driven: [45, 90], externals: 1}
  - {name: moving ring, type: epicyclic_train, input: sun, output: ring, arm: arm, driving: [30, 45], driven: [45, 90], externals: 1}
  - {name: internal mesh, type: gear_mesh, gear1: sun, gear2: ring, carrier: arm, z1: 30, z2: 90, internal: true}
drivers:
  - {name: sun angle, type: angle, link: sun}
  - {name: ring angle, type: angle, link: ring}
)";

bool is_mechanism_file(const fs::path& file) {
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("elements:", 0) == 0) return true;
  return false;
}

}  // namespace

TEST(ElementDerivatives, EveryPluginElementTypeMatchesFiniteDifferences) {
  gearkit::plugin::PluginHost host({{"demo", "help", "kin", "plugins"}, gearkit::mechanism::builtin_joint_types()});
  host.load_all(gearkit::plugin::default_plugin_locations(GEARKIT_EXE));
  ASSERT_TRUE(host.failures().empty()) << host.failures().front().what();
  ASSERT_FALSE(host.element_types().empty());
  const auto lookup = [&](std::string_view type) { return host.find_element_type(type); };

  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(fs::path(GEARKIT_SOURCE_DIR) / "examples"))
    if (entry.path().extension() == ".yaml" && is_mechanism_file(entry.path())) files.push_back(entry.path());
  const fs::path planetary = fs::path(GEARKIT_BINARY_DIR) / "element_derivatives_planetary.yaml";
  std::ofstream(planetary) << kPlanetary;
  files.push_back(planetary);

  std::map<std::string, int> checked;  // constraint kind -> constraints checked
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    const gearkit::mechanism::Mechanism m = gearkit::mechanism::load_mechanism(file.string(), lookup);
    for (const auto& mc : m.model.constraints()) {
      const gearkit::kin::testing::DerivativeReport r = gearkit::kin::testing::check_derivatives(*mc.constraint);
      EXPECT_TRUE(r.ok()) << file.filename().string() << ", " << mc.name << ":\n" << r.describe(mc.constraint->kind());
      EXPECT_GT(r.entries_checked, 0);
      ++checked[mc.constraint->kind()];
    }
  }
  // An element's kind() is the type name it is registered under (the reactions and the
  // animation find elements by it).
  for (const auto& [type, spec] : host.element_types())
    EXPECT_GT(checked[type], 0) << "element type '" << type << "' (registered by a plugin) was checked by no "
                                << "mechanism: add an example or a case to this test";
  for (const char* joint : {"revolute", "gear_mesh", "epicyclic_train", "cam_follower"})
    EXPECT_GT(checked[joint], 0) << joint;
}
