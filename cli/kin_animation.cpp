// The animated SVG of `gearkit kin --animate`: each link drawn through its points, the joints as
// circles, the ground points as triangles; SMIL <animate> steps through the sweep's positions.
#include "kin_analysis.hpp"
#include "kin_animation_elements.hpp"

#include <gearkit/kin/solve.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <gearkit/io/xml.hpp>

namespace gearkit::cli {

namespace {

// At most 240 frames: the browser interpolates between them.
std::vector<const KinPosition*> select_frames(const KinAnalysis& analysis) {
  std::vector<const KinPosition*> frames;
  const std::size_t n = analysis.positions.size();
  const std::size_t stride = std::max<std::size_t>(1, (n + 239) / 240);
  for (std::size_t i = 0; i < n; i += stride) frames.push_back(&analysis.positions[i]);
  if (n > 0 && frames.back() != &analysis.positions.back()) frames.push_back(&analysis.positions.back());
  return frames;
}

// The viewport over every frame's points (mm), with a margin for slider guides and names;
// `w`, `h`: its size in SVG units.
// `discs`: circles about moving points (a pitch circle, a cam) that reach beyond the links' points.
AnimationCanvas canvas_of(const kin::Model& m, const std::vector<const KinPosition*>& frames,
                          const std::vector<std::pair<kin::BodyPoint, double>>& discs, double& w, double& h) {
  double x0 = std::numeric_limits<double>::max(), y0 = x0, x1 = -x0, y1 = -x0;
  auto grow = [&](const Eigen::Vector2d& p) {
    x0 = std::min(x0, p.x());
    x1 = std::max(x1, p.x());
    y0 = std::min(y0, p.y());
    y1 = std::max(y1, p.y());
  };
  for (const auto& [name, p] : m.ground().points) grow(p);
  for (const KinPosition* f : frames)
    for (std::size_t b = 0; b < m.bodies().size(); ++b)
      for (const auto& [name, local] : m.bodies()[b].points) grow(point_at(f->q, static_cast<int>(b), local));
  for (const auto& [centre, r] : discs)
    for (const KinPosition* f : frames) {
      const Eigen::Vector2d o = point_at(f->q, centre.body, centre.local);
      grow(o - Eigen::Vector2d(r, r));
      grow(o + Eigen::Vector2d(r, r));
    }
  if (x0 > x1) x0 = x1 = y0 = y1 = 0.0;
  // A link's name starts at the middle of its points and runs right (name_labels: bold, 5.4
  // strokes high, a stroke = span / 150; about 0.72 of its height a character): a slider's name
  // at the far end ran off the picture, past the margin.
  const double stroke_m = std::max({x1 - x0, y1 - y0, 1e-3}) / 150.0;
  for (const KinPosition* f : frames)
    for (std::size_t b = 0; b < m.bodies().size(); ++b) {
      const kin::Body& body = m.bodies()[b];
      if (body.points.empty()) continue;
      Eigen::Vector2d mid = Eigen::Vector2d::Zero();
      for (const auto& [name, local] : body.points) mid += point_at(f->q, static_cast<int>(b), local);
      mid /= static_cast<double>(body.points.size());
      x1 = std::max(x1, mid.x() + stroke_m * (1.0 + 0.72 * 5.4 * static_cast<double>(body.name.size())) - 0.14 * 150.0 * stroke_m);
    }
  const double span = std::max({x1 - x0, y1 - y0, 1e-3});
  const double margin = 0.14 * span;
  const double scale = 1000.0;  // m -> mm in the drawing's units
  w = (x1 - x0 + 2 * margin) * scale;
  h = (y1 - y0 + 2 * margin) * scale;
  return AnimationCanvas{x0, y1, margin, scale, span * scale / 150.0};
}

std::string animate(const char* attribute, double duration, const std::vector<std::string>& values) {
  if (values.size() < 2) return {};
  return fmt::format("<animate attributeName=\"{}\" dur=\"{:.2f}s\" repeatCount=\"indefinite\" values=\"{}\"/>\n", attribute,
                     duration, fmt::join(values, ";"));
}

// One link: its outline through its points (a polygon from three points), then its joints.
std::string body_svg(const kin::Model& m, std::size_t b, const std::vector<const KinPosition*>& frames, const AnimationCanvas& c,
                     double duration) {
  static const char* palette[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};
  const kin::Body& body = m.bodies()[b];
  std::vector<std::string> values;
  for (const KinPosition* f : frames) {
    std::string pts;
    for (const auto& [name, local] : body.points) {
      const Eigen::Vector2d p = point_at(f->q, static_cast<int>(b), local);
      pts += fmt::format("{:.3f},{:.3f} ", c.X(p.x()), c.Y(p.y()));
    }
    values.push_back(pts);
  }
  if (values.empty()) return {};
  const char* color = palette[b % std::size(palette)];
  const bool closed = body.points.size() >= 3;
  std::string svg = fmt::format("<{} points=\"{}\" fill=\"{}\" fill-opacity=\"0.25\" stroke=\"{}\" stroke-width=\"{:.3f}\" "
                                "stroke-linejoin=\"round\" stroke-linecap=\"round\"><title>{}</title>\n",
                                closed ? "polygon" : "polyline", values.front(), closed ? color : "none", color, c.stroke,
                                io::xml_escape(body.name));
  svg += animate("points", duration, values);
  svg += closed ? "</polygon>\n" : "</polyline>\n";
  for (const auto& [name, local] : body.points) {
    std::vector<std::string> cx, cy;
    for (const KinPosition* f : frames) {
      const Eigen::Vector2d p = point_at(f->q, static_cast<int>(b), local);
      cx.push_back(fmt::format("{:.3f}", c.X(p.x())));
      cy.push_back(fmt::format("{:.3f}", c.Y(p.y())));
    }
    svg += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"{:.3f}\" fill=\"white\" stroke=\"black\" stroke-width=\"{:.3f}\"><title>{}.{}</title>\n",
                       cx.front(), cy.front(), 1.2 * c.stroke, 0.4 * c.stroke, io::xml_escape(body.name), io::xml_escape(name));
    svg += animate("cx", duration, cx) + animate("cy", duration, cy) + "</circle>\n";
  }
  return svg;
}

}  // namespace

