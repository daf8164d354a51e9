#include "kin_animation_elements.hpp"

#include <gearkit/io/error.hpp>
#include <gearkit/io/quantity.hpp>
#include <gearkit/io/xml.hpp>
#include <gearkit/kin/joints.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace gearkit::cli {

namespace {

std::string animate(const char* attribute, const std::vector<std::string>& values, double duration) {
  if (values.size() < 2) return "";
  return fmt::format("<animate attributeName=\"{}\" dur=\"{:.3f}s\" repeatCount=\"indefinite\" values=\"{}\"/>", attribute,
                     duration, fmt::join(values, ";"));
}

}  // namespace

std::optional<double> animation_speed(const io::po::variables_map& vm, const mechanism::Mechanism& mech, int driver) {
  if (!vm.count("speed")) return std::nullopt;
  const bool angle = mech.drivers.at(static_cast<std::size_t>(driver)).quantity == kin::DriverQuantity::angle;
  double v = 0.0;
  try {
    v = io::parse_option_quantity_si(vm["speed"].as<std::string>(),
                                     angle ? io::Quantity::angular_velocity : io::Quantity::velocity, "");
  } catch (const io::QuantityError& e) {
    io::fail_option("--speed", e.what());
  }
  if (!(v > 0)) io::fail_option("--speed", fmt::format("expected a speed above 0, found {}", io::quote(vm["speed"].as<std::string>())));
  return v;
}

// The captions stay under about 70 characters: the animation's width holds no more at its size.
double loop_seconds(const KinAnalysis& analysis, std::optional<double> speed, std::optional<double> file_speed,
                    std::size_t frames, std::string& text) {
  const double span = analysis.positions.empty() ? 0.0 : std::abs(analysis.positions.back().input - analysis.positions.front().input);
  if (speed && *speed > 0 && span > 0) {
    text = fmt::format("one loop {:.3g} s: the sweep at --speed", span / *speed);
    return span / *speed;
  }
  if (file_speed && std::abs(*file_speed) > 0 && span > 0) {
    const double real = span / std::abs(*file_speed);
    double slower = 1.0;
    while (real * slower < 0.5) slower *= 10.0;
    text = slower == 1.0 ? fmt::format("one loop {:.3g} s: the sweep at the speed in the file", real)
                         : fmt::format("one loop {:.3g} s: the speed in the file, {:g}x slower (real {:.3g} s)", real * slower,
                                       slower, real);
    return real * slower;
  }
  const double seconds = std::max(2.0, 0.04 * static_cast<double>(frames));
  text = fmt::format("one loop {:.3g} s: no speed given, 25 frames per second", seconds);
  return seconds;
}

std::string slider_elements(const kin::Model& model, const std::vector<const KinPosition*>& frames, const AnimationCanvas& c,
                            double duration) {
  std::string svg;
  const double block = 6.0 * c.stroke / c.scale;  // half length of a block [m]
  for (const auto& constraint : model.constraints()) {
    const auto* p = dynamic_cast<const kin::Prismatic*>(constraint.constraint.get());
    if (!p || frames.empty()) continue;
    std::vector<std::string> guide, slider;
    double lo = 1e300, hi = -1e300;  // the slider's travel along the guide
    for (const KinPosition* f : frames) {
      const Eigen::Vector2d g = point_at(f->q, p->guide().body, p->guide().local), s = point_at(f->q, p->slider().body, p->slider().local);
      const double a = angle_of(f->q, p->guide().body);
      const Eigen::Vector2d u = Eigen::Rotation2Dd(a) * p->axis_local().normalized();
      const double t = (s - g).dot(u);
      lo = std::min(lo, t), hi = std::max(hi, t);
      const Eigen::Vector2d n(-u.y(), u.x());
      std::string pts;
      for (const auto& [du, dn] : {std::pair{-1.0, -0.6}, {1.0, -0.6}, {1.0, 0.6}, {-1.0, 0.6}}) {
        const Eigen::Vector2d v = s + du * block * u + dn * block * n;
        pts += fmt::format("{:.3f},{:.3f} ", c.X(v.x()), c.Y(v.y()));
      }
      slider.push_back(pts);
    }
    for (const KinPosition* f : frames) {
      const Eigen::Vector2d g = point_at(f->q, p->guide().body, p->guide().local);
      const Eigen::Vector2d u = Eigen::Rotation2Dd(angle_of(f->q, p->guide().body)) * p->axis_local().normalized();
      const Eigen::Vector2d a = g + (lo - 2 * block) * u, b = g + (hi + 2 * block) * u;
      guide.push_back(fmt::format("M{:.3f},{:.3f} L{:.3f},{:.3f}", c.X(a.x()), c.Y(a.y()), c.X(b.x()), c.Y(b.y())));
    }
    svg += fmt::format("<path d=\"{}\" stroke=\"#555\" stroke-width=\"{:.3f}\" stroke-dasharray=\"{:.3f} {:.3f}\"><title>guide</title>{}</path>\n",
                       guide.front(), 0.6 * c.stroke, 3 * c.stroke, 1.5 * c.stroke, animate("d", guide, duration));
    svg += fmt::format("<polygon points=\"{}\" fill=\"#ddd\" stroke=\"#333\" stroke-width=\"{:.3f}\"><title>slider</title>{}</polygon>\n",
                       slider.front(), 0.6 * c.stroke, animate("points", slider, duration));
  }
  return svg;
}

