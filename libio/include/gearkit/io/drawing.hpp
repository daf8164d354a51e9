#pragma once
// A small 2-D drawing model in millimetres, written as DXF (AutoCAD 2000, for CAD/CAM) or SVG
// (for browsers). Gear tooth forms, cam profiles and mechanism sketches all go through it, so
// there is one DXF writer and one SVG writer in the project.
#include <string>
#include <vector>

namespace gearkit::io {

/// A polyline vertex. `bulge` describes the segment that starts here (DXF convention):
/// tan(theta/4) of the arc's included angle theta, positive counter-clockwise; 0 = straight.
struct Vertex {
  double x = 0, y = 0;
  double bulge = 0;
};

struct Polyline {
  std::string layer;
  std::vector<Vertex> vertices;
  bool closed = false;
};

struct Line {
  std::string layer;
  double x1 = 0, y1 = 0, x2 = 0, y2 = 0;
};

struct Circle {
  std::string layer;
  double cx = 0, cy = 0, r = 0;
};

/// Counter-clockwise arc from start_deg to end_deg.
struct Arc {
  std::string layer;
  double cx = 0, cy = 0, r = 0;
  double start_deg = 0, end_deg = 0;
};

struct Text {
  std::string layer;
  double x = 0, y = 0;
  double height = 3.5;
  std::string text;
};

struct Layer {
  std::string name;
  int aci_color = 7;              ///< AutoCAD colour index (7 = black/white)
  std::string svg_color = "#000"; ///< stroke colour in SVG
  bool dashed = false;
};

struct Drawing {
  std::vector<Layer> layers;  ///< entities on a layer not listed here get default style
  std::vector<Polyline> polylines;
  std::vector<Line> lines;
  std::vector<Circle> circles;
  std::vector<Arc> arcs;
  std::vector<Text> texts;
};

struct DxfOptions {
  /// Write LINE and ARC entities instead of LWPOLYLINE, for old readers.
  bool lines_and_arcs_only = false;
};

/// DXF text, AutoCAD 2000 (AC1015), $INSUNITS = 4 (mm), with handles and owner pointers so
/// that strict readers (ezdxf audit, CAD/CAM programs) accept it.
std::string to_dxf(const Drawing& drawing, const DxfOptions& options = {});

struct SvgOptions {
  double margin_mm = 5;
  double stroke_mm = 0.25;
  std::string title;
};

/// SVG text with a viewBox in millimetres, y pointing up (as in the drawing), one <g> per layer.
std::string to_svg(const Drawing& drawing, const SvgOptions& options = {});

}  // namespace gearkit::io
