// Bindings of libkin through libmechanism: a mechanism file (element types from the plugins in
// the build or install tree), its degrees of freedom, the solution at one input and a sweep
// whose samples are written straight into the buffers of NumPy arrays (one allocation per array
// for the whole sweep; no Python object per position).
#include "common.hpp"

#include <gearkit/io/error.hpp>
#include <gearkit/kin/dof.hpp>
#include <gearkit/kin/solve.hpp>
#include <gearkit/kin/sweep.hpp>
#include <gearkit/mechanism/reader.hpp>
#include <gearkit/mechanism/sweep_start.hpp>
#include <gearkit/plugin/plugin_host.hpp>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

namespace gearkit::python {

namespace {

// Element types (gear meshes, cams, ...) come from the plugins, loaded once per process. Kept
// for the whole life of the process: their element readers must outlive every model.
plugin::PluginHost& plugin_host(const std::string& plugin_dir) {
  static plugin::PluginHost* host = [&] {
    auto* h = new plugin::PluginHost(plugin::BuiltinNames{{}, mechanism::builtin_joint_types()});
    if (!plugin_dir.empty()) h->load_all({std::filesystem::path(plugin_dir)});
    return h;
  }();
  return *host;
}

// A std::vector's storage handed to NumPy without a copy: the array owns the vector.
py::array_t<double> to_array(std::vector<double>&& v, std::vector<py::ssize_t> shape) {
  auto* owner = new std::vector<double>(std::move(v));
  py::capsule free(owner, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  return py::array_t<double>(shape, owner->data(), free);
}

py::array_t<double> vector_array(const Eigen::VectorXd& v) {
  return to_array(std::vector<double>(v.data(), v.data() + v.size()), {static_cast<py::ssize_t>(v.size())});
}

class Mechanism {
 public:
  Mechanism(const std::string& path, const std::string& plugin_dir) : mech_(load(path, plugin_dir)), data_(mech_.model) {}

  const mechanism::Mechanism& mech() const { return mech_; }

  int driver_index(const py::object& driver) const {
    if (driver.is_none()) {
      if (mech_.drivers.empty()) fail_argument("driver", "the mechanism has no driver");
      return 0;
    }
    const std::string name = driver.cast<std::string>();
    for (std::size_t i = 0; i < mech_.drivers.size(); ++i)
      if (mech_.drivers[i].name == name) return static_cast<int>(i);
    std::vector<std::string> names;
    for (const auto& d : mech_.drivers) names.push_back(d.name);
    fail_argument("driver", fmt::format("expected a driver of the mechanism ({}), found {}", fmt::join(names, ", "), io::quote(name)));
  }

  io::Quantity input_quantity(int driver) const {
    return mech_.drivers[static_cast<std::size_t>(driver)].quantity == kin::DriverQuantity::angle ? io::Quantity::angle : io::Quantity::length;
  }

  py::dict dof() {
    kin::Data data(mech_.model);
    kin::solve_position(mech_.model, data, 0.0);
    const kin::DofReport r = kin::dof(mech_.model, data);
    py::dict d;
    d["moving_bodies"] = r.moving_bodies;
    d["constraint_equations"] = r.constraint_equations;
    d["gruebler"] = r.gruebler;
    d["gruebler_count"] = r.gruebler_count;
    d["rank"] = r.rank;
    d["dof"] = r.dof;
    d["redundant"] = r.redundant;
    d["redundant_rows"] = r.redundant_rows;
    d["drivers"] = r.drivers;
    return d;
  }

  py::dict solve(const py::object& at, const py::object& driver_name);
  py::dict sweep(const py::object& start, const py::object& end, const py::object& step, const py::object& driver_name, bool switch_branch);

 private:
  static mechanism::Mechanism load(const std::string& path, const std::string& plugin_dir) {
    plugin::PluginHost& host = plugin_host(plugin_dir);
    return mechanism::load_mechanism(path, [&host](std::string_view type) { return host.find_element_type(type); });
  }

  mechanism::Mechanism mech_;
  kin::Data data_;  // the drawn configuration, where every analysis starts from
};

py::dict outputs_at(const mechanism::Mechanism& mech, const kin::Data& data) {
  py::dict values;
  for (const kin::Output& o : mech.outputs) {
    const kin::OutputValue v = kin::evaluate_output(mech.model, data, o);
    values[py::str(o.name)] = py::make_tuple(v.value, v.rate, v.acceleration);
  }
  return values;
}

py::dict Mechanism::solve(const py::object& at, const py::object& driver_name) {
  const int driver = driver_index(driver_name);
  const double value = quantity_si(at, input_quantity(driver), "at");
  kin::Data data(mech_.model);
  data.q = data_.q;
  const kin::PositionReport r = kin::solve_at(mech_.model, data, driver, value);
  py::dict d;
  d["input"] = value;
  d["converged"] = r.converged;
  d["singular"] = r.singular;
  d["iterations"] = r.iterations;
  d["residual"] = r.residual;
  d["message"] = r.message;
  d["q"] = vector_array(data.q);
  d["qd"] = vector_array(data.qd);
  d["qdd"] = vector_array(data.qdd);
  d["outputs"] = r.converged && !r.singular ? outputs_at(mech_, data) : py::dict();
  return d;
}

// Row-major (samples x columns) buffers filled by the streamed sweep.
struct SweepBuffers {
  std::vector<double> input, q, qd, qdd, values, rates, accelerations;
  std::vector<std::uint8_t> on_change_point;
};

py::dict Mechanism::sweep(const py::object& start, const py::object& end, const py::object& step, const py::object& driver_name,
                          bool switch_branch) {
  const int driver = driver_index(driver_name);
  const io::Quantity quantity = input_quantity(driver);
  kin::SweepOptions o = mechanism::sweep_options(driver, quantity_si(start, quantity, "start"), quantity_si(end, quantity, "end"),
                                                 quantity_si(step, quantity, "step"), true, switch_branch);
  if (!(o.step > 0.0)) fail_argument("step", fmt::format("expected a step > 0, found {:g}", o.step));
  o.outputs = mech_.outputs;
  const long planned = kin::sweep_sample_count(o);
  if (planned > 100'000'000) fail_argument("step", fmt::format("expected at most 1e8 positions, found {}", planned));
  const std::size_t n = static_cast<std::size_t>(mech_.model.coordinates()), k = mech_.outputs.size();
  SweepBuffers b;
  for (auto* v : {&b.q, &b.qd, &b.qdd}) v->reserve(static_cast<std::size_t>(planned) * n);
  for (auto* v : {&b.values, &b.rates, &b.accelerations}) v->reserve(static_cast<std::size_t>(planned) * k);
  b.input.reserve(static_cast<std::size_t>(planned));
  kin::Data data(mech_.model), probe(mech_.model);
  data.q = data_.q;
  mechanism::approach_start(mech_, data, driver, o);
  kin::SweepResult result;
  const auto visit = [&](const kin::SweepSample& s) {
    b.input.push_back(s.input);
    b.q.insert(b.q.end(), s.q.data(), s.q.data() + n);
    b.qd.insert(b.qd.end(), s.qd.data(), s.qd.data() + n);
    b.qdd.insert(b.qdd.end(), s.qdd.data(), s.qdd.data() + n);
    b.on_change_point.push_back(s.on_change_point);
    if (k == 0) return;
    kin::Data* at = s.data;
    if (!at) {  // an interpolated sample: its outputs from q, qd, qdd in a workspace of its own
      probe.q = s.q;
      probe.qd = s.qd;
      probe.qdd = s.qdd;
      at = &probe;
    }
    for (const kin::Output& out : mech_.outputs) {
      const kin::OutputValue v = kin::evaluate_output(mech_.model, *at, out);
      b.values.push_back(v.value);
      b.rates.push_back(v.rate);
      b.accelerations.push_back(v.acceleration);
    }
  };
  {
    py::gil_scoped_release unlocked;  // the sweep touches no Python object
    kin::sweep(mech_.model, data, o, result, visit);
  }
  const auto m = static_cast<py::ssize_t>(b.input.size());
  py::dict d;
  d["input"] = to_array(std::move(b.input), {m});
  d["q"] = to_array(std::move(b.q), {m, static_cast<py::ssize_t>(n)});
  d["qd"] = to_array(std::move(b.qd), {m, static_cast<py::ssize_t>(n)});
  d["qdd"] = to_array(std::move(b.qdd), {m, static_cast<py::ssize_t>(n)});
  d["values"] = to_array(std::move(b.values), {m, static_cast<py::ssize_t>(k)});
  d["rates"] = to_array(std::move(b.rates), {m, static_cast<py::ssize_t>(k)});
  d["accelerations"] = to_array(std::move(b.accelerations), {m, static_cast<py::ssize_t>(k)});
  d["on_change_point"] = py::array_t<bool>(m, reinterpret_cast<const bool*>(b.on_change_point.data()));
  py::list dead;
  for (const auto& p : result.dead_points) dead.append(py::make_tuple(p.input, p.description));
  d["dead_points"] = dead;
  py::list change;
  for (const auto& p : result.change_points) change.append(py::make_tuple(p.input, p.bifurcation, p.switched));
  d["change_points"] = change;
  d["assembled"] = result.assembled;
  d["complete"] = result.complete;
  d["message"] = result.message;
  return d;
}

std::vector<std::string> coordinate_names(const kin::Model& model) {
  std::vector<std::string> names;
  for (int b = 0; b < static_cast<int>(model.bodies().size()); ++b)
    for (const char* c : {"x", "y", "theta"}) names.push_back(model.body_name(b) + "." + c);
  return names;
}

}  // namespace

void bind_kin(py::module_& m) {
  py::class_<Mechanism>(m, "Mechanism", "A mechanism file read into the planar solver (libmechanism load_mechanism).")
      .def(py::init<const std::string&, const std::string&>(), py::arg("path"), py::arg("plugin_dir") = "")
      .def_property_readonly("title", [](const Mechanism& s) { return s.mech().title; })
      .def_property_readonly("coordinates", [](const Mechanism& s) { return coordinate_names(s.mech().model); })
      .def_property_readonly("outputs", [](const Mechanism& s) {
        std::vector<std::string> names;
        for (const auto& o : s.mech().outputs) names.push_back(o.name);
        return names;
      })
      .def_property_readonly("drivers", [](const Mechanism& s) {
        std::vector<std::string> names;
        for (const auto& d : s.mech().drivers) names.push_back(d.name);
        return names;
      })
      .def("driver_range", [](const Mechanism& s, const py::object& driver) -> py::object {
        const auto& r = s.mech().drivers[static_cast<std::size_t>(s.driver_index(driver))].range;
        return r ? py::object(py::make_tuple(r->start, r->end, r->step)) : py::object(py::none());
      }, py::arg("driver") = py::none())
      .def("dof", &Mechanism::dof)
      .def("solve", &Mechanism::solve, py::arg("at"), py::arg("driver") = py::none())
      .def("sweep", &Mechanism::sweep, py::arg("start"), py::arg("end"), py::arg("step"), py::arg("driver") = py::none(),
           py::arg("switch_branch") = false);
}

}  // namespace gearkit::python