namespace {

// A spring from a to b as SVG points: straight ends of 15 % each and a zigzag of 8 coils between,
// `width` wide (SVG units), so that it reads as a spring at any length.
std::string zigzag(const AnimationCanvas& c, const Eigen::Vector2d& a, const Eigen::Vector2d& b, double width) {
  const Eigen::Vector2d A(c.X(a.x()), c.Y(a.y())), B(c.X(b.x()), c.Y(b.y())), d = B - A;
  const double length = d.norm();
  if (!(length > 0)) return fmt::format("{:.3f},{:.3f} {:.3f},{:.3f}", A.x(), A.y(), B.x(), B.y());
  const Eigen::Vector2d u = d / length, n(-u.y(), u.x());
  constexpr int kCorners = 16;  // two per coil
  std::string pts = fmt::format("{:.3f},{:.3f} ", A.x(), A.y());
  for (int k = 0; k <= kCorners + 1; ++k) {
    const double t = 0.15 + 0.7 * static_cast<double>(k) / (kCorners + 1);
    const double side = k == 0 || k == kCorners + 1 ? 0.0 : (k % 2 ? 0.5 : -0.5);
    const Eigen::Vector2d p = A + t * d + side * width * n;
    pts += fmt::format("{:.3f},{:.3f} ", p.x(), p.y());
  }
  return pts + fmt::format("{:.3f},{:.3f}", B.x(), B.y());
}

}  // namespace

std::string spring_elements(const kin::Model& model, const std::vector<const KinPosition*>& frames, const AnimationCanvas& c,
                            double duration) {
  std::string svg;
  for (const kin::Spring& s : model.springs()) {
    if (frames.empty()) continue;
    std::vector<std::string> values;
    for (const KinPosition* f : frames)
      values.push_back(zigzag(c, point_at(f->q, s.a.body, s.a.local), point_at(f->q, s.b.body, s.b.local), 4.0 * c.stroke));
    svg += fmt::format("<polyline points=\"{}\" fill=\"none\" stroke=\"#2a7f2a\" stroke-width=\"{:.3f}\" "
                       "stroke-linejoin=\"round\"><title>spring {}</title>{}</polyline>\n",
                       values.front(), 0.6 * c.stroke, io::xml_escape(s.name), animate("points", values, duration));
  }
  return svg;
}

