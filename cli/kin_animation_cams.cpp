// Cams of cam_follower elements and the central members of epicyclic_train elements in the
// animation of `gearkit kin --animate`, from the geometry the constraints give for drawings
// (kin::Constraint::drawing).
#include "kin_animation_elements.hpp"

#include <gearkit/io/xml.hpp>
#include <gearkit/kin/joints.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace gearkit::cli {

namespace {

// The pose of a body's frame in SVG units: the origin and the angle in degrees, negative for a
// counter-clockwise model angle since the SVG's y axis points down.
std::string translate_value(const Eigen::VectorXd& q, int body, const AnimationCanvas& c) {
  const Eigen::Vector2d o = point_at(q, body, Eigen::Vector2d::Zero());
  return fmt::format("{:.3f},{:.3f}", c.X(o.x()), c.Y(o.y()));
}
std::string rotate_value(const Eigen::VectorXd& q, int body) {
  return fmt::format("{:.4f}", -angle_of(q, body) * 180.0 / std::numbers::pi);
}

std::string body_frame_group_open(const std::vector<const KinPosition*>& frames, int body, const AnimationCanvas& c,
                                  const std::string& title) {
  return fmt::format("<g transform=\"translate({}) rotate({})\"><title>{}</title>\n", translate_value(frames.front()->q, body, c),
                     rotate_value(frames.front()->q, body), io::xml_escape(title));
}

// The group's motion: the body's origin, then its rotation added to it.
std::string body_frame_motion(const std::vector<const KinPosition*>& frames, int body, const AnimationCanvas& c, double duration) {
  if (frames.size() < 2) return {};
  std::vector<std::string> translate, rotate;
  for (const KinPosition* f : frames) {
    translate.push_back(translate_value(f->q, body, c));
    rotate.push_back(rotate_value(f->q, body));
  }
  return fmt::format("<animateTransform attributeName=\"transform\" type=\"translate\" dur=\"{0:.3f}s\" repeatCount=\"indefinite\" "
                     "values=\"{1}\"/>\n<animateTransform attributeName=\"transform\" type=\"rotate\" additive=\"sum\" "
                     "dur=\"{0:.3f}s\" repeatCount=\"indefinite\" values=\"{2}\"/>\n",
                     duration, fmt::join(translate, ";"), fmt::join(rotate, ";"));
}

// Points of the cam's frame [m] as SVG path data in the group's units (mm, y down).
std::string path_data(const std::vector<Eigen::Vector2d>& pts, double scale, bool closed) {
  std::string d;
  for (const Eigen::Vector2d& p : pts) d += fmt::format("{}{:.3f},{:.3f}", d.empty() ? "M" : " L", p.x() * scale, -p.y() * scale);
  return closed ? d + " Z" : d;
}

// The side the cam lies on: +1 if the pitch curve runs counter-clockwise about the cam's axis
// `a` (the cam is on its left), -1 if clockwise.
double cam_side(const std::vector<Eigen::Vector2d>& pitch, const Eigen::Vector2d& a) {
  double turn = 0.0;
  for (std::size_t i = 1; i < pitch.size(); ++i) turn += kin::cross(pitch[i - 1] - a, pitch[i] - pitch[i - 1]);
  return turn >= 0.0 ? 1.0 : -1.0;
}

// The profile a roller of radius rr leaves: each pitch point moved by rr along the pitch curve's
// normal towards the cam (the inner envelope of the roller's circles), the tangent by central
// differences (one-sided at the ends of an open curve).
std::vector<Eigen::Vector2d> profile_of(const std::vector<Eigen::Vector2d>& pitch, bool closed, double side, double rr) {
  std::vector<Eigen::Vector2d> out;
  const std::size_t n = pitch.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t prev = i > 0 ? i - 1 : (closed ? n - 1 : 0), next = i + 1 < n ? i + 1 : (closed ? 0 : n - 1);
    const Eigen::Vector2d t = pitch[next] - pitch[prev];
    out.push_back(t.norm() > 0 ? Eigen::Vector2d(pitch[i] + side * rr * kin::perp(t).normalized()) : pitch[i]);
  }
  return out;
}

