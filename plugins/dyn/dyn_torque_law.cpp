#include "dyn_torque_law.hpp"

#include <gearkit/io/quantity.hpp>
#include <gearkit/io/limits.hpp>
#include <gearkit/io/yaml_model.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>

namespace gearkit::plugins::dyn {

namespace {

constexpr double deg = std::numbers::pi / 180;

std::string show_deg(double rad) { return fmt::format("{:g} deg", rad / deg); }

}  // namespace

TorqueLaw read_law(const YAML::Node& node, const std::string& file, const std::string& what) {
  TorqueLaw law;
  law.what = what;
  law.mark = io::mark_of(node, file);
  if (node.IsScalar()) {
    law.kind = TorqueLaw::Kind::constant;
    law.value = io::scalar_quantity(node, file, io::Quantity::torque, "N*m");
    return law;
  }
  io::MapReader r(node, file, what);
  const int forms = r.has("constant") + r.has("table") + r.has("expression") + r.has("power");
  if (forms != 1)
    io::fail_at(r.mark(), fmt::format("{}: expected exactly one of 'constant', 'table', 'expression' or 'power', "
                                      "found {}", what, forms));
  if (r.has("constant")) {
    law.kind = TorqueLaw::Kind::constant;
    law.value = r.quantity("constant", io::Quantity::torque, "N*m");
  } else if (r.has("power")) {
    law.kind = TorqueLaw::Kind::constant_power;
    law.value = r.quantity("power", io::Quantity::power, "W");
    if (!(law.value > 0))
      io::fail_at(r.mark("power"), fmt::format("{}: 'power': expected a positive value, found {:g} W", what, law.value));
  } else if (r.has("table")) {
    law.kind = TorqueLaw::Kind::table;
    for (const YAML::Node& row : r.sequence("table", io::limits::kDynTableRows, "rows")) {
      const io::SourceMark m = io::mark_of(row, file);
      if (!row.IsSequence() || row.size() != 2)
        io::fail_at(m, fmt::format("{}: expected a row [angle, torque], found {}", what,
                                   row.IsSequence() ? fmt::format("{} values", row.size()) : std::string("no list")));
      law.angle.push_back(io::scalar_quantity(row[0], file, io::Quantity::angle, "deg"));
      law.torque.push_back(io::scalar_quantity(row[1], file, io::Quantity::torque, "N*m"));
      law.row_marks.push_back(m);
    }
    if (law.angle.size() < 2)
      io::fail_at(r.mark("table"), fmt::format("{}: expected at least 2 rows, found {}", what, law.angle.size()));
    for (std::size_t i = 1; i < law.angle.size(); ++i) {
      if (law.angle[i] < law.angle[i - 1])
        io::fail_at(law.row_marks[i], fmt::format("{}: angles must not decrease, found {} after {}", what,
                                                  show_deg(law.angle[i]), show_deg(law.angle[i - 1])));
      if (i > 1 && law.angle[i] == law.angle[i - 1] && law.angle[i] == law.angle[i - 2])
        io::fail_at(law.row_marks[i], fmt::format("{}: three rows at {} (a step needs exactly two)", what,
                                                  show_deg(law.angle[i])));
    }
  } else {
    law.kind = TorqueLaw::Kind::expression;
    law.expression = r.string("expression");
    if (const auto p = r.optional_node("parameters")) {
      io::MapReader params(*p, file, "parameters");
      for (auto it = p->begin(); it != p->end(); ++it) {
        const std::string name = io::scalar_text(it->first, file, "a parameter name");
        law.parameters[name] = params.number(name);
      }
      params.finish();
    }
    if (const auto n = r.optional_integer("samples")) {
      if (*n < 8 || *n > 1000000)
        io::fail_at(r.mark("samples"), fmt::format("'samples': expected 8 to 1000000, found {}", *n));
      law.samples = static_cast<int>(*n);
    }
    try {
      gd::Expression(law.expression, {"theta", "omega", "t"}, law.parameters);
    } catch (const std::invalid_argument& e) {
      io::fail_at(r.mark("expression"), fmt::format("{}: {}", what, e.what()));
    }
  }
  if (r.has("scale")) {
    const YAML::Node s = r.node("scale");
    if (s.IsScalar() && s.Scalar() == "balance") {
      law.balance = true;
    } else {
      law.scale = r.number("scale");
      if (!std::isfinite(law.scale)) io::fail_at(r.mark("scale"), "'scale': expected a finite number or 'balance'");
    }
  }
  r.finish();
  return law;
}

namespace {

// The one place a torque table becomes a periodic curve: libdyn's preconditions (rows in order,
// at most two at one angle, the end value equal to the start value) become errors at the table.
gd::PiecewiseLinear periodic_table(const TorqueLaw& law, std::vector<double> angle) {
  double scale = 0;
  for (double t : law.torque) scale = std::max(scale, std::abs(t));
  if (std::abs(law.torque.front() - law.torque.back()) > 1e-9 * scale)
    io::fail_at(law.row_marks.back(),
                fmt::format("{} is not periodic: {:g} N*m at {} but {:g} N*m at {}; end the table with the "
                            "value it starts with (a jump is two rows at the same angle)",
                            law.what, law.torque.front(), show_deg(law.angle.front()), law.torque.back(),
                            show_deg(law.angle.back())));
  std::vector<double> torque = law.torque;
  torque.back() = torque.front();  // equal within 1e-9: exactly equal for the curve
  try {
    return gd::PiecewiseLinear(std::move(angle), std::move(torque), true);
  } catch (const std::invalid_argument& e) {
    io::fail_at(law.mark, fmt::format("{}: {}", law.what, e.what()));
  }
}

}  // namespace

gd::PiecewiseLinear curve_of(const TorqueLaw& law, double cycle) {
  gd::PiecewiseLinear curve = gd::PiecewiseLinear::constant(law.value, 0, cycle);
  switch (law.kind) {
    case TorqueLaw::Kind::constant:
      break;
    case TorqueLaw::Kind::constant_power:
      io::fail_at(law.mark, fmt::format("{}: a constant power is not a torque of the angle; give a torque here",
                                        law.what));
    case TorqueLaw::Kind::table: {
      const double range = law.angle.back() - law.angle.front();
      if (std::abs(law.angle.front()) > 1e-9 * cycle || std::abs(range - cycle) > 1e-9 * cycle)
        io::fail_at(law.mark, fmt::format("{}: the table must run over one cycle, from 0 to {}; found {} to {}",
                                          law.what, show_deg(cycle), show_deg(law.angle.front()),
                                          show_deg(law.angle.back())));
      std::vector<double> x = law.angle;
      x.front() = 0;
      x.back() = cycle;
      curve = periodic_table(law, std::move(x));
      break;
    }
    case TorqueLaw::Kind::expression: {
      std::optional<gd::Expression> e;
      try {
        e.emplace(law.expression, std::vector<std::string>{"theta"}, law.parameters);
      } catch (const std::invalid_argument& ex) {
        io::fail_at(law.mark, fmt::format("{}: over the cycle only 'theta' may vary: {}", law.what, ex.what()));
      }
      try {
        curve = gd::sample([&e](double th) { return (*e)({th}); }, 0, cycle, law.samples, false);
      } catch (const std::exception& ex) {
        io::fail_at(law.mark, fmt::format("{}: {}", law.what, ex.what()));
      }
      const auto& y = curve.y();
      double scale = 0;
      for (double v : y) scale = std::max(scale, std::abs(v));
      if (std::abs(y.front() - y.back()) > 1e-9 * scale)
        io::fail_at(law.mark, fmt::format("{} is not periodic: {:g} N*m at 0 deg but {:g} N*m at {}", law.what,
                                          y.front(), y.back(), show_deg(cycle)));
      std::vector<double> yy = y;
      yy.back() = yy.front();
      curve = gd::PiecewiseLinear(curve.x(), std::move(yy), true);
      break;
    }
  }
  return curve.scaled(law.scale);
}

std::function<double(double, double, double)> function_of(const TorqueLaw& law) {
  const double k = law.scale;
  switch (law.kind) {
    case TorqueLaw::Kind::constant:
      return [v = law.value * k](double, double, double) { return v; };
    case TorqueLaw::Kind::constant_power:
      return [p = law.value * k](double, double w, double) { return p / w; };
    case TorqueLaw::Kind::table: {
      std::vector<double> x = law.angle;
      const double base = x.front();
      for (double& v : x) v -= base;
      auto curve = std::make_shared<gd::PiecewiseLinear>(periodic_table(law, std::move(x)));
      return [curve, k](double th, double, double) { return k * (*curve)(th); };
    }
    case TorqueLaw::Kind::expression: {
      auto e = std::make_shared<gd::Expression>(law.expression, std::vector<std::string>{"theta", "omega", "t"},
                                                law.parameters);
      return [e, k](double th, double w, double t) { return k * (*e)({th, w, t}); };
    }
  }
  return {};
}

}  // namespace gearkit::plugins::dyn