namespace {

// The point of `body` that a revolute joint pins to `carrier`: the gear's axis.
std::optional<kin::BodyPoint> axis_of(const kin::Model& model, int body, int carrier) {
  for (const auto& mc : model.constraints()) {
    const auto* r = dynamic_cast<const kin::Revolute*>(mc.constraint.get());
    if (!r) continue;
    if (r->a().body == body && r->b().body == carrier) return r->a();
    if (r->b().body == body && r->a().body == carrier) return r->b();
  }
  return std::nullopt;
}

// k of a gear mesh's relation (theta_2 - theta_c) + k (theta_1 - theta_c) = const, by least
// squares over the frames' steps: the element's tooth counts are the plugin's, not the solver's,
// and k = z1/z2 (external, the gears turn opposite) or -z1/z2 (internal) is what the motion shows.
std::optional<double> mesh_factor(const std::vector<const KinPosition*>& frames, int g1, int g2, int carrier) {
  double s12 = 0.0, s11 = 0.0;
  for (std::size_t i = 1; i < frames.size(); ++i) {
    auto step = [&](int b) {
      return std::remainder(angle_of(frames[i]->q, b) - angle_of(frames[i - 1]->q, b) - angle_of(frames[i]->q, carrier) +
                                angle_of(frames[i - 1]->q, carrier),
                            2.0 * std::numbers::pi);
    };
    const double d1 = step(g1), d2 = step(g2);
    s12 += d1 * d2, s11 += d1 * d1;
  }
  if (!(s11 > 1e-12)) return std::nullopt;  // the gears did not turn: nothing tells their sizes
  return -s12 / s11;
}

// One gear: its pitch circle (dashed) about its moving axis and a tooth mark, a radial tick on the
// circle at the gear's angle, so that its turning shows.
std::string gear_svg(const std::vector<const KinPosition*>& frames, const AnimationCanvas& c, const kin::BodyPoint& axis,
                     double r, double duration, const std::string& name) {
  std::vector<std::string> cx, cy, mark;
  for (const KinPosition* f : frames) {
    const Eigen::Vector2d o = point_at(f->q, axis.body, axis.local);
    const double a = angle_of(f->q, axis.body);
    const Eigen::Vector2d p = o + 0.85 * r * Eigen::Vector2d(std::cos(a), std::sin(a)), q = o + 1.12 * r * Eigen::Vector2d(std::cos(a), std::sin(a));
    cx.push_back(fmt::format("{:.3f}", c.X(o.x())));
    cy.push_back(fmt::format("{:.3f}", c.Y(o.y())));
    mark.push_back(fmt::format("M{:.3f},{:.3f} L{:.3f},{:.3f}", c.X(p.x()), c.Y(p.y()), c.X(q.x()), c.Y(q.y())));
  }
  return fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"{:.3f}\" fill=\"none\" stroke=\"#b06000\" stroke-width=\"{:.3f}\" "
                     "stroke-dasharray=\"{:.3f} {:.3f}\"><title>pitch circle {}</title>{}{}</circle>\n"
                     "<path d=\"{}\" stroke=\"#b06000\" stroke-width=\"{:.3f}\"><title>tooth mark {}</title>{}</path>\n",
                     cx.front(), cy.front(), r * c.scale, 0.6 * c.stroke, 3 * c.stroke, 1.5 * c.stroke, io::xml_escape(name),
                     animate("cx", cx, duration), animate("cy", cy, duration), mark.front(), c.stroke, io::xml_escape(name),
                     animate("d", mark, duration));
}

}  // namespace

std::vector<GearCircle> gear_circles(const kin::Model& model, const std::vector<const KinPosition*>& frames) {
  std::vector<GearCircle> out;
  for (const auto& mc : model.constraints()) {
    if (mc.constraint->kind() != "gear_mesh" || frames.size() < 2) continue;
    const std::vector<int> b = mc.constraint->bodies();  // gear 2, gear 1, carrier (the gear_mesh element's order)
    if (b.size() != 3) continue;
    const std::optional<kin::BodyPoint> a2 = axis_of(model, b[0], b[2]), a1 = axis_of(model, b[1], b[2]);
    const std::optional<double> k = mesh_factor(frames, b[1], b[0], b[2]);
    if (!a1 || !a2 || !k || !(1.0 + *k > 1e-9)) continue;
    const Eigen::VectorXd& q = frames.front()->q;
    const double a = (point_at(q, a1->body, a1->local) - point_at(q, a2->body, a2->local)).norm();
    // External: r1 + r2 = a, r1 = k r2; internal (k < 0, gear 2 the ring): r2 - r1 = a, r1 = -k r2.
    // Both give r2 = a / (1 + k).
    const double r2 = a / (1.0 + *k), r1 = std::abs(*k) * r2;
    out.push_back({*a1, r1, model.bodies()[static_cast<std::size_t>(b[1])].name});
    out.push_back({*a2, r2, model.bodies()[static_cast<std::size_t>(b[0])].name});
  }
  return out;
}

