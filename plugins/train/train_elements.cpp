// The `epicyclic_train` entry of mechanism files (docs/kin.md), read into
// gearkit::elements::EpicyclicTrainParameters and built by make_epicyclic_train.
#include "train_elements.hpp"

#include <gearkit/elements/epicyclic_train.hpp>
#include <gearkit/mechanism/element_type.hpp>

#include <fmt/format.h>


namespace gearkit::plugins::train {

namespace {

std::vector<int> tooth_list(io::MapReader& r, const std::string& key) {
  std::vector<int> teeth;
  for (const YAML::Node& z : r.sequence(key)) {
    const std::string text = io::scalar_text(z, r.file(), "a number of teeth");
    char* end = nullptr;
    const long v = std::strtol(text.c_str(), &end, 10);
    if (end == text.c_str() || *end != '\0' || v < 1 || v > 1000000)
      io::fail_at(io::mark_of(z, r.file()), fmt::format("expected a number of teeth from 1 to 1000000, found {}", io::quote(text)));
    teeth.push_back(static_cast<int>(v));
  }
  return teeth;
}

std::unique_ptr<kin::Constraint> read_epicyclic_train(mechanism::ElementReader& reader) {
  io::MapReader& keys = reader.keys();
  elements::EpicyclicTrainParameters p;
  p.input = reader.link("input");
  p.output = reader.link("output");
  p.arm = reader.link("arm");
  p.driving = tooth_list(keys, "driving");
  p.driven = tooth_list(keys, "driven");
  const long long externals = keys.integer("externals");
  if (externals < 0 || externals > 1000)
    io::fail_at(keys.mark("externals"), fmt::format("'externals': expected a number of external meshes from 0 to 1000, "
                                                    "found {}", externals));
  p.externals = static_cast<int>(externals);
  return elements::make_epicyclic_train(reader.model(), p);
}

}  // namespace

void register_elements(plugin::PluginRegistrar& registrar) {
  registrar.add_element_type({"epicyclic_train",
                              "Willis' equation of a simple epicyclic train: (w_out - w_arm) = tau0 (w_in - w_arm)",
                              &read_epicyclic_train});
}

}  // namespace gearkit::plugins::train
