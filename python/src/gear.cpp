// Bindings of libgear: a gear pair's table from keyword arguments or from a gear-pair file, and
// the load capacity of a pair file with a `load:` section, as the JSON of `gearkit gear`
// (plugins/gear's report builders), which the package turns into result objects.
#include "common.hpp"

#include "gear_pair_file.hpp"
#include "gear_rating_report.hpp"
#include "gear_report.hpp"

#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/gear/rating.hpp>
#include <gearkit/io/error.hpp>

#include <fmt/format.h>

namespace gearkit::python {

namespace gg = gearkit::gear;
using io::Quantity;

namespace {

constexpr double kMm = 1000.0;  // libgear works in mm; the arguments are SI

double mm(const py::handle& v, const char* name) { return quantity_si(v, Quantity::length, name) * kMm; }

gg::ShiftSplit shift_split(const std::string& split) {
  if (split == "balanced") return gg::ShiftSplit::balanced_sliding;
  if (split == "proportional") return gg::ShiftSplit::proportional;
  if (split == "min-shift") return gg::ShiftSplit::min_shift;
  if (split == "user") return gg::ShiftSplit::user_x1;
  fail_argument("split", fmt::format("expected balanced, proportional, min-shift or user, found {}", io::quote(split)));
}

struct PairArguments {
  int z1, z2;
  py::object module, pressure_angle, helix_angle, x1, x2, centre_distance;
  std::string split;
  py::object face_width, allowance1, allowance2;
  bool internal, transverse, tip_shortening;
};

gg::GearPairInput pair_input(const PairArguments& a) {
  gg::GearPairInput in;
  in.z1 = a.z1;
  in.z2 = a.z2;
  in.module = mm(a.module, "module");
  if (!a.pressure_angle.is_none()) in.pressure_angle = quantity_si(a.pressure_angle, Quantity::angle, "pressure_angle");
  in.helix_angle = quantity_si(a.helix_angle, Quantity::angle, "helix_angle");
  in.internal = a.internal;
  in.system = a.transverse ? gg::ModuleSystem::transverse : gg::ModuleSystem::normal;
  in.apply_tip_shortening = a.tip_shortening;
  if (!a.centre_distance.is_none()) in.centre_distance = mm(a.centre_distance, "centre_distance");
  if (in.centre_distance && !a.x2.is_none()) fail_argument("x2", "x2 follows from centre_distance (give x1 to fix the split)");
  in.x1 = a.x1.is_none() ? 0.0 : quantity_si(a.x1, Quantity::dimensionless, "x1");
  in.x2 = a.x2.is_none() ? 0.0 : quantity_si(a.x2, Quantity::dimensionless, "x2");
  in.split = shift_split(a.split.empty() ? (a.x1.is_none() ? "balanced" : "user") : a.split);
  in.face_width = mm(a.face_width, "face_width");
  in.A_sn1 = mm(a.allowance1, "allowance1");
  in.A_sn2 = mm(a.allowance2, "allowance2");
  return in;
}

// The table of a pair; a GeometryError names the GearPairInput field, which is the argument's name
// or the pair file's key.
gg::GearPairResult table(const gg::GearPairInput& in, const plugins::gear::PairFile* file) {
  try {
    return gg::compute_gear_pair(in);
  } catch (const gg::GeometryError& e) {
    if (file) io::fail_at(plugins::gear::mark_for_field(*file, e.field()), e.what());
    fail_argument(e.field(), e.what());
  }
}

std::string gear_pair_json(const PairArguments& a) {
  const gg::GearPairInput in = pair_input(a);
  io::Report report = plugins::gear::gear_report(in, table(in, nullptr));
  return report_json(report);
}

// `gearkit gear FILE --format json`: the table and, with a `load:` section, the rating.
std::string gear_pair_file_json(const std::string& path) {
  const plugins::gear::PairFile file = plugins::gear::read_pair_file(path);
  const gg::GearPairResult result = table(file.geometry, &file);
  io::Report report = plugins::gear::gear_report(file.geometry, result);
  if (file.rating) {
    gg::RatingInput rating = *file.rating;
    plugins::gear::grade_allowances(file, result, rating);
    try {
      plugins::gear::add_rating_report(report, rating, gg::rate_gear_pair(file.geometry, result, rating));
    } catch (const gg::RatingError& e) {
      io::fail_at(plugins::gear::mark_for_field(file, e.field()), e.what());
    }
  }
  return report_json(report);
}

}  // namespace

void bind_gear(py::module_& m) {
  m.def(
      "gear_pair_json",
      [](int z1, int z2, py::object module, py::object pressure_angle, py::object helix_angle, py::object x1, py::object x2,
         py::object centre_distance, std::string split, py::object face_width, py::object allowance1, py::object allowance2,
         bool internal, bool transverse, bool tip_shortening) {
        return gear_pair_json(PairArguments{z1, z2, module, pressure_angle, helix_angle, x1, x2, centre_distance, split, face_width,
                                            allowance1, allowance2, internal, transverse, tip_shortening});
      },
      py::kw_only(), py::arg("z1"), py::arg("z2"), py::arg("module"), py::arg("pressure_angle") = py::none(),
      py::arg("helix_angle") = 0.0, py::arg("x1") = py::none(), py::arg("x2") = py::none(), py::arg("centre_distance") = py::none(),
      py::arg("split") = "", py::arg("face_width") = 0.0, py::arg("allowance1") = 0.0, py::arg("allowance2") = 0.0,
      py::arg("internal") = false, py::arg("transverse") = false, py::arg("tip_shortening") = true,
      "The gear table of a pair (libgear compute_gear_pair) as the JSON of `gearkit gear --format json`.");
  m.def("gear_pair_file_json", &gear_pair_file_json, py::arg("path"),
        "A gear-pair file's table and, with a `load:` section, its rating, as `gearkit gear FILE --format json`.");
}

}  // namespace gearkit::python
