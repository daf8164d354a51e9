#include "kin_coupler.hpp"

#include <gearkit/io/drawing_annotation.hpp>
#include <gearkit/io/error.hpp>
#include <gearkit/io/plot.hpp>
#include <gearkit/io/report.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gearkit::cli {

namespace {

constexpr double kMm = 1000.0;

const char* const kColours[] = {"#1f4e9a", "#b02020", "#2a7f2a", "#a000a0", "#b06000"};

std::string known_points(const kin::Model& m) {
  std::vector<std::string> names;
  for (const kin::Body& b : m.bodies())
    for (const auto& [p, local] : b.points) names.push_back(b.name + "." + p);
  return fmt::format("{}", fmt::join(names, ", "));
}

std::string csv_table(const mechanism::Mechanism& mech, int driver, const CouplerPaths& c) {
  const bool angle = mech.drivers[static_cast<std::size_t>(driver)].quantity == kin::DriverQuantity::angle;
  std::string out = angle ? "input_deg" : "input_mm";
  for (const CouplerPoint& p : c.points()) out += fmt::format(",{0}_x_mm,{0}_y_mm", p.name);
  out += "\n";
  for (std::size_t i = 0; i < c.inputs().size(); ++i) {
    const double in = c.inputs()[i] * (angle ? 180.0 / std::numbers::pi : kMm);
    out += fmt::format("{:.9g}", in);
    for (const auto& path : c.paths()) out += fmt::format(",{:.9g},{:.9g}", path[i].x(), path[i].y());
    out += "\n";
  }
  return out;
}

// Rulers in mm along the bottom and the left of `box` (layer "scale"): a line over the ticked
// range, a tick every nice step (io::axis_ticks, 1/2/5 x 10^n) with its value below or left of
// it, and "x [mm]" / "y [mm]". The curves were drawn to scale with nothing to read a length by.
void add_scale(io::Drawing& d, const io::Box& box, double h) {
  const io::AxisTicks tx = io::axis_ticks(box.xmin, box.xmax, 6, io::AxisScale::linear, true);
  const io::AxisTicks ty = io::axis_ticks(box.ymin, box.ymax, 6, io::AxisScale::linear, true);
  const double yb = std::min(box.ymin, ty.lo) - 2.0 * h, xl = std::min(box.xmin, tx.lo) - 2.0 * h, tick = 0.8 * h;
  d.lines.push_back({"scale", tx.lo, yb, tx.hi, yb});
  d.lines.push_back({"scale", xl, ty.lo, xl, ty.hi});
  const double mx = std::max(std::abs(tx.lo), std::abs(tx.hi)), my = std::max(std::abs(ty.lo), std::abs(ty.hi));
  for (double x : tx.values) {
    d.lines.push_back({"scale", x, yb, x, yb - tick});
    const std::string t = io::tick_label(x, tx.step, mx);
    d.texts.push_back({"scale", x - 0.5 * io::text_width(t, h), yb - tick - 1.3 * h, h, t});
  }
  for (double y : ty.values) {
    d.lines.push_back({"scale", xl, y, xl - tick, y});
    const std::string t = io::tick_label(y, ty.step, my);
    d.texts.push_back({"scale", xl - tick - 0.5 * h - io::text_width(t, h), y - 0.4 * h, h, t});
  }
  d.texts.push_back({"scale", 0.5 * (tx.lo + tx.hi) - 0.5 * io::text_width("x [mm]", h), yb - tick - 3.0 * h, h, "x [mm]"});
  d.texts.push_back({"scale", xl - 0.5 * io::text_width("y [mm]", h), ty.hi + 1.2 * h, h, "y [mm]"});
}

}  // namespace

void add_coupler_options(io::po::options_description& desc) {
  desc.add_options()
      ("coupler", io::po::value<std::string>()->value_name("LINK.POINT,..."),
       "coupler curves: the paths of these link points over the sweep")
      ("coupler-svg", io::po::value<std::string>()->value_name("FILE.svg"), "the coupler curves drawn to scale (Py against Px)")
      ("coupler-csv", io::po::value<std::string>()->value_name("FILE.csv"), "the coupler curves' points, one table (mm)")
      ("coupler-dxf", io::po::value<std::string>()->value_name("FILE.dxf"), "the coupler curves as DXF polylines (mm)");
}

