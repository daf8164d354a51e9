// DXF writer, AutoCAD 2000 (AC1015). The file carries every section and table that strict readers
// expect of an R2000 file (AutoCAD, ezdxf's audit, CAM post-processors): HEADER, CLASSES, TABLES
// (VPORT, LTYPE, LAYER, STYLE, VIEW, UCS, APPID, DIMSTYLE, BLOCK_RECORD), BLOCKS, ENTITIES and
// OBJECTS (root dictionary, groups, layouts, plot styles, multiline styles), each object with a
// unique handle (group code 5) and its owner (330). The structure follows the DXF reference for
// AutoCAD 2000 and what ezdxf itself writes for a new R2000 document.
#include <gearkit/io/drawing.hpp>

#include "drawing_geometry.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>

namespace gearkit::io {

// The "txt" font of CAD programs advances about 0.86 h per character (measured on LibreCAD 2.2's
// dxf2pdf output: 24 characters of height 9.4 px span 193 px), where the annotation layouts leave
// 0.62 h (drawing_annotation.hpp, as a sans-serif in SVG takes): texts are written narrowed to fit.
constexpr double kTextWidthFactor = 0.72;

// Every TEXT uses one style whose NAME is a LibreCAD font with Greek letters and whose FONT FILE is
// Arial, which AutoCAD, BricsCAD, QCAD and DraftSight all find and which has Greek too. LibreCAD
// picks a TEXT's font by its style name and ignores the style's file (measured on LibreCAD 2.2
// dxf2pdf: style "Standard" with file "txt", "iso3098" or "iso3098.shx" drew alpha as the lozenge
// of standard.lff; style "iso3098" drew it); the other programs go by the file. The "txt" font
// loses the Greek of the gear data block (alpha_n, beta, rho_fP*) and its underscore is a letter
// wide ("m__n"); iso3098.lff has the Greek but no '*'. OpenGOST type B (lettering of GOST 2.304,
// the ISO 3098 type B shapes) has all of them; ctest render.html_and_pdf checks every character
// written against the font file.
constexpr std::string_view kTextStyle = "lc_opengost-br";
constexpr std::string_view kTextFontFile = "arial.ttf";
namespace {

using Handle = std::uint64_t;

/// Group-code/value pairs, one per line, as DXF wants them.
class TagWriter {
 public:
  void tag(int code, std::string_view value) { fmt::format_to(std::back_inserter(out_), "{:>3}\n{}\n", code, value); }
  void tag(int code, int value) { fmt::format_to(std::back_inserter(out_), "{:>3}\n{}\n", code, value); }
  void real(int code, double value) {
    if (!std::isfinite(value)) throw std::invalid_argument("to_dxf: non-finite coordinate in drawing");
    // Shortest text that reads back to the same double: no precision is lost on the way to CAM.
    fmt::format_to(std::back_inserter(out_), "{:>3}\n{}\n", code, value);
  }
  void handle(int code, Handle h) { fmt::format_to(std::back_inserter(out_), "{:>3}\n{:X}\n", code, h); }
  void point(int code, double x, double y) {
    real(code, x);
    real(code + 10, y);
  }
  void point3(int code, double x, double y, double z = 0) {
    point(code, x, y);
    real(code + 20, z);
  }
  const std::string& text() const { return out_; }