// One position of a flat face seen from the cam: its line n . x = p in the cam's frame (n the
// unit normal, x0 the face's point, d its direction) and dp/dphi, phi the angle of n (NaN where
// the velocities do not give it).
struct FaceLine {
  Eigen::Vector2d n, x0, d;
  double p = 0.0, dp_dphi = std::numeric_limits<double>::quiet_NaN();
};

Eigen::Vector2d velocity_of(const Eigen::VectorXd& qd, const Eigen::VectorXd& q, int body, const Eigen::Vector2d& local) {
  if (body == kin::kGround) return Eigen::Vector2d::Zero();
  const auto i = static_cast<Eigen::Index>(3 * body);
  return Eigen::Vector2d(qd(i), qd(i + 1)) + qd(i + 2) * kin::perp(kin::rotate(q(i + 2), local));
}

// dp/dphi exactly from the velocities: p = n . (P - C) in any frame (P the face's point, C the
// cam's origin) and n turns with the face's frame, so dp/dt = w_f perp(n) . (P - C) + n . (v_P -
// v_C), while phi, the angle of n from the cam, changes at w_f - w_cam.
FaceLine face_line(const KinPosition& f, const kin::ConstraintDrawing::Cam& cam) {
  const Eigen::VectorXd& q = f.q;
  const Eigen::Vector2d c = point_at(q, cam.cam, Eigen::Vector2d::Zero()), P = point_at(q, cam.contact.body, cam.contact.local);
  const Eigen::Vector2d d = kin::rotate(angle_of(q, cam.face->frame), cam.face->direction), n = kin::perp(d);
  const double theta = angle_of(q, cam.cam);
  FaceLine line{kin::rotate(-theta, n), kin::rotate(-theta, P - c), kin::rotate(-theta, d), n.dot(P - c)};
  if (f.qd.size() != q.size()) return line;
  const auto omega = [&](int body) { return body == kin::kGround ? 0.0 : f.qd(3 * body + 2); };
  const double w_f = omega(cam.face->frame), dphi = w_f - omega(cam.cam);
  const Eigen::Vector2d v = velocity_of(f.qd, q, cam.contact.body, cam.contact.local) - velocity_of(f.qd, q, cam.cam, Eigen::Vector2d::Zero());
  const double dp = w_f * kin::perp(n).dot(P - c) + n.dot(v);
  if (std::abs(dphi) > 1e-12 * (std::abs(w_f) + std::abs(omega(cam.cam)) + 1e-300)) line.dp_dphi = dp / dphi;
  return line;
}

// The profile a flat face leaves: the envelope of its lines n(phi) . x = p(phi), which solves
// them with their phi-derivative perp(n) . x = dp/dphi, so x = p n + (dp/dphi) perp(n) (Norton,
// Design of Machinery, ch. 8: the flat-faced follower's contact point lies ds/dtheta
// along the face from the follower's axis). dp/dphi by central differences where the velocities
// do not give it. `t_min`, `t_max` [m]: where the contact lies along the face from its point.
std::vector<Eigen::Vector2d> face_envelope(std::vector<FaceLine>& lines, bool closed, double& t_min, double& t_max) {
  const std::size_t n = lines.size();
  const auto phi = [&](std::size_t i) { return std::atan2(lines[i].n.y(), lines[i].n.x()); };
  std::vector<Eigen::Vector2d> out;
  t_min = std::numeric_limits<double>::max();
  t_max = -t_min;
  for (std::size_t i = 0; i < n; ++i) {
    FaceLine& l = lines[i];
    if (std::isnan(l.dp_dphi) && n > 1) {
      const std::size_t prev = i > 0 ? i - 1 : (closed ? n - 1 : 0), next = i + 1 < n ? i + 1 : (closed ? 0 : n - 1);
      const double dphi = std::remainder(phi(next) - phi(prev), 2.0 * std::numbers::pi);
      l.dp_dphi = std::abs(dphi) > 0 ? (lines[next].p - lines[prev].p) / dphi : 0.0;
    }
    if (!std::isfinite(l.dp_dphi)) l.dp_dphi = 0.0;
    out.push_back(l.p * l.n + l.dp_dphi * kin::perp(l.n));
    t_min = std::min(t_min, (out.back() - l.x0).dot(l.d));
    t_max = std::max(t_max, (out.back() - l.x0).dot(l.d));
  }
  return out;
}

}  // namespace