std::string gear_elements(const kin::Model& model, const std::vector<const KinPosition*>& frames, const AnimationCanvas& c,
                          double duration) {
  std::string svg;
  for (const GearCircle& g : gear_circles(model, frames)) svg += gear_svg(frames, c, g.axis, g.r, duration, g.name);
  return svg;
}

namespace {

// The world point `world` [m] in the frame of `body` at q.
Eigen::Vector2d local_of(const Eigen::VectorXd& q, int body, const Eigen::Vector2d& world) {
  return kin::rotate(-angle_of(q, body), world - point_at(q, body, Eigen::Vector2d::Zero()));
}

std::string body_name(const kin::Model& model, int body) {
  return body == kin::kGround ? std::string("ground") : model.bodies()[static_cast<std::size_t>(body)].name;
}

// The arm's end: its point farthest from the axis (local `axis`), and that distance [m].
std::pair<Eigen::Vector2d, double> arm_reach(const kin::Model& model, int arm, const Eigen::Vector2d& axis) {
  std::pair<Eigen::Vector2d, double> out{axis, 0.0};
  const auto& points = arm == kin::kGround ? model.ground().points : model.bodies()[static_cast<std::size_t>(arm)].points;
  for (const auto& [name, local] : points)
    if ((local - axis).norm() > out.second) out = {local, (local - axis).norm()};
  return out;
}

}  // namespace

std::vector<TrainPicture> train_pictures(const kin::Model& model, const std::vector<const KinPosition*>& frames) {
  std::vector<TrainPicture> out;
  for (const auto& mc : model.constraints()) {
    const kin::ConstraintDrawing d = mc.constraint->drawing();
    if (d.central.size() < 2 || frames.empty()) continue;
    std::optional<kin::BodyPoint> axis;  // the input's pivot, else another member's
    for (const auto& w : d.central) axis = axis ? axis : pivot_of(model, w.body);
    if (!axis && d.arm) axis = pivot_of(model, *d.arm);
    if (!axis) continue;
    const Eigen::VectorXd& q = frames.front()->q;
    const Eigen::Vector2d o = point_at(q, axis->body, axis->local);
    const int arm = d.arm.value_or(kin::kGround);
    TrainPicture t{mc.name, {}, {arm, local_of(q, arm, o)}, {}};
    auto [end, reach] = arm_reach(model, arm, t.arm_axis.local);
    if (!(reach > 1e-9)) {  // an arm with no point off the axis: a reach from the model's size
      for (std::size_t b = 0; b < model.bodies().size(); ++b)
        for (const auto& [name, local] : model.bodies()[b].points) reach = std::max(reach, 0.3 * (point_at(q, static_cast<int>(b), local) - o).norm());
      reach = reach > 1e-9 ? reach : 0.05;
      end = t.arm_axis.local + Eigen::Vector2d(reach, 0.0);
    }
    t.arm_end = {arm, end};
    int z_min = d.central.front().teeth, z_max = z_min;
    for (const auto& w : d.central) z_min = std::min(z_min, w.teeth), z_max = std::max(z_max, w.teeth);
    const double per_tooth = 2.0 * reach / (z_min + z_max);  // notional: the arm's end midway between the circles
    for (const auto& w : d.central)
      t.central.push_back({{w.body, local_of(q, w.body, o)}, per_tooth * w.teeth, body_name(model, w.body)});
    out.push_back(std::move(t));
  }
  return out;
}

std::string train_elements(const std::vector<TrainPicture>& trains, const std::vector<const KinPosition*>& frames,
                           const AnimationCanvas& c, double duration) {
  std::string svg;
  for (const TrainPicture& t : trains) {
    for (const GearCircle& g : t.central) svg += gear_svg(frames, c, g.axis, g.r, duration, g.name);
    std::vector<std::string> d;
    for (const KinPosition* f : frames) {
      const Eigen::Vector2d a = point_at(f->q, t.arm_axis.body, t.arm_axis.local), b = point_at(f->q, t.arm_end.body, t.arm_end.local);
      d.push_back(fmt::format("M{:.3f},{:.3f} L{:.3f},{:.3f}", c.X(a.x()), c.Y(a.y()), c.X(b.x()), c.Y(b.y())));
    }
    svg += fmt::format("<path d=\"{}\" stroke=\"#b06000\" stroke-width=\"{:.3f}\" stroke-linecap=\"round\"><title>arm {}</title>{}</path>\n",
                       d.front(), 1.6 * c.stroke, io::xml_escape(t.name), animate("d", d, duration));
  }
  return svg;
}