 private:
  std::string out_;
};

/// Characters AutoCAD refuses in symbol table names.
std::string layer_name(const std::string& name) {
  if (name.empty()) return "0";
  std::string out;
  for (char c : name) {
    const bool bad = std::string_view("<>/\\\":;?*|=`,").find(c) != std::string_view::npos ||
                     static_cast<unsigned char>(c) < 32;
    out += bad ? '_' : c;
  }
  return out;
}

/// TEXT strings in an ANSI_1252 R2000 file: non-ASCII characters as \U+ and 4 hex digits,
/// no control characters.
std::string dxf_text(std::string_view utf8) {
  std::string out;
  for (std::size_t i = 0; i < utf8.size();) {
    const auto c = static_cast<unsigned char>(utf8[i]);
    if (c < 0x80) {
      out += c < 32 ? ' ' : static_cast<char>(c);
      ++i;
      continue;
    }
    const int extra = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : c >= 0xC0 ? 1 : 0;
    std::uint32_t cp = extra == 3 ? (c & 0x07u) : extra == 2 ? (c & 0x0Fu) : (c & 0x1Fu);
    std::size_t j = i + 1;
    for (int k = 0; k < extra && j < utf8.size(); ++k, ++j) cp = (cp << 6) | (static_cast<unsigned char>(utf8[j]) & 0x3Fu);
    if (extra == 0) cp = '?';
    out += fmt::format("\\U+{:04X}", cp);
    i = j;
  }
  return out;
}

struct LayerStyle {
  int aci_color = 7;
  bool dashed = false;
};

/// The fixed objects every file has, with their handles.
struct Skeleton {
  Handle vport_table, ltype_table, layer_table, style_table, view_table, ucs_table, appid_table,
      dimstyle_table, block_record_table;
  Handle vport_active, ltype_byblock, ltype_bylayer, ltype_continuous, ltype_dashed, style_standard,
      style_text, appid_acad, dimstyle_standard;
  Handle model_record, paper_record, model_block, model_endblk, paper_block, paper_endblk;
  Handle root_dict, group_dict, layout_dict, mlinestyle_dict, plotsettings_dict, plotstylename_dict,
      plotstyle_normal, mlinestyle_standard, model_layout, paper_layout;
};

class DxfDocument {
 public:
  DxfDocument(const Drawing& drawing, const DxfOptions& options) : drawing_(drawing), options_(options) {
    collect_layers();
    allocate_skeleton();
  }

  std::string write() {
    // Entities first: they take handles, and $HANDSEED in the header must exceed all of them.
    TagWriter entities;
    write_entities(entities);
    TagWriter tables;
    write_tables(tables);
    TagWriter blocks;
    write_blocks(blocks);
    TagWriter objects;
    write_objects(objects);

    TagWriter file;
    write_header(file);
    write_classes(file);
    std::string out = file.text();
    out += tables.text();
    out += blocks.text();
    out += entities.text();
    out += objects.text();
    out += "  0\nEOF\n";
    return out;
  }

 private:
  Handle next() { return next_handle_++; }

  void collect_layers() {
    layers_["0"] = LayerStyle{};
    for (const Layer& l : drawing_.layers) layers_[layer_name(l.name)] = LayerStyle{l.aci_color, l.dashed};
    auto add = [&](const std::string& name) { layers_.try_emplace(layer_name(name)); };
    for (const auto& e : drawing_.polylines) add(e.layer);
    for (const auto& e : drawing_.lines) add(e.layer);
    for (const auto& e : drawing_.circles) add(e.layer);
    for (const auto& e : drawing_.arcs) add(e.layer);
    for (const auto& e : drawing_.texts) add(e.layer);
    for (const auto& [name, style] : layers_) layer_handles_[name] = 0;
  }

  void allocate_skeleton() {
    Skeleton& s = sk_;
    for (Handle* h : {&s.vport_table, &s.ltype_table, &s.layer_table, &s.style_table, &s.view_table, &s.ucs_table,
                      &s.appid_table, &s.dimstyle_table, &s.block_record_table, &s.vport_active, &s.ltype_byblock,
                      &s.ltype_bylayer, &s.ltype_continuous, &s.ltype_dashed, &s.style_standard, &s.style_text, &s.appid_acad,
                      &s.dimstyle_standard, &s.model_record, &s.paper_record, &s.model_block, &s.model_endblk,
                      &s.paper_block, &s.paper_endblk, &s.root_dict, &s.group_dict, &s.layout_dict,
                      &s.mlinestyle_dict, &s.plotsettings_dict, &s.plotstylename_dict, &s.plotstyle_normal,
                      &s.mlinestyle_standard, &s.model_layout, &s.paper_layout})
      *h = next();
    for (auto& [name, h] : layer_handles_) h = next();
  }

  // ---- HEADER and CLASSES ------------------------------------------------------------------

