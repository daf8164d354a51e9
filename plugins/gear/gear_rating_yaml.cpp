// YAML readers of the rating input shared by gear-pair and train files.
#include "gear_rating_yaml.hpp"

#include <gearkit/io/error.hpp>
#include <gearkit/io/yaml_model.hpp>

#include <fmt/format.h>

#include <stdexcept>

namespace gearkit::plugins::gear {

namespace gg = gearkit::gear;

using io::MapReader;
using io::Quantity;

gg::Material read_material(const YAML::Node& node, const std::string& file, const char* what) {
  if (node.IsScalar()) {
    try {
      return gg::material_by_name(io::scalar_text(node, file, what));
    } catch (const std::invalid_argument& e) {
      io::fail_at(io::mark_of(node, file), e.what());
    }
  }
  MapReader m(node, file, what);
  gg::Material mat;
  if (m.has("class")) {
    const std::string spec = fmt::format("{}:{}:{}", m.string("class"), m.choice("grade", {"ML", "MQ", "ME"}, "MQ"), m.number("hardness"));
    try {
      mat = gg::material_by_name(spec);
    } catch (const std::invalid_argument& e) {
      io::fail_at(m.mark("class"), e.what());
    }
  }
  mat.name = m.optional_string("name").value_or(mat.name.empty() ? std::string("user-defined") : mat.name);
  mat.sigma_Hlim = m.quantity_or("sigma_Hlim", Quantity::pressure, "MPa", mat.sigma_Hlim * 1e6) / 1e6;
  mat.sigma_Flim = m.quantity_or("sigma_Flim", Quantity::pressure, "MPa", mat.sigma_Flim * 1e6) / 1e6;
  mat.E = m.quantity_or("E", Quantity::pressure, "MPa", mat.E * 1e6) / 1e6;
  mat.nu = m.optional_number("nu").value_or(mat.nu);
  mat.HB = m.optional_number("HB").value_or(mat.HB);
  try {
    gg::validate(mat);
  } catch (const std::invalid_argument& e) {
    io::fail_at(m.mark(), e.what());
  }
  m.finish();
  return mat;
}

void read_accuracy(MapReader& r, gg::RatingInput& in) {
  if (auto q = r.optional_integer("quality")) {
    if (*q < -1000 || *q > 1000) io::fail_at(r.mark("quality"), fmt::format("expected an ISO 1328 grade, found {}", *q));
    in.quality = static_cast<int>(*q);
  }
  const std::string edition = r.choice("iso1328_edition", {"2013", "1995"}, "2013");
  in.iso1328_edition = edition == "1995" ? gg::Iso1328Edition::iso1995 : gg::Iso1328Edition::iso2013;
}

}  // namespace gearkit::plugins::gear
