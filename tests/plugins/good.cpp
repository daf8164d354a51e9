// A minimal well-formed plugin for the plugin-host tests: one command, one element type.
#include "marker.hpp"

#include <gearkit/kin/angle_relation.hpp>
#include <gearkit/mechanism/element_type.hpp>
#include <gearkit/plugin/plugin.hpp>

#include <ostream>

GEARKIT_PLUGIN("test-good", "9.8.7", "Test plugin that loads")
GEARKIT_TEST_MARKER("good")

namespace {

// theta_b = ratio * theta_a (both links named by keys a and b).
std::unique_ptr<gearkit::kin::Constraint> read_test_element(gearkit::mechanism::ElementReader& reader) {
  const int a = reader.link("a"), b = reader.link("b");
  const double ratio = reader.keys().number("ratio");
  return std::make_unique<gearkit::kin::AngleRelation>(std::vector<std::pair<int, double>>{{b, 1.0}, {a, -ratio}}, 0.0,
                                                       "test_element");
}

}  // namespace

GEARKIT_PLUGIN_EXPORT void gearkit_plugin_register(gearkit::plugin::PluginRegistrar& registrar) {
  registrar.add_command({"hello-test", "Prints a greeting and its arguments", [](gearkit::plugin::CommandContext& c) {
                           c.out << "hello from test plugin";
                           for (const auto& a : c.args) c.out << " " << a;
                           c.out << "\n";
                           return 0;
                         }});
  registrar.add_element_type({"test_element", "theta_b = ratio theta_a", &read_test_element});
}