std::optional<kin::BodyPoint> pivot_of(const kin::Model& model, int body) {
  std::optional<kin::BodyPoint> any;
  for (const auto& mc : model.constraints()) {
    const auto* r = dynamic_cast<const kin::Revolute*>(mc.constraint.get());
    if (!r || body == kin::kGround) continue;
    for (const auto& [mine, other] : {std::pair{r->a(), r->b()}, std::pair{r->b(), r->a()}}) {
      if (mine.body != body) continue;
      if (other.body == kin::kGround) return mine;
      if (!any) any = mine;
    }
  }
  return any;
}

namespace {

std::string roller_element(const CamPicture& cam, const std::vector<const KinPosition*>& frames, const AnimationCanvas& c, double duration) {
  if (!(cam.drawing.roller_radius > 0)) return {};
  std::vector<std::string> cx, cy;
  for (const KinPosition* f : frames) {
    const Eigen::Vector2d p = point_at(f->q, cam.drawing.contact.body, cam.drawing.contact.local);
    cx.push_back(fmt::format("{:.3f}", c.X(p.x())));
    cy.push_back(fmt::format("{:.3f}", c.Y(p.y())));
  }
  std::string svg = fmt::format(
      "<circle cx=\"{}\" cy=\"{}\" r=\"{:.3f}\" fill=\"#f4f4f4\" stroke=\"#333\" stroke-width=\"{:.3f}\"><title>roller {}</title>", cx.front(),
      cy.front(), cam.drawing.roller_radius * c.scale, 0.6 * c.stroke, io::xml_escape(cam.name));
  if (frames.size() > 1)
    svg += fmt::format("<animate attributeName=\"cx\" dur=\"{0:.3f}s\" repeatCount=\"indefinite\" values=\"{1}\"/>"
                       "<animate attributeName=\"cy\" dur=\"{0:.3f}s\" repeatCount=\"indefinite\" values=\"{2}\"/>",
                       duration, fmt::join(cx, ";"), fmt::join(cy, ";"));
  return svg + "</circle>\n";
}

// The flat face as a segment of its line moving with the follower: from face_span's first to its
// second distance along the face from the face's point.
std::string face_element(const CamPicture& cam, const std::vector<const KinPosition*>& frames, const AnimationCanvas& c, double duration) {
  std::vector<std::string> d;
  for (const KinPosition* f : frames) {
    const Eigen::Vector2d P = point_at(f->q, cam.drawing.contact.body, cam.drawing.contact.local);
    const Eigen::Vector2d u = kin::rotate(angle_of(f->q, cam.drawing.face->frame), cam.drawing.face->direction);
    const Eigen::Vector2d a = P + cam.face_span->first * u, b = P + cam.face_span->second * u;
    d.push_back(fmt::format("M{:.3f},{:.3f} L{:.3f},{:.3f}", c.X(a.x()), c.Y(a.y()), c.X(b.x()), c.Y(b.y())));
  }
  std::string svg = fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"#333\" stroke-width=\"{:.3f}\" stroke-linecap=\"butt\"><title>face {}</title>",
                                d.front(), 1.2 * c.stroke, io::xml_escape(cam.name));
  if (frames.size() > 1)
    svg += fmt::format("<animate attributeName=\"d\" dur=\"{:.3f}s\" repeatCount=\"indefinite\" values=\"{}\"/>", duration, fmt::join(d, ";"));
  return svg + "</path>\n";
}

}  // namespace

