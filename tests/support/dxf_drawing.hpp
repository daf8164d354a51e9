#pragma once
// Rebuilds an io::Drawing from a DXF as ezdxf reads it back (tests/gear/dxf_dump.py's JSON), so
// that layout tests check the file a CAD program gets with libio's text-box and curve tests.
#include <gearkit/io/drawing.hpp>
#include <gearkit/io/drawing_annotation.hpp>

#include <nlohmann/json.hpp>

#include <string>

namespace gearkit::testing {

inline io::Drawing drawing_from_dump(const nlohmann::json& dump) {
  io::Drawing d;
  for (const auto& [layer, list] : dump["lines"].items())
    for (const auto& l : list) d.lines.push_back({layer, l[0], l[1], l[2], l[3]});
  for (const auto& [layer, list] : dump["circles"].items())
    for (const auto& c : list) d.circles.push_back({layer, c[0], c[1], c[2]});
  for (const auto& [layer, list] : dump["arcs"].items())
    for (const auto& a : list) d.arcs.push_back({layer, a[0], a[1], a[2], a[3], a[4]});
  for (const auto& [layer, list] : dump["polyline_shapes"].items()) {
    for (const auto& shape : list) {
      io::Polyline p{layer, {}, shape["closed"].get<bool>()};
      for (std::size_t i = 0; i < shape["points"].size(); ++i)
        p.vertices.push_back({shape["points"][i][0], shape["points"][i][1], shape["bulges"][i]});
      d.polylines.push_back(std::move(p));
    }
  }
  for (const auto& [layer, list] : dump["text_at"].items())
    for (std::size_t i = 0; i < list.size(); ++i)
      d.texts.push_back({layer, list[i][1], list[i][2], dump["text_height"][layer][i], list[i][0].get<std::string>()});
  return d;
}

/// "text A overlaps text B" / "curve crosses text A" lines for a failure message; empty when the
/// layout is clean.
inline std::string layout_faults(const io::Drawing& d) {
  std::string out;
  for (const auto& [i, j] : io::overlapping_texts(d)) out += "'" + d.texts[i].text + "' overlaps '" + d.texts[j].text + "'\n";
  for (std::size_t i : io::texts_crossed_by_curves(d)) out += "a curve crosses '" + d.texts[i].text + "'\n";
  return out;
}

}  // namespace gearkit::testing
