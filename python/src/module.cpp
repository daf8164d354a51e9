// The extension module gearkit._gearkit: errors, quantities, and the bindings of each library
// (gear.cpp, train.cpp, kin.cpp). The public API is the package python/gearkit, which wraps
// what this module returns into result objects, fractions and DataFrames.
#include "common.hpp"

#include <gearkit/io/error.hpp>
#include <gearkit/io/version.hpp>

#include <fmt/format.h>

#include <cmath>

namespace gearkit::python {

void fail_argument(std::string_view name, std::string_view message) {
  throw io::InputError(fmt::format("argument '{}': {}", name, message));
}

double quantity_si(const py::handle& value, io::Quantity expected, const char* name) {
  if (py::isinstance<py::str>(value)) {
    try {
      return io::parse_quantity_si(value.cast<std::string>(), expected, "");
    } catch (const io::QuantityError& e) {
      fail_argument(name, e.what());
    }
  }
  if (py::isinstance<py::bool_>(value) || !(py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value))) {
    fail_argument(name, fmt::format("expected {} as a number in SI units or a string with its unit, found a {}",
                                      io::describe(expected), std::string(py::str(value.get_type().attr("__name__")))));
  }
  const double v = value.cast<double>();
  const io::MagnitudeRange range = io::magnitude_range(expected);
  const double size = std::fabs(v);
  if (!std::isfinite(v) || (size != 0.0 && (size < range.smallest || size > range.largest))) {
    fail_argument(name, fmt::format("expected {} of size 0 or {:g}..{:g} (SI), found {:g}", io::describe(expected), range.smallest,
                                      range.largest, v));
  }
  return v;
}

std::optional<double> optional_quantity_si(const py::handle& value, io::Quantity expected, const char* name) {
  if (value.is_none()) return std::nullopt;
  return quantity_si(value, expected, name);
}

std::string report_json(io::Report& report) {
  io::warn_non_finite(report);
  return io::render(report, io::Format::json);
}

}  // namespace gearkit::python

PYBIND11_MODULE(_gearkit, m) {
  namespace gp = gearkit::python;
  namespace py = pybind11;
  m.doc() = "gearkit's libraries (libgear, libtrain, libkin): the compiled part of the gearkit package";
  // Bad input raises ValueError with the CLI's exit-2 line; io::InputError is the library's name
  // for it. Programming errors stay the std exceptions pybind11 maps (ValueError, RuntimeError).
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const gearkit::io::InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  m.attr("__version__") = std::string(gearkit::io::version());
  gp::bind_gear(m);
  gp::bind_train(m);
  gp::bind_kin(m);
}