  void write_header(TagWriter& w) const {
    const Extents e = extents_.empty() ? Extents{0, 0, 100, 100} : extents_;
    w.tag(0, "SECTION");
    w.tag(2, "HEADER");
    auto var = [&](std::string_view name) { w.tag(9, name); };
    var("$ACADVER"); w.tag(1, "AC1015");
    var("$ACADMAINTVER"); w.tag(70, 6);
    var("$DWGCODEPAGE"); w.tag(3, "ANSI_1252");
    var("$INSBASE"); w.point3(10, 0, 0);
    var("$EXTMIN"); w.point3(10, e.xmin, e.ymin);
    var("$EXTMAX"); w.point3(10, e.xmax, e.ymax);
    var("$LIMMIN"); w.point(10, 0, 0);
    var("$LIMMAX"); w.point(10, 420, 297);
    var("$LTSCALE"); w.real(40, 1);
    var("$TEXTSTYLE"); w.tag(7, "Standard");
    var("$CLAYER"); w.tag(8, "0");
    var("$CELTYPE"); w.tag(6, "ByLayer");
    var("$CECOLOR"); w.tag(62, 256);
    var("$DIMSTYLE"); w.tag(2, "Standard");
    var("$LUNITS"); w.tag(70, 2);
    var("$LUPREC"); w.tag(70, 4);
    var("$AUNITS"); w.tag(70, 0);
    var("$AUPREC"); w.tag(70, 2);
    var("$ANGBASE"); w.real(50, 0);
    var("$ANGDIR"); w.tag(70, 0);
    var("$HANDSEED"); w.handle(5, next_handle_);
    var("$TILEMODE"); w.tag(70, 1);
    var("$PLIMMIN"); w.point(10, 0, 0);
    var("$PLIMMAX"); w.point(10, 420, 297);
    var("$CMLSTYLE"); w.tag(2, "Standard");
    var("$MEASUREMENT"); w.tag(70, 1);  // metric
    var("$INSUNITS"); w.tag(70, 4);     // millimetres
    var("$PSTYLEMODE"); w.tag(290, 1);
    w.tag(0, "ENDSEC");
  }

  static void write_classes(TagWriter& w) {
    // Classes of the non-R12 objects used in OBJECTS (names and flags as AutoCAD 2000 writes them).
    w.tag(0, "SECTION");
    w.tag(2, "CLASSES");
    auto cls = [&](std::string_view dxf, std::string_view cpp, int flags) {
      w.tag(0, "CLASS");
      w.tag(1, dxf);
      w.tag(2, cpp);
      w.tag(3, "ObjectDBX Classes");
      w.tag(90, flags);
      w.tag(280, 0);
      w.tag(281, 0);
    };
    cls("ACDBDICTIONARYWDFLT", "AcDbDictionaryWithDefault", 0);
    cls("ACDBPLACEHOLDER", "AcDbPlaceHolder", 0);
    cls("LAYOUT", "AcDbLayout", 0);
    w.tag(0, "ENDSEC");
  }

  // ---- TABLES ------------------------------------------------------------------------------

  void table_begin(TagWriter& w, std::string_view name, Handle h, int count) const {
    w.tag(0, "TABLE");
    w.tag(2, name);
    w.handle(5, h);
    w.handle(330, 0);
    w.tag(100, "AcDbSymbolTable");
    w.tag(70, count);
  }

  static void record_begin(TagWriter& w, std::string_view type, Handle h, Handle table, std::string_view subclass,
                           std::string_view name, int handle_code = 5) {
    w.tag(0, type);
    w.handle(handle_code, h);
    w.handle(330, table);
    w.tag(100, "AcDbSymbolTableRecord");
    w.tag(100, subclass);
    w.tag(2, name);
    w.tag(70, 0);
  }

  void write_tables(TagWriter& w) const {
    w.tag(0, "SECTION");
    w.tag(2, "TABLES");
    write_vport_table(w);
    write_ltype_table(w);
    write_layer_table(w);
    write_style_table(w);
    table_begin(w, "VIEW", sk_.view_table, 0);
    w.tag(0, "ENDTAB");
    table_begin(w, "UCS", sk_.ucs_table, 0);
    w.tag(0, "ENDTAB");
    table_begin(w, "APPID", sk_.appid_table, 1);
    record_begin(w, "APPID", sk_.appid_acad, sk_.appid_table, "AcDbRegAppTableRecord", "ACAD");
    w.tag(0, "ENDTAB");
    write_dimstyle_table(w);
    write_block_record_table(w);
    w.tag(0, "ENDSEC");
  }