namespace {

// A text's or symbol's box in SVG units (y down).
struct Box {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool meets(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

// A text of `chars` characters at (x, y) (start, baseline), `size` high, `em` wide a character.
Box text_box(double x, double y, double size, std::size_t chars, double em) {
  return {x, y - size, x + em * size * static_cast<double>(chars), y + 0.25 * size};
}

// What a link's name must keep clear of in one frame: the joints' circles, the ground pivots'
// triangles and the points' names (as name_labels and the animation draw them).
std::vector<Box> label_obstacles(const kin::Model& model, const Eigen::VectorXd& q, const AnimationCanvas& c) {
  const double s = c.stroke, size = 4.5 * s;
  std::vector<Box> out;
  for (const auto& [name, p] : model.ground().points)
    out.push_back({c.X(p.x()) - 3 * s, c.Y(p.y()) - 1.2 * s, c.X(p.x()) + 3 * s, c.Y(p.y()) + 5.1 * s});
  for (std::size_t b = 0; b < model.bodies().size(); ++b)
    for (const auto& [name, local] : model.bodies()[b].points) {
      const Eigen::Vector2d p = point_at(q, static_cast<int>(b), local);
      out.push_back({c.X(p.x()) - 1.8 * s, c.Y(p.y()) - 1.8 * s, c.X(p.x()) + 1.8 * s, c.Y(p.y()) + 1.8 * s});
      out.push_back(text_box(c.X(p.x()) + 2 * s, c.Y(p.y()) - 2 * s, size, name.size(), 0.62));
    }
  return out;
}

}  // namespace

std::vector<Eigen::Vector2d> link_label_positions(const kin::Model& model, const Eigen::VectorXd& q, const AnimationCanvas& c,
                                                  std::vector<std::size_t>& choice) {
  const double s = c.stroke, size = 1.2 * 4.5 * s;
  std::vector<Box> taken = label_obstacles(model, q, c);
  std::vector<Eigen::Vector2d> out(model.bodies().size(), Eigen::Vector2d::Zero());
  for (std::size_t b = 0; b < model.bodies().size(); ++b) {
    const kin::Body& body = model.bodies()[b];
    if (body.points.empty()) continue;
    // Anchors: the middle of the link's points, then halfway from it to each point.
    std::vector<Eigen::Vector2d> anchors{Eigen::Vector2d::Zero()};
    for (const auto& [name, local] : body.points) anchors.front() += point_at(q, static_cast<int>(b), local);
    anchors.front() /= static_cast<double>(body.points.size());
    for (const auto& [name, local] : body.points) anchors.push_back(0.5 * (anchors.front() + point_at(q, static_cast<int>(b), local)));
    const double w = 0.72 * size * static_cast<double>(body.name.size());
    std::vector<Eigen::Vector2d> candidates;  // below right, above right, below left, above left
    for (const Eigen::Vector2d& a : anchors)
      for (const auto& [dx, dy] : {std::pair{s, 6 * s}, {s, -3 * s}, {-s - w, 6 * s}, {-s - w, -3 * s}})
        candidates.emplace_back(c.X(a.x()) + dx, c.Y(a.y()) + dy);
    auto clear = [&](std::size_t k) {
      const Box box = text_box(candidates[k].x(), candidates[k].y(), size, body.name.size(), 0.72);
      return std::none_of(taken.begin(), taken.end(), [&](const Box& o) { return box.meets(o); });
    };
    std::size_t k = choice[b] < candidates.size() && clear(choice[b]) ? choice[b] : 0;  // the last frame's, if still clear
    while (k < candidates.size() && !clear(k)) ++k;
    if (k == candidates.size()) k = 0;  // crowded: the first
    choice[b] = k;
    out[b] = candidates[k];
    taken.push_back(text_box(out[b].x(), out[b].y(), size, body.name.size(), 0.72));
  }
  return out;
}

std::string name_labels(const kin::Model& model, const std::vector<const KinPosition*>& frames, const AnimationCanvas& c,
                        double duration) {
  std::string svg;
  const double size = 4.5 * c.stroke;
  for (const auto& [name, p] : model.ground().points) {
    bool on_link = false;  // a pivot is named by the link point on it
    for (const kin::Body& b : model.bodies())
      for (const auto& point : b.points) on_link = on_link || point.first == name;
    if (on_link) continue;
    svg += fmt::format("<text x=\"{:.3f}\" y=\"{:.3f}\" font-size=\"{:.3f}\" font-family=\"sans-serif\" fill=\"#555\">{}</text>\n", c.X(p.x()) + 2 * c.stroke,
                       c.Y(p.y()) + 6 * c.stroke, size, io::xml_escape(name));
  }
  std::vector<std::vector<Eigen::Vector2d>> at_frame;  // per frame, each link's name position
  std::vector<std::size_t> choice(model.bodies().size(), 0);
  for (const KinPosition* f : frames) at_frame.push_back(link_label_positions(model, f->q, c, choice));
  for (std::size_t b = 0; b < model.bodies().size() && !frames.empty(); ++b) {
    const kin::Body& body = model.bodies()[b];
    if (body.points.empty()) continue;
    std::vector<std::string> lx, ly;
    for (const auto& p : at_frame) {
      lx.push_back(fmt::format("{:.3f}", p[b].x()));
      ly.push_back(fmt::format("{:.3f}", p[b].y()));
    }
    svg += fmt::format("<text x=\"{}\" y=\"{}\" font-size=\"{:.3f}\" font-family=\"sans-serif\" font-weight=\"bold\">{}{}{}</text>\n", lx.front(), ly.front(),
                       1.2 * size, io::xml_escape(body.name), animate("x", lx, duration), animate("y", ly, duration));
    for (const auto& [name, local] : body.points) {
      std::vector<std::string> px, py;
      for (const KinPosition* f : frames) {
        const Eigen::Vector2d p = point_at(f->q, static_cast<int>(b), local);
        px.push_back(fmt::format("{:.3f}", c.X(p.x()) + 2 * c.stroke));
        py.push_back(fmt::format("{:.3f}", c.Y(p.y()) - 2 * c.stroke));
      }
      svg += fmt::format("<text x=\"{}\" y=\"{}\" font-size=\"{:.3f}\" font-family=\"sans-serif\" fill=\"#333\">{}{}{}</text>\n", px.front(), py.front(), size,
                         io::xml_escape(name), animate("x", px, duration), animate("y", py, duration));
    }
  }
  return svg;
}

std::string output_traces(const mechanism::Mechanism& mech, const KinAnalysis& analysis, const AnimationCanvas& c) {
  std::string svg;
  std::vector<std::pair<int, Eigen::Vector2d>> done;
  for (const kin::Output& o : mech.outputs) {
    if (o.kind != kin::OutputKind::point_x && o.kind != kin::OutputKind::point_y) continue;
    if (o.point.body == kin::kGround) continue;
    bool seen = false;
    for (const auto& [b, l] : done) seen = seen || (b == o.point.body && (l - o.point.local).norm() < 1e-12);
    if (seen) continue;
    done.emplace_back(o.point.body, o.point.local);
    std::string d;
    for (const KinPosition& p : analysis.positions) {
      const Eigen::Vector2d v = point_at(p.q, o.point.body, o.point.local);
      d += fmt::format("{}{:.3f},{:.3f}", d.empty() ? "M" : " L", c.X(v.x()), c.Y(v.y()));
    }
    svg += fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"#a000a0\" stroke-width=\"{:.3f}\" stroke-dasharray=\"{:.3f} {:.3f}\">"
                       "<title>trace of {}</title></path>\n",
                       d, 0.5 * c.stroke, 2 * c.stroke, c.stroke, io::xml_escape(o.name));
  }
  return svg;
}

}  // namespace gearkit::cli