std::string animation_svg(const mechanism::Mechanism& mech, const KinAnalysis& analysis, std::optional<double> input_speed) {
  const kin::Model& m = mech.model;
  const std::vector<const KinPosition*> frames = select_frames(analysis);
  const std::vector<CamPicture> cams = cam_pictures(m, analysis.positions);
  const std::vector<TrainPicture> trains = train_pictures(m, frames);
  std::vector<std::pair<kin::BodyPoint, double>> discs;
  for (const GearCircle& g : gear_circles(m, frames)) discs.emplace_back(g.axis, 1.12 * g.r);
  for (const TrainPicture& t : trains)
    for (const GearCircle& g : t.central) discs.emplace_back(g.axis, 1.12 * g.r);
  for (const CamPicture& c : cams) {
    discs.emplace_back(kin::BodyPoint{c.drawing.cam, Eigen::Vector2d::Zero()}, c.reach + c.drawing.roller_radius);
    if (c.face_span) discs.emplace_back(c.drawing.contact, std::max(std::abs(c.face_span->first), std::abs(c.face_span->second)));
  }
  double w = 0, h = 0;
  const AnimationCanvas canvas = canvas_of(m, frames, discs, w, h);
  const double stroke = canvas.stroke;
  std::string loop_text;
  const double duration =
      loop_seconds(analysis, input_speed, mech.drivers.at(static_cast<std::size_t>(analysis.driver)).speed, frames.size(), loop_text);

  std::string svg = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 {:.3f} {:.3f}\" width=\"800\" height=\"{:.0f}\">\n"
      "<title>{}</title>\n<desc>{}</desc>\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      w, h, 800.0 * h / w, io::xml_escape(mech.title), io::xml_escape(loop_text));
  svg += output_traces(mech, analysis, canvas) + slider_elements(m, frames, canvas, duration) +
         spring_elements(m, frames, canvas, duration) + gear_elements(m, frames, canvas, duration) +
         train_elements(trains, frames, canvas, duration) + cam_elements(cams, frames, canvas, duration);
  for (const auto& [name, p] : m.ground().points) {
    const double s = 3 * stroke, x = canvas.X(p.x()), y = canvas.Y(p.y());
    svg += fmt::format("<polygon points=\"{:.3f},{:.3f} {:.3f},{:.3f} {:.3f},{:.3f}\" fill=\"#888\"><title>ground.{}</title></polygon>\n",
                       x, y, x - s, y + 1.7 * s, x + s, y + 1.7 * s, io::xml_escape(name));
  }
  for (std::size_t b = 0; b < m.bodies().size(); ++b) svg += body_svg(m, b, frames, canvas, duration);
  svg += name_labels(m, frames, canvas, duration);
  std::vector<std::string> notes{loop_text};
  if (const std::string cam = cam_notes(cams); !cam.empty()) notes.push_back(cam);
  for (const TrainPicture& t : trains) notes.push_back(fmt::format("train ({}): pitch circles to a notional scale (no module)", t.name));
  for (std::size_t i = 0; i < notes.size(); ++i)
    svg += fmt::format("<text x=\"{:.3f}\" y=\"{:.3f}\" font-size=\"{:.3f}\" font-family=\"sans-serif\" fill=\"#555\">{}</text>\n",
                       2 * stroke, h - 2 * stroke - 5.5 * stroke * static_cast<double>(notes.size() - 1 - i), 4.5 * stroke,
                       io::xml_escape(notes[i]));
  svg += "</svg>\n";
  return svg;
}

}  // namespace gearkit::cli