  void write_vport_table(TagWriter& w) const {
    const Extents e = extents_.empty() ? Extents{0, 0, 100, 100} : extents_;
    table_begin(w, "VPORT", sk_.vport_table, 1);
    record_begin(w, "VPORT", sk_.vport_active, sk_.vport_table, "AcDbViewportTableRecord", "*Active");
    w.point(10, 0, 0);
    w.point(11, 1, 1);
    w.point(12, 0.5 * (e.xmin + e.xmax), 0.5 * (e.ymin + e.ymax));  // view centre: the drawing
    w.point(13, 0, 0);
    w.point(14, 10, 10);
    w.point(15, 10, 10);
    w.point3(16, 0, 0, 1);
    w.point3(17, 0, 0, 0);
    w.real(40, 1.1 * std::max(e.ymax - e.ymin, (e.xmax - e.xmin) / 1.34));  // view height
    w.real(41, 1.34);
    w.real(42, 50);
    w.real(43, 0);
    w.real(44, 0);
    w.real(50, 0);
    w.real(51, 0);
    w.tag(71, 0);
    w.tag(72, 100);
    w.tag(73, 1);
    w.tag(74, 3);
    w.tag(75, 0);
    w.tag(76, 0);
    w.tag(77, 0);
    w.tag(78, 0);
    w.tag(281, 0);
    w.tag(65, 1);
    w.point3(110, 0, 0, 0);
    w.point3(111, 1, 0, 0);
    w.point3(112, 0, 1, 0);
    w.tag(79, 0);
    w.real(146, 0);
    w.tag(0, "ENDTAB");
  }

  void write_ltype_table(TagWriter& w) const {
    table_begin(w, "LTYPE", sk_.ltype_table, 4);
    auto solid = [&](Handle h, std::string_view name, std::string_view description) {
      record_begin(w, "LTYPE", h, sk_.ltype_table, "AcDbLinetypeTableRecord", name);
      w.tag(3, description);
      w.tag(72, 65);
      w.tag(73, 0);
      w.real(40, 0);
    };
    solid(sk_.ltype_byblock, "ByBlock", "");
    solid(sk_.ltype_bylayer, "ByLayer", "");
    solid(sk_.ltype_continuous, "Continuous", "Solid line");
    // ISO dashed line: 5 mm dash, 2.5 mm gap (pattern elements as R2000 writes them: 49 + 74).
    record_begin(w, "LTYPE", sk_.ltype_dashed, sk_.ltype_table, "AcDbLinetypeTableRecord", "DASHED");
    w.tag(3, "Dashed __ __ __ __");
    w.tag(72, 65);
    w.tag(73, 2);
    w.real(40, 7.5);
    w.real(49, 5);
    w.tag(74, 0);
    w.real(49, -2.5);
    w.tag(74, 0);
    w.tag(0, "ENDTAB");
  }

  void write_layer_table(TagWriter& w) const {
    table_begin(w, "LAYER", sk_.layer_table, static_cast<int>(layers_.size()));
    for (const auto& [name, style] : layers_) {
      record_begin(w, "LAYER", layer_handles_.at(name), sk_.layer_table, "AcDbLayerTableRecord", name);
      const int color = style.aci_color >= 1 && style.aci_color <= 255 ? style.aci_color : 7;
      w.tag(62, color);
      w.tag(6, style.dashed ? "DASHED" : "Continuous");
      w.tag(370, -3);                       // lineweight: default
      w.handle(390, sk_.plotstyle_normal);  // plot style "Normal"
    }
    w.tag(0, "ENDTAB");
  }

  void write_style_table(TagWriter& w) const {
    table_begin(w, "STYLE", sk_.style_table, 2);
    write_style(w, sk_.style_standard, "Standard", "txt");
    write_style(w, sk_.style_text, kTextStyle, kTextFontFile);
    w.tag(0, "ENDTAB");
  }