std::vector<CouplerPoint> parse_coupler_points(const kin::Model& model, const std::string& text) {
  std::vector<CouplerPoint> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::string word = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const std::size_t dot = word.find('.');
    bool found = false;
    for (std::size_t b = 0; b < model.bodies().size() && dot != std::string::npos && !found; ++b) {
      if (model.bodies()[b].name != word.substr(0, dot)) continue;
      for (const auto& [name, local] : model.bodies()[b].points)
        if (name == word.substr(dot + 1)) {
          out.push_back({word, static_cast<int>(b), local});
          found = true;
        }
    }
    if (!found)
      io::fail_option("--coupler", fmt::format("expected LINK.POINT of a moving link ({}), found {}", known_points(model),
                                               io::quote(word)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

CouplerPaths::CouplerPaths(std::vector<CouplerPoint> points, long expected_positions)
    : points_(std::move(points)), paths_(points_.size()),
      stride_(std::max(1L, (expected_positions + kCouplerPoints - 1) / kCouplerPoints)) {}

void CouplerPaths::keep(double input, const Eigen::VectorXd& q) {
  inputs_.push_back(input);
  for (std::size_t k = 0; k < points_.size(); ++k)
    paths_[k].push_back(kin::Model::point_position(q, {points_[k].body, points_[k].local}) * kMm);
}

void CouplerPaths::add(const KinPosition& p) {
  skipped_last_ = seen_++ % stride_ != 0;
  if (!skipped_last_) {
    keep(p.input, p.q);
    return;
  }
  last_input_ = p.input;
  last_q_ = p.q;
}

void CouplerPaths::finish() {
  if (skipped_last_) keep(last_input_, last_q_);
  skipped_last_ = false;
}

io::Drawing coupler_drawing(const mechanism::Mechanism& mech, const std::vector<CouplerPoint>& points,
                            const std::vector<std::vector<Eigen::Vector2d>>& paths) {
  io::Drawing d;
  d.layers = {{"ground", 8, "#555555", false},
              {"labels", 7, "#000000", false},
              {"axes", 8, "#aaaaaa", true},
              {"scale", 7, "#000000", false}};
  for (std::size_t k = 0; k < points.size(); ++k) {
    const std::string layer = fmt::format("coupler_{}", k + 1);
    d.layers.push_back({layer, static_cast<int>(1 + k % 6), kColours[k % 5], false});
    io::Polyline p{layer, {}, false};
    for (const Eigen::Vector2d& v : paths[k]) p.vertices.push_back({v.x(), v.y(), 0.0});
    if (!p.vertices.empty()) d.polylines.push_back(std::move(p));
  }
  for (const auto& [name, p] : mech.model.ground().points) {
    d.circles.push_back({"ground", p.x() * kMm, p.y() * kMm, 1.0});
  }
  const io::Box box = io::drawing_box(d);
  const double h = io::text_height_for(std::max(box.xmax - box.xmin, box.ymax - box.ymin));
  for (const auto& [name, p] : mech.model.ground().points) d.texts.push_back({"ground", p.x() * kMm + 1.5, p.y() * kMm - 1.5 * h, h, name});
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (paths[k].empty()) continue;
    const Eigen::Vector2d s = paths[k].front();
    d.circles.push_back({fmt::format("coupler_{}", k + 1), s.x(), s.y(), 0.6 * h});
    if (paths[k].size() > 2) {  // the direction of travel, a little after the start
      const std::size_t i = std::max<std::size_t>(2, paths[k].size() / 16);
      const Eigen::Vector2d at = paths[k][std::min(i, paths[k].size() - 1)], t = at - paths[k][std::min(i, paths[k].size() - 1) - 1];
      if (t.norm() > 0) io::add_arrow_head(d, at.x(), at.y(), std::atan2(t.y(), t.x()), 1.5 * h, fmt::format("coupler_{}", k + 1));
    }
    io::add_label(d, s.x(), s.y(), s.x() + 3 * h, s.y() + 3 * h, points[k].name + " (start)", h, "labels");
  }
  d.lines.push_back({"axes", box.xmin - 5, 0, box.xmax + 5, 0});
  d.lines.push_back({"axes", 0, box.ymin - 5, 0, box.ymax + 5});
  add_scale(d, io::drawing_box(d), h);
  d.texts.push_back({"labels", box.xmin, io::drawing_box(d).ymax + 2 * h, h,
                     fmt::format("{}: coupler curves, Py against Px [mm]", mech.title)});
  return d;
}

std::optional<std::vector<CouplerPoint>> reserve_coupler_outputs(const io::po::variables_map& vm, const kin::Model& model,
                                                                 io::OutputSet& outputs) {
  const bool files = vm.count("coupler-svg") || vm.count("coupler-csv") || vm.count("coupler-dxf");
  if (!vm.count("coupler")) {
    if (files) io::fail_option("--coupler", "expected the points (--coupler LINK.POINT) for --coupler-svg/-csv/-dxf");
    return std::nullopt;
  }
  std::vector<CouplerPoint> points = parse_coupler_points(model, vm["coupler"].as<std::string>());
  for (const char* option : {"coupler-csv", "coupler-svg", "coupler-dxf"})
    if (vm.count(option)) outputs.reserve(std::string("--") + option, vm[option].as<std::string>());
  return points;
}

void fill_coupler_outputs(const io::po::variables_map& vm, const mechanism::Mechanism& mech, int driver, const CouplerPaths& c,
                          io::Report& report, io::OutputSet& outputs) {
  if (c.empty()) {
    report.warnings.push_back("no positions for the coupler curves; their files are not written");
    return;
  }
  if (vm.count("coupler-csv")) outputs.fill("--coupler-csv", csv_table(mech, driver, c));
  if (vm.count("coupler-svg") || vm.count("coupler-dxf")) {
    const io::Drawing d = coupler_drawing(mech, c.points(), c.paths());
    if (vm.count("coupler-svg")) outputs.fill("--coupler-svg", io::to_svg(d, {8, 0.35, mech.title}));
    if (vm.count("coupler-dxf")) outputs.fill("--coupler-dxf", io::to_dxf(d));
  }
}

}  // namespace gearkit::cli
