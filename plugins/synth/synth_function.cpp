// `gearkit synth function FILE`: a four-bar or slider-crank function generator (Freudenstein),
// three precision points (Chebyshev spacing by default) or a least-squares fit, with its
// structural error reported and plotted.
#include "synth_output.hpp"

#include <gearkit/dyn/expression.hpp>
#include <gearkit/io/error.hpp>
#include <gearkit/synth/function_generation.hpp>

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace gearkit::plugins::synth {

namespace {

constexpr double pi = std::numbers::pi;

struct FunctionFile {
  gs::FunctionTask task;
  std::string title, formula;
};

// [a, b] of quantities.
std::pair<double, double> read_pair(io::MapReader& r, const std::string& key, io::Quantity q, std::string_view unit) {
  const YAML::Node n = r.node(key);
  if (!n.IsSequence() || n.size() != 2) io::fail_at(r.mark(key), fmt::format("expected '{}' as [start, range]", key));
  return {io::scalar_quantity(n[0], r.file(), q, unit), io::scalar_quantity(n[1], r.file(), q, unit)};
}

std::function<double(double)> compile(io::MapReader& r, const std::string& text) {
  try {
    auto expr = std::make_shared<dyn::Expression>(text, std::vector<std::string>{"x"});
    return [expr](double x) {
      try {
        return (*expr)({x});
      } catch (const std::domain_error&) {
        return std::numeric_limits<double>::quiet_NaN();
      }
    };
  } catch (const std::invalid_argument& e) {
    io::fail_at(r.mark("function"), fmt::format("expected a formula in x, found '{:.60}': {}", text, e.what()));
  }
}

FunctionFile read_task(const io::YamlDocument& doc) {
  io::MapReader r(doc.root, doc.file, "function-generation task");
  FunctionFile f;
  gs::FunctionTask& t = f.task;
  f.title = r.optional_string("synthesis").value_or("");
  const bool slider = r.choice("generator", {"four-bar", "slider-crank"}, "four-bar") == "slider-crank";
  t.type = slider ? gs::GeneratorType::slider_crank : gs::GeneratorType::four_bar;
  f.formula = r.string("function");
  t.f = compile(r, f.formula);
  std::tie(t.x_start, t.x_end) = read_pair(r, "x", io::Quantity::dimensionless, "");
  std::tie(t.input_start, t.input_range) = read_pair(r, "input", io::Quantity::angle, "deg");
  std::tie(t.output_start, t.output_range) =
      read_pair(r, "output", slider ? io::Quantity::length : io::Quantity::angle, slider ? "mm" : "deg");
  if (!slider) t.ground = r.quantity_or("ground", io::Quantity::length, "mm", 0.1);
  t.method = r.choice("method", {"precision-points", "least-squares"}, "precision-points") == "least-squares"
                 ? gs::FitMethod::least_squares
                 : gs::FitMethod::precision_points;
  if (const auto n = r.optional_node("precision_points"))
    for (const YAML::Node& x : *n) t.precision_x.push_back(io::scalar_quantity(x, doc.file, io::Quantity::dimensionless, ""));
  if (const auto n = r.optional_integer("fit_points")) t.fit_points = static_cast<int>(std::clamp<long long>(*n, -1, 1 << 30));
  if (const auto n = r.optional_integer("error_samples")) t.error_samples = static_cast<int>(std::clamp<long long>(*n, -1, 1 << 30));
  r.finish();
  return f;
}

void add_precision_table(const FunctionFile& f, const gs::FunctionResult& r, Output& out) {
  const bool slider = r.type == gs::GeneratorType::slider_crank;
  io::Table t{r.precision_x.size() > 3 ? "Fit points" : "Precision points",
              {"x", "y = f(x)", "crank theta2 [deg]", slider ? "slider s [mm]" : "rocker theta4 [deg]"}, {}};
  nlohmann::json points = nlohmann::json::array();
  for (std::size_t j = 0; j < r.precision_x.size(); ++j) {
    const double x = r.precision_x[j], y = f.task.f(x);
    const double out_value = f.task.output_start + (y - r.y_start) / (r.y_end - r.y_start) * f.task.output_range;
    const double shown = slider ? out_value : gs::wrap_two_pi(out_value + r.four_bar.rocker_offset);
    t.add_row({io::fixed(x, 6), io::fixed(y, 6), deg(gs::wrap_two_pi(r.precision_theta2[j])), slider ? mm(shown) : deg(shown)});
    points.push_back({{"x", x}, {"y", y}, {"theta2_deg", r.precision_theta2[j] * 180 / pi},
                      {slider ? "s_mm" : "theta4_deg", slider ? shown * 1000 : shown * 180 / pi}});
  }
  out.report.tables.push_back(std::move(t));
  out.report.json["precision_points"] = points;
  out.report.json["coefficients"] = {{"K1", r.K.K1}, {"K2", r.K.K2}, {"K3", r.K.K3}};
  out.report.notes.push_back(fmt::format("Coefficients: K1 = {:.8g}, K2 = {:.8g}, K3 = {:.8g}{}.", r.K.K1, r.K.K2,
                                         r.K.K3, slider ? " (K1 = 2a [m], K2 = 2ae [m^2], K3 = a^2 + e^2 - b^2 [m^2])" : ""));
}

void add_error_table(const gs::FunctionResult& r, Output& out) {
  const double range = std::abs(r.y_end - r.y_start);
  io::Table t{"Structural error (y generated - f(x))", {"x", "f(x)", "generated", "error", "error [% of y range]"}, {}};
  nlohmann::json samples = nlohmann::json::array();
  const std::size_t n = r.samples.size(), stride = std::max<std::size_t>(1, (n - 1) / 10);
  for (std::size_t k = 0; k < n; ++k) {
    const gs::ErrorSample& s = r.samples[k];
    samples.push_back({s.x, s.y_ideal, std::isfinite(s.y_generated) ? nlohmann::json(s.y_generated) : nlohmann::json(nullptr)});
    if (k % stride != 0 && k + 1 != n) continue;
    t.add_row({io::fixed(s.x, 4), io::fixed(s.y_ideal, 6), std::isfinite(s.y_generated) ? io::fixed(s.y_generated, 6) : "not assembled",
               std::isfinite(s.error) ? io::fixed(s.error, 6) : "-", std::isfinite(s.error) ? io::fixed(100 * s.error / range, 4) : "-"});
  }
  out.report.tables.push_back(std::move(t));
  out.report.json["structural_error"] = {{"max_abs", r.max_error}, {"x_at_max", r.max_error_x},
                                         {"max_percent_of_range", 100 * r.max_error / range},
                                         {"samples_x_y_generated", samples}};
  out.report.notes.push_back(fmt::format("Largest structural error {:.4g} at x = {:.6g} ({:.3f} % of the y range).",
                                         r.max_error, r.max_error_x, 100 * r.max_error / range));
  if (std::any_of(r.samples.begin(), r.samples.end(), [](const auto& s) { return !std::isfinite(s.error); }))
    out.report.warnings.push_back("the generator cannot be assembled over part of the x range");
}

io::Plot error_plot(const FunctionFile& f, const gs::FunctionResult& r) {
  io::Series ideal{"f(x)", {}, {}, ""}, generated{"generated", {}, {}, ""}, error{"structural error", {}, {}, ""};
  for (const gs::ErrorSample& s : r.samples) {
    ideal.x.push_back(s.x);
    ideal.y.push_back(s.y_ideal);
    generated.x.push_back(s.x);
    generated.y.push_back(s.y_generated);
    error.x.push_back(s.x);
    error.y.push_back(s.error);
  }
  return {fmt::format("Function generator for y = {}", f.formula), "x", {{"y", {ideal, generated}, {}}, {"error in y", {error}, {}}}, 800, 240};
}

void draw_slider_crank(const gs::SliderCrank& k, const std::vector<double>& theta2, io::Drawing& d) {
  d.layers = {{"linkage", 7, "#000", false}, {"positions", 8, "#999", false}, {"pivots", 7, "#000", false}};
  const gs::Vec2 u(std::cos(k.axis_angle), std::sin(k.axis_angle)), n(-u.y(), u.x());
  const double w = (k.crank + k.rod) * 1000 / 15;
  for (std::size_t j = 0; j < theta2.size(); ++j) {
    const auto s = gs::slider_position(k, theta2[j]);
    if (!s) continue;
    const gs::Vec2 A = k.O2 + k.crank * gs::Vec2(std::cos(theta2[j]), std::sin(theta2[j])), B = k.O2 + k.offset * n + *s * u;
    const std::string layer = j == 0 ? "linkage" : "positions";
    d.polylines.push_back({layer, {{k.O2.x() * 1000, k.O2.y() * 1000, 0}, {A.x() * 1000, A.y() * 1000, 0}, {B.x() * 1000, B.y() * 1000, 0}}, false});
    d.polylines.push_back({layer, {{B.x() * 1000 - w, B.y() * 1000 - w / 2, 0}, {B.x() * 1000 + w, B.y() * 1000 - w / 2, 0},
                                   {B.x() * 1000 + w, B.y() * 1000 + w / 2, 0}, {B.x() * 1000 - w, B.y() * 1000 + w / 2, 0}}, true});
  }
  d.circles.push_back({"pivots", k.O2.x() * 1000, k.O2.y() * 1000, w / 2});
}

std::vector<std::string> mapping_comments(const FunctionFile& f, const gs::FunctionResult& r) {
  const bool slider = r.type == gs::GeneratorType::slider_crank;
  const double in0 = f.task.input_start + (slider ? r.slider_crank.crank_offset : r.four_bar.crank_offset);
  const double out0 = f.task.output_start + (slider ? 0.0 : r.four_bar.rocker_offset);
  return {fmt::format("Function generator for y = {} over x = {:g} .. {:g}, synthesised by gearkit synth.", f.formula,
                      f.task.x_start, f.task.x_end),
          fmt::format("x maps to the crank angle theta2 = {} deg + (x - {:g}) / {:g} * {} deg;", deg(in0), f.task.x_start,
                      f.task.x_end - f.task.x_start, deg(f.task.input_range)),
          slider ? fmt::format("y maps to the slider position s = {} mm + (y - {:.6g}) / {:.6g} * {} mm.", mm(out0), r.y_start,
                               r.y_end - r.y_start, mm(f.task.output_range))
                 : fmt::format("y maps to the rocker angle theta4 = {} deg + (y - {:.6g}) / {:.6g} * {} deg.", deg(out0),
                               r.y_start, r.y_end - r.y_start, deg(f.task.output_range))};
}

}  // namespace

Output run_function_task(const io::YamlDocument& doc, const Overrides& overrides) {
  const FunctionFile f = read_task(doc);
  const gs::FunctionResult r = gs::synthesize_function(f.task);
  if (!r.defects.ok())
    throw gs::NoSolution(fmt::format("the generator cannot run over the whole x range ({}); try other input or output "
                                     "ranges", r.defects.notes.front()));
  const bool slider = r.type == gs::GeneratorType::slider_crank;
  Output out;
  out.report.title = f.title.empty() ? fmt::format("Function generator ({}) for y = {}", slider ? "slider-crank" : "four-bar", f.formula) : f.title;
  out.report.json["task"] = "function";
  out.report.json["function"] = f.formula;
  add_precision_table(f, r, out);
  const int direction = f.task.input_range > 0 ? 1 : -1;
  const double theta2_start = f.task.input_start + (slider ? r.slider_crank.crank_offset : r.four_bar.crank_offset);
  std::vector<Checkpoint> checks;
  if (slider) {
    const gs::SliderCrank& k = r.slider_crank.linkage;
    io::Table t{"Linkage", {"link", "length [mm]"}, {{"crank O2A", mm(k.crank)}, {"rod AB", mm(k.rod)}, {"offset e", mm(k.offset)}}};
    out.report.tables.push_back(std::move(t));
    out.report.json["linkage"] = {{"crank_mm", k.crank * 1000}, {"rod_mm", k.rod * 1000}, {"offset_mm", k.offset * 1000}, {"branch", k.branch}};
    for (const std::string& n : r.defects.notes) out.report.warnings.push_back(n);
    gs::MechanismSketch sketch = gs::slider_crank_sketch(k, theta2_start, std::abs(f.task.input_range), direction, out.report.title);
    sketch.comments = mapping_comments(f, r);
    out.mechanism_yaml = gs::to_mechanism_yaml(sketch);
    for (double t2 : r.precision_theta2)
      if (const auto s = gs::slider_position(k, t2)) checks.push_back({unwrapped(theta2_start, t2, direction), {}, *s, "s", false});
    draw_slider_crank(k, r.precision_theta2, out.drawing);
  } else {
    const gs::FourBar& fb = r.four_bar.linkage;
    add_four_bar_tables(fb, r.defects, r.transmission, out.report);
    add_four_bar_summary(fb, theta2_start, std::abs(f.task.input_range), direction, overrides.min_transmission_angle,
                         r.defects.ok(), out.report);
    gs::MechanismSketch sketch = gs::four_bar_sketch(fb, theta2_start, std::abs(f.task.input_range), direction, out.report.title);
    sketch.comments = mapping_comments(f, r);
    out.mechanism_yaml = gs::to_mechanism_yaml(sketch);
    for (double t2 : r.precision_theta2)
      if (const auto pose = gs::pose_at(fb, t2)) checks.push_back({unwrapped(theta2_start, t2, direction), {}, pose->theta4, "theta4", true});
    draw_four_bar(fb, r.precision_theta2, std::abs(f.task.input_range), direction, out.drawing);
  }
  add_error_table(r, out);
  out.plot = error_plot(f, r);
  if (r.defects.ok()) verify_with_solver(out.mechanism_yaml, checks, out.report);
  return out;
}

}  // namespace gearkit::plugins::synth