  void write_style(TagWriter& w, Handle h, std::string_view name, std::string_view font_file) const {
    record_begin(w, "STYLE", h, sk_.style_table, "AcDbTextStyleTableRecord", name);
    w.real(40, 0);
    w.real(41, kTextWidthFactor);
    w.real(50, 0);
    w.tag(71, 0);
    w.real(42, 2.5);
    w.tag(3, font_file);
    w.tag(4, "");
  }

  void write_dimstyle_table(TagWriter& w) const {
    table_begin(w, "DIMSTYLE", sk_.dimstyle_table, 1);
    w.tag(100, "AcDbDimStyleTable");
    // DIMSTYLE records carry their handle in group 105, not 5.
    record_begin(w, "DIMSTYLE", sk_.dimstyle_standard, sk_.dimstyle_table, "AcDbDimStyleTableRecord", "Standard",
                 105);
    // ISO-25 metric dimensioning values.
    w.real(40, 1);
    w.real(41, 2.5);
    w.real(42, 0.625);
    w.real(43, 3.75);
    w.real(44, 1.25);
    w.real(140, 2.5);
    w.real(141, 2.5);
    w.real(147, 0.625);
    w.tag(77, 1);
    w.tag(78, 8);
    w.tag(271, 2);
    w.tag(272, 2);
    w.handle(340, sk_.style_standard);
    w.tag(0, "ENDTAB");
  }

  void write_block_record_table(TagWriter& w) const {
    table_begin(w, "BLOCK_RECORD", sk_.block_record_table, 2);
    auto record = [&](Handle h, std::string_view name, Handle layout) {
      w.tag(0, "BLOCK_RECORD");
      w.handle(5, h);
      w.handle(330, sk_.block_record_table);
      w.tag(100, "AcDbSymbolTableRecord");
      w.tag(100, "AcDbBlockTableRecord");
      w.tag(2, name);
      w.handle(340, layout);
    };
    record(sk_.model_record, "*Model_Space", sk_.model_layout);
    record(sk_.paper_record, "*Paper_Space", sk_.paper_layout);
    w.tag(0, "ENDTAB");
  }

  // ---- BLOCKS ------------------------------------------------------------------------------

  void write_blocks(TagWriter& w) const {
    w.tag(0, "SECTION");
    w.tag(2, "BLOCKS");
    auto block = [&](Handle begin, Handle end, Handle record, std::string_view name, bool paper) {
      w.tag(0, "BLOCK");
      w.handle(5, begin);
      w.handle(330, record);
      w.tag(100, "AcDbEntity");
      if (paper) w.tag(67, 1);
      w.tag(8, "0");
      w.tag(100, "AcDbBlockBegin");
      w.tag(2, name);
      w.tag(70, 0);
      w.point3(10, 0, 0);
      w.tag(3, name);
      w.tag(1, "");
      w.tag(0, "ENDBLK");
      w.handle(5, end);
      w.handle(330, record);
      w.tag(100, "AcDbEntity");
      if (paper) w.tag(67, 1);
      w.tag(8, "0");
      w.tag(100, "AcDbBlockEnd");
    };
    block(sk_.model_block, sk_.model_endblk, sk_.model_record, "*Model_Space", false);
    block(sk_.paper_block, sk_.paper_endblk, sk_.paper_record, "*Paper_Space", true);
    w.tag(0, "ENDSEC");
  }

  // ---- ENTITIES ----------------------------------------------------------------------------

  void entity_begin(TagWriter& w, std::string_view type, const std::string& layer) {
    w.tag(0, type);
    w.handle(5, next());
    w.handle(330, sk_.model_record);
    w.tag(100, "AcDbEntity");
    w.tag(8, layer_name(layer));
  }

  void write_line(TagWriter& w, const std::string& layer, double x1, double y1, double x2, double y2) {
    entity_begin(w, "LINE", layer);
    w.tag(100, "AcDbLine");
    w.point3(10, x1, y1);
    w.point3(11, x2, y2);
    extents_.add(x1, y1);
    extents_.add(x2, y2);
  }

  void write_arc(TagWriter& w, const Arc& a) {
    entity_begin(w, "ARC", a.layer);
    w.tag(100, "AcDbCircle");
    w.point3(10, a.cx, a.cy);
    w.real(40, a.r);
    w.tag(100, "AcDbArc");
    w.real(50, a.start_deg);
    w.real(51, a.end_deg);
    extents_.add_arc(a);
  }