std::vector<CamPicture> cam_pictures(const kin::Model& model, const std::vector<KinPosition>& positions) {
  std::vector<CamPicture> out;
  for (const auto& mc : model.constraints()) {
    const std::optional<kin::ConstraintDrawing::Cam> cam = mc.constraint->drawing().cam;
    if (!cam || positions.size() < 2) continue;
    CamPicture p;
    p.name = mc.name;
    p.drawing = *cam;
    const double theta0 = angle_of(positions.front().q, cam->cam);
    std::vector<FaceLine> lines;
    for (const KinPosition& f : positions) {
      const double turned = std::abs(angle_of(f.q, cam->cam) - theta0);
      if (turned >= 2.0 * std::numbers::pi - 1e-9) {  // a whole turn: the curve closes
        p.closed = true;
        break;
      }
      p.turned = std::max(p.turned, turned);
      const Eigen::Vector2d origin = point_at(f.q, cam->cam, Eigen::Vector2d::Zero());
      p.pitch.push_back(kin::rotate(-angle_of(f.q, cam->cam), point_at(f.q, cam->contact.body, cam->contact.local) - origin));
      if (cam->face) lines.push_back(face_line(f, *cam));
    }
    const std::optional<kin::BodyPoint> axis = pivot_of(model, cam->cam);
    p.axis = axis ? axis->local : Eigen::Vector2d::Zero();
    double t_min = 0.0, t_max = 0.0;
    p.profile = cam->face ? face_envelope(lines, p.closed, t_min, t_max)
                          : profile_of(p.pitch, p.closed, cam_side(p.pitch, p.axis), cam->roller_radius);
    for (const auto* curve : {&p.pitch, &p.profile})
      for (const Eigen::Vector2d& v : *curve) p.reach = std::max(p.reach, v.norm());
    if (cam->face) p.face_span = {t_min - 0.1 * p.reach, t_max + 0.1 * p.reach};
    out.push_back(std::move(p));
  }
  return out;
}

std::string cam_elements(const std::vector<CamPicture>& cams, const std::vector<const KinPosition*>& frames, const AnimationCanvas& c,
                         double duration) {
  std::string svg;
  for (const CamPicture& cam : cams) {
    if (frames.empty()) continue;
    const int body = cam.drawing.cam;
    std::vector<Eigen::Vector2d> fill = cam.profile;
    if (!cam.closed) fill.insert(fill.begin(), cam.axis);  // the traced sector, closed through the axis
    svg += body_frame_group_open(frames, body, c, "cam " + cam.name);
    svg += fmt::format("<path d=\"{}\" fill=\"#e9dcc0\" stroke=\"none\"/>\n", path_data(fill, c.scale, true));
    svg += fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"#6b4e16\" stroke-width=\"{:.3f}\"><title>cam profile {}</title></path>\n",
                       path_data(cam.profile, c.scale, cam.closed), 0.8 * c.stroke, io::xml_escape(cam.name));
    if (cam.drawing.roller_radius > 0)
      svg += fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"#6b4e16\" stroke-width=\"{:.3f}\" stroke-dasharray=\"{:.3f} {:.3f}\">"
                         "<title>pitch curve {}</title></path>\n",
                         path_data(cam.pitch, c.scale, cam.closed), 0.35 * c.stroke, 2 * c.stroke, 1.2 * c.stroke,
                         io::xml_escape(cam.name));
    svg += body_frame_motion(frames, body, c, duration) + "</g>\n";
    svg += cam.face_span ? face_element(cam, frames, c, duration) : roller_element(cam, frames, c, duration);
  }
  return svg;
}

std::string cam_notes(const std::vector<CamPicture>& cams) {
  std::string text;
  for (const CamPicture& cam : cams)
    if (!cam.closed && cam.drawing.cam != kin::kGround)
      text += fmt::format("{}cam ({}): only the {:.0f} deg the sweep turns it are drawn", text.empty() ? "" : "; ", cam.name,
                          cam.turned * 180.0 / std::numbers::pi);
  return text;
}

}  // namespace gearkit::cli
