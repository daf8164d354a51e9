#pragma once
// Shared by the binding files of the Python module: quantities given as SI floats or as strings
// with units (the files' parser), and the registration functions of each library's bindings.
#include <gearkit/io/quantity.hpp>
#include <gearkit/io/report.hpp>

#include <pybind11/pybind11.h>

#include <optional>
#include <string>
#include <string_view>

namespace gearkit::python {

namespace py = pybind11;

/// Throws io::InputError("argument '<name>': <message>"), the keyword argument's counterpart of
/// io::fail_option's "option '--name': <message>".
[[noreturn]] void fail_argument(std::string_view name, std::string_view message);

/// The SI value of a keyword argument: a float (or int) is SI already; a string is parsed by
/// io::parse_quantity_si with `expected` ("3 mm", "20 deg"; a bare number in a string is SI).
/// @throws io::InputError "argument '<name>': ..." (ValueError in Python) for a malformed string,
///   a wrong dimension, a value out of range, or another type.
double quantity_si(const py::handle& value, io::Quantity expected, const char* name);

/// As quantity_si, nullopt for None.
std::optional<double> optional_quantity_si(const py::handle& value, io::Quantity expected, const char* name);

/// A report's JSON as the CLI renders it (warnings included, numbers rounded as the CLI's).
std::string report_json(io::Report& report);

void bind_gear(py::module_& m);
void bind_train(py::module_& m);
void bind_kin(py::module_& m);

}  // namespace gearkit::python