  void write_circle(TagWriter& w, const Circle& c) {
    entity_begin(w, "CIRCLE", c.layer);
    w.tag(100, "AcDbCircle");
    w.point3(10, c.cx, c.cy);
    w.real(40, c.r);
    extents_.add(c.cx - c.r, c.cy - c.r);
    extents_.add(c.cx + c.r, c.cy + c.r);
  }

  void write_lwpolyline(TagWriter& w, const Polyline& p) {
    entity_begin(w, "LWPOLYLINE", p.layer);
    w.tag(100, "AcDbPolyline");
    w.tag(90, static_cast<int>(p.vertices.size()));
    w.tag(70, p.closed ? 1 : 0);
    w.real(43, 0);  // constant width 0: a plain curve for CAM
    for (const Vertex& v : p.vertices) {
      w.point(10, v.x, v.y);
      if (v.bulge != 0) w.real(42, v.bulge);
    }
    for_each_segment(p, [&](const Vertex& a, const Vertex& b) { extents_.add_segment(a, b); });
    for (const Vertex& v : p.vertices) extents_.add(v.x, v.y);
  }

  /// A polyline as separate LINE and ARC entities (for readers that predate LWPOLYLINE).
  void write_polyline_as_lines_and_arcs(TagWriter& w, const Polyline& p) {
    for_each_segment(p, [&](const Vertex& a, const Vertex& b) {
      if (a.bulge == 0 || (a.x == b.x && a.y == b.y)) {
        if (a.x != b.x || a.y != b.y) write_line(w, p.layer, a.x, a.y, b.x, b.y);
        return;
      }
      Arc arc = arc_of_bulge(a, b);
      arc.layer = p.layer;
      write_arc(w, arc);
    });
  }

  void write_text(TagWriter& w, const Text& t) {
    entity_begin(w, "TEXT", t.layer);
    w.tag(100, "AcDbText");
    w.point3(10, t.x, t.y);
    w.real(40, t.height > 0 ? t.height : 2.5);
    w.tag(1, dxf_text(t.text));
    w.real(41, kTextWidthFactor);
    w.tag(7, kTextStyle);
    w.tag(100, "AcDbText");
    extents_.add(t.x, t.y);
  }

  void write_entities(TagWriter& w) {
    w.tag(0, "SECTION");
    w.tag(2, "ENTITIES");
    for (const Polyline& p : drawing_.polylines) {
      if (p.vertices.empty()) continue;
      if (options_.lines_and_arcs_only)
        write_polyline_as_lines_and_arcs(w, p);
      else
        write_lwpolyline(w, p);
    }
    for (const Line& l : drawing_.lines) write_line(w, l.layer, l.x1, l.y1, l.x2, l.y2);
    for (const Circle& c : drawing_.circles) write_circle(w, c);
    for (const Arc& a : drawing_.arcs) write_arc(w, a);
    for (const Text& t : drawing_.texts) write_text(w, t);
    w.tag(0, "ENDSEC");
  }

  // ---- OBJECTS -----------------------------------------------------------------------------

  static void dictionary_begin(TagWriter& w, Handle h, Handle owner) {
    w.tag(0, "DICTIONARY");
    w.handle(5, h);
    w.handle(330, owner);
    w.tag(100, "AcDbDictionary");
    w.tag(281, 1);
  }

  static void entry(TagWriter& w, std::string_view name, Handle h) {
    w.tag(3, name);
    w.handle(350, h);
  }

