// G-code (RS-274/NGC) of the cutter-centre path: arcs G2/G3 on a 2-axis mill, or the angle-radius
// form for a rotary table (the table turns the cam, the cutter moves along X).
#include "cam_gcode.hpp"

#include "cam_text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gearkit::plugins::cam {

namespace gc = gearkit::cam;

namespace {

constexpr double pi = std::numbers::pi;

/// Decimals: at least 1 um / 1e-6 deg (arc end radii then agree to 2e-6 mm, as controllers
/// check), and rounding never moves a coordinate by more than a twentieth of the tolerance.
int decimals_for(double tolerance) {
  return std::clamp(static_cast<int>(std::ceil(-std::log10(tolerance / 20))), 6, 9);
}

struct Writer {
  int digits;
  std::string out;

  std::string num(double v) const {
    std::string s = fmt::format("{:.{}f}", v, digits);
    if (s.find('.') != std::string::npos) {
      while (s.back() == '0') s.pop_back();
      if (s.back() == '.') s += '0';
    }
    return s == "-0.0" ? "0.0" : s;
  }
  void line(const std::string& text) { out += text + "\n"; }
};

/// One closed loop in XY: a rapid to its start, then G1 for lines and G2/G3 for arcs (I, J: the
/// centre from the arc's start, RS-274/NGC's default incremental arc-centre mode).
void loop_xy(Writer& w, const std::vector<gc::Piece>& loop) {
  const std::vector<gc::Piece> pieces = gc::merge_pieces(loop);
  if (pieces.empty()) return;
  w.line(fmt::format("G0 X{} Y{}", w.num(pieces.front().x0), w.num(pieces.front().y0)));
  for (const gc::Piece& p : pieces) {
    if (!p.is_arc()) {
      w.line(fmt::format("G1 X{} Y{}", w.num(p.x1), w.num(p.y1)));
      continue;
    }
    w.line(fmt::format("{} X{} Y{} I{} J{}", p.sweep < 0 ? "G2" : "G3", w.num(p.x1), w.num(p.y1), w.num(p.cx - p.x0),
                       w.num(p.cy - p.y0)));
  }
}

/// One closed loop as G1 X<radius> C<table angle>: the table turns the cam by C = -phi (deg) to
/// bring the path's point at polar angle phi onto the +X axis, where the cutter stands.
void loop_polar(Writer& w, const std::vector<gc::Piece>& loop, double tol) {
  const std::vector<gc::PolarPoint> pts = gc::polar_moves(gc::merge_pieces(loop), tol);
  if (pts.empty()) return;
  w.line(fmt::format("G0 X{} C{}", w.num(pts.front().r), w.num(-deg(pts.front().phi))));
  for (std::size_t i = 1; i < pts.size(); ++i) w.line(fmt::format("G1 X{} C{}", w.num(pts[i].r), w.num(-deg(pts[i].phi))));
}

/// Text for an RS-274 comment, which ends at the first ')' and may not nest '('.
std::string comment_text(std::string s) {
  for (char& c : s)
    if (c == '(' || c == ')') c = c == '(' ? '[' : ']';
    else if (c == '\n' || c == '\r') c = ' ';
  return s;
}

void header(Writer& w, const CamModel& model, const GcodeOptions& o, const std::string& file) {
  w.line("%");
  w.line(fmt::format("(gearkit cam: {})", comment_text(model.name.empty() ? file : model.name)));
  w.line(fmt::format("(cutter-centre path of a {} mm cutter, fit tolerance {} mm)", w.num(*model.cutter_radius_mm),
                     fmt::format("{:.6g}", model.tolerance_mm)));
  if (o.polar) {
    w.line("(rotary table: X = cutter centre's distance from the table axis, C = table angle in deg;)");
    w.line("(the table turns the cam by C to bring each point onto +X; moves are linear in X and C)");
  } else {
    w.line("(2-axis mill: cam centre at X0 Y0, cam at angle 0 as in the DXF; arcs G2/G3 with centre I J from the start)");
  }
  w.line("(units mm, absolute coordinates; set the depth and start the spindle before running)");
  w.line(o.polar ? "G21 G90 G94 G40" : "G21 G90 G17 G94 G40");
  w.line(fmt::format("F{}", w.num(o.feed_mm_min)));
}

}  // namespace

std::string cam_gcode(const CamModel& model, const CamResult& r, const GcodeOptions& o, const std::string& file) {
  Writer w{decimals_for(model.tolerance_mm), {}};
  header(w, model, o, file);
  auto contour = [&](const std::vector<std::vector<gc::Piece>>& loops, const std::string& what) {
    for (const auto& loop : loops) {
      w.line(fmt::format("({})", what));
      if (o.polar)
        loop_polar(w, loop, model.tolerance_mm);
      else
        loop_xy(w, loop);
    }
  };
  const bool groove = !r.profile.outer_tool_path.empty();
  contour(r.profile.tool_path, groove ? "inner wall of the groove" : "profile");
  if (groove) contour(r.profile.outer_tool_path, "outer wall of the groove");
  if (r.second_profile) {
    w.line("M0 (mount the conjugate cam's plate, then resume)");
    contour(r.second_profile->tool_path, "conjugate cam");
  }
  w.line("M2");
  w.line("%");
  return w.out;
}

}  // namespace gearkit::plugins::cam