  void write_layout(TagWriter& w, Handle h, std::string_view name, int tab_order, Handle block_record,
                    bool model) const {
    w.tag(0, "LAYOUT");
    w.handle(5, h);
    w.handle(330, sk_.layout_dict);
    w.tag(100, "AcDbPlotSettings");
    w.tag(1, "");
    w.tag(2, "none_device");
    w.tag(4, "ISO_A3_(420.00_x_297.00_MM)");
    w.tag(6, "");
    for (int code : {40, 41, 42, 43}) w.real(code, 7.5);
    w.real(44, 420);
    w.real(45, 297);
    for (int code : {46, 47, 48, 49, 140, 141}) w.real(code, 0);
    w.real(142, 1);
    w.real(143, 1);
    w.tag(70, model ? 1024 : 0);
    w.tag(72, 1);  // paper units: millimetres
    w.tag(73, 0);
    w.tag(74, 5);
    w.tag(7, "");
    w.tag(75, 16);
    w.real(147, 1);
    w.real(148, 0);
    w.real(149, 0);
    w.tag(100, "AcDbLayout");
    w.tag(1, name);
    w.tag(70, 1);
    w.tag(71, tab_order);
    w.point(10, 0, 0);
    w.point(11, 420, 297);
    w.point3(12, 0, 0);
    w.point3(14, 0, 0);
    w.point3(15, 0, 0);
    w.real(146, 0);
    w.point3(13, 0, 0);
    w.point3(16, 1, 0);
    w.point3(17, 0, 1);
    w.tag(76, 0);
    w.handle(330, block_record);
  }

  void write_objects(TagWriter& w) const {
    w.tag(0, "SECTION");
    w.tag(2, "OBJECTS");
    dictionary_begin(w, sk_.root_dict, 0);
    entry(w, "ACAD_GROUP", sk_.group_dict);
    entry(w, "ACAD_LAYOUT", sk_.layout_dict);
    entry(w, "ACAD_MLINESTYLE", sk_.mlinestyle_dict);
    entry(w, "ACAD_PLOTSETTINGS", sk_.plotsettings_dict);
    entry(w, "ACAD_PLOTSTYLENAME", sk_.plotstylename_dict);
    dictionary_begin(w, sk_.group_dict, sk_.root_dict);
    dictionary_begin(w, sk_.layout_dict, sk_.root_dict);
    entry(w, "Model", sk_.model_layout);
    entry(w, "Layout1", sk_.paper_layout);
    dictionary_begin(w, sk_.mlinestyle_dict, sk_.root_dict);
    entry(w, "Standard", sk_.mlinestyle_standard);
    dictionary_begin(w, sk_.plotsettings_dict, sk_.root_dict);

    w.tag(0, "ACDBDICTIONARYWDFLT");
    w.handle(5, sk_.plotstylename_dict);
    w.handle(330, sk_.root_dict);
    w.tag(100, "AcDbDictionary");
    w.tag(281, 1);
    entry(w, "Normal", sk_.plotstyle_normal);
    w.tag(100, "AcDbDictionaryWithDefault");
    w.handle(340, sk_.plotstyle_normal);

    w.tag(0, "ACDBPLACEHOLDER");
    w.handle(5, sk_.plotstyle_normal);
    w.handle(330, sk_.plotstylename_dict);

    w.tag(0, "MLINESTYLE");
    w.handle(5, sk_.mlinestyle_standard);
    w.tag(102, "{ACAD_REACTORS");
    w.handle(330, sk_.mlinestyle_dict);
    w.tag(102, "}");
    w.handle(330, sk_.mlinestyle_dict);
    w.tag(100, "AcDbMlineStyle");
    w.tag(2, "Standard");
    w.tag(70, 0);
    w.tag(3, "");
    w.tag(62, 256);
    w.real(51, 90);
    w.real(52, 90);
    w.tag(71, 2);
    w.real(49, 0.5);
    w.tag(62, 256);
    w.tag(6, "BYLAYER");
    w.real(49, -0.5);
    w.tag(62, 256);
    w.tag(6, "BYLAYER");

    write_layout(w, sk_.model_layout, "Model", 0, sk_.model_record, true);
    write_layout(w, sk_.paper_layout, "Layout1", 1, sk_.paper_record, false);
    w.tag(0, "ENDSEC");
  }

  const Drawing& drawing_;
  DxfOptions options_;
  std::map<std::string, LayerStyle> layers_;
  std::map<std::string, Handle> layer_handles_;
  Skeleton sk_{};
  Handle next_handle_ = 0x20;  // low handles stay free, as AutoCAD's own files leave them
  Extents extents_;
};

}  // namespace

std::string to_dxf(const Drawing& drawing, const DxfOptions& options) {
  return DxfDocument(drawing, options).write();
}

}  // namespace gearkit::io
