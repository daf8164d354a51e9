// Tests of gearkit/io/drawing.hpp: the DXF (AutoCAD 2000) and SVG writers.
// The DXF structure is checked twice: by a small tag reader here (handles, owners, header) and by
// ezdxf's audit (an independent reader, run through tests/io/ezdxf_check.py with Debian's python3).
#include <gearkit/io/drawing.hpp>

#include <gtest/gtest.h>

#include <unistd.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace gearkit::io;

struct Tag {
  int code;
  std::string value;
};

std::vector<Tag> read_tags(const std::string& dxf) {
  std::istringstream in(dxf);
  std::vector<Tag> tags;
  std::string code, value;
  while (std::getline(in, code) && std::getline(in, value)) tags.push_back({std::stoi(code), value});
  return tags;
}

/// Entities of one type as lists of tags (from their 0-tag up to the next 0-tag).
std::vector<std::vector<Tag>> entities_of(const std::vector<Tag>& tags, const std::string& type) {
  std::vector<std::vector<Tag>> out;
  for (std::size_t i = 0; i < tags.size(); ++i) {
    if (tags[i].code != 0 || tags[i].value != type) continue;
    std::vector<Tag> e;
    for (std::size_t j = i + 1; j < tags.size() && tags[j].code != 0; ++j) e.push_back(tags[j]);
    out.push_back(e);
  }
  return out;
}

std::vector<double> reals(const std::vector<Tag>& entity, int code) {
  std::vector<double> out;
  for (const Tag& t : entity)
    if (t.code == code) out.push_back(std::stod(t.value));
  return out;
}

std::string header_value(const std::vector<Tag>& tags, const std::string& name) {
  for (std::size_t i = 0; i + 1 < tags.size(); ++i)
    if (tags[i].code == 9 && tags[i].value == name) return tags[i + 1].value;
  return "";
}

Drawing sample_drawing() {
  Drawing d;
  d.layers = {{"profile", 1, "#c00", false}, {"pitch_curve", 5, "#00c", true}};
  // A square with one counter-clockwise and one clockwise bulge arc.
  d.polylines.push_back({"profile", {{0, 0, 0.5}, {10, 0, 0}, {10, 10, -1}, {0, 10, 0}}, true});
  d.lines.push_back({"misc", 0, 0, 5, 5});
  d.circles.push_back({"pitch_curve", 0, 0, 20});
  d.arcs.push_back({"pitch_curve", 0, 0, 15, 350, 30});
  d.texts.push_back({"text", 1, 1, 3.5, "Leva \xce\xb8 = 30\xc2\xb0"});
  return d;
}

std::filesystem::path scratch_dir() {
  // One folder per process: ctest runs several test processes at once.
  auto dir = std::filesystem::path(GEARKIT_BINARY_DIR) / "test-scratch" / ("io-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

/// Runs tests/io/ezdxf_check.py on `file` and returns its JSON verdict.
nlohmann::json ezdxf_check(const std::filesystem::path& file, const std::string& extra = "") {
  const std::string command = std::string("/usr/bin/python3 ") + GEARKIT_SOURCE_DIR + "/tests/io/ezdxf_check.py '" +
                              file.string() + "' " + extra + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return {{"read_error", "cannot run python3"}};
  std::string output;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
  pclose(pipe);
  try {
    return nlohmann::json::parse(output.substr(output.rfind("\n{") == std::string::npos ? 0 : output.rfind("\n{") + 1));
  } catch (const nlohmann::json::exception&) {
    return {{"read_error", output}};
  }
}

TEST(DrawingDxf, HeaderDeclaresAutoCad2000InMillimetres) {
  const auto tags = read_tags(to_dxf(sample_drawing()));
  EXPECT_EQ(header_value(tags, "$ACADVER"), "AC1015");
  EXPECT_EQ(header_value(tags, "$INSUNITS"), "4");  // DXF reference: 4 = millimetres
  EXPECT_EQ(header_value(tags, "$MEASUREMENT"), "1");
  ASSERT_FALSE(tags.empty());
  EXPECT_EQ(tags.back().code, 0);
  EXPECT_EQ(tags.back().value, "EOF");
}

TEST(DrawingDxf, SectionsComeInTheR2000Order) {
  const auto tags = read_tags(to_dxf(sample_drawing()));
  std::vector<std::string> sections;
  for (std::size_t i = 0; i + 1 < tags.size(); ++i)
    if (tags[i].code == 0 && tags[i].value == "SECTION") sections.push_back(tags[i + 1].value);
  EXPECT_EQ(sections, (std::vector<std::string>{"HEADER", "CLASSES", "TABLES", "BLOCKS", "ENTITIES", "OBJECTS"}));
  std::vector<std::string> tables;
  for (std::size_t i = 0; i + 1 < tags.size(); ++i)
    if (tags[i].code == 0 && tags[i].value == "TABLE") tables.push_back(tags[i + 1].value);
  EXPECT_EQ(tables, (std::vector<std::string>{"VPORT", "LTYPE", "LAYER", "STYLE", "VIEW", "UCS", "APPID", "DIMSTYLE",
                                              "BLOCK_RECORD"}));
}

TEST(DrawingDxf, HandlesAreUniqueOwnersExistAndHandseedIsAboveAll) {
  const auto tags = read_tags(to_dxf(sample_drawing()));
  std::set<unsigned long> handles;
  bool in_header = true;
  for (const Tag& t : tags) {
    if (t.code == 0 && t.value == "ENDSEC") in_header = false;
    if (!in_header && (t.code == 5 || t.code == 105)) {
      const unsigned long h = std::stoul(t.value, nullptr, 16);
      EXPECT_TRUE(handles.insert(h).second) << "duplicate handle " << t.value;
    }
  }
  ASSERT_FALSE(handles.empty());
  for (const Tag& t : tags) {
    if (t.code == 330 || t.code == 340 || t.code == 350 || t.code == 390) {
      const unsigned long h = std::stoul(t.value, nullptr, 16);
      EXPECT_TRUE(h == 0 || handles.count(h)) << "dangling pointer " << t.code << " -> " << t.value;
    }
  }
  EXPECT_GT(std::stoul(header_value(tags, "$HANDSEED"), nullptr, 16), *handles.rbegin());
}

TEST(DrawingDxf, LayersAndLinetypesAreDeclared) {
  const auto tags = read_tags(to_dxf(sample_drawing()));
  std::map<std::string, std::pair<std::string, std::string>> layers;  // name -> (colour, linetype)
  for (const auto& layer : entities_of(tags, "LAYER")) {
    std::string name, color, ltype;
    for (const Tag& t : layer) {
      if (t.code == 2) name = t.value;
      if (t.code == 62) color = t.value;
      if (t.code == 6) ltype = t.value;
    }
    layers[name] = {color, ltype};
  }
  // Declared layers keep their style; layers only used by entities get the default one.
  EXPECT_EQ(layers["profile"], std::make_pair(std::string("1"), std::string("Continuous")));
  EXPECT_EQ(layers["pitch_curve"], std::make_pair(std::string("5"), std::string("DASHED")));
  EXPECT_EQ(layers["misc"], std::make_pair(std::string("7"), std::string("Continuous")));
  EXPECT_TRUE(layers.count("0"));
  std::set<std::string> ltypes;
  for (const auto& lt : entities_of(tags, "LTYPE"))
    for (const Tag& t : lt)
      if (t.code == 2) ltypes.insert(t.value);
  EXPECT_TRUE(ltypes.count("Continuous"));
  EXPECT_TRUE(ltypes.count("DASHED"));
}

TEST(DrawingDxf, PolylineKeepsVerticesAndBulgesExactly) {
  Drawing d;
  d.polylines.push_back({"profile", {{0.1, 0.2, 0}, {1.0 / 3, 2.0 / 7, 0.4142135623730951}, {5, 6, 0}}, true});
  const auto polylines = entities_of(read_tags(to_dxf(d)), "LWPOLYLINE");
  ASSERT_EQ(polylines.size(), 1u);
  const auto& p = polylines[0];
  EXPECT_EQ(reals(p, 90), std::vector<double>{3});
  EXPECT_EQ(reals(p, 70), std::vector<double>{1});  // closed
  EXPECT_EQ(reals(p, 10), (std::vector<double>{0.1, 1.0 / 3, 5}));
  EXPECT_EQ(reals(p, 20), (std::vector<double>{0.2, 2.0 / 7, 6}));
  EXPECT_EQ(reals(p, 42), std::vector<double>{0.4142135623730951});
}

TEST(DrawingDxf, LinesAndArcsOnlyTurnsBulgesIntoArcs) {
  Drawing d;
  // Chord (0,0)-(10,0) with bulge 0.5: by hand, r = c (1 + b^2) / (4 b) = 10 * 1.25 / 2 = 6.25,
  // centre at (1 - b^2) / (4 b) * c = 3.75 left of the chord, i.e. (5, 3.75); the arc runs
  // counter-clockwise from atan2(-3.75, -5) = -143.130 deg to atan2(-3.75, 5) = -36.870 deg.
  // Then a clockwise semicircle (bulge -1) from (10,0) to (10,10): centre (10,5), r = 5; as a
  // counter-clockwise ARC it runs from the end point (90 deg) round the left side to -90 deg.
  d.polylines.push_back({"profile", {{0, 0, 0.5}, {10, 0, -1}, {10, 10, 0}}, false});
  const auto tags = read_tags(to_dxf(d, DxfOptions{true}));
  EXPECT_TRUE(entities_of(tags, "LWPOLYLINE").empty());
  const auto arcs = entities_of(tags, "ARC");
  ASSERT_EQ(arcs.size(), 2u);
  EXPECT_NEAR(reals(arcs[0], 10)[0], 5, 1e-12);
  EXPECT_NEAR(reals(arcs[0], 20)[0], 3.75, 1e-12);
  EXPECT_NEAR(reals(arcs[0], 40)[0], 6.25, 1e-12);
  EXPECT_NEAR(reals(arcs[0], 50)[0], -143.13010235415598, 1e-9);
  EXPECT_NEAR(reals(arcs[0], 51)[0], -36.86989764584402, 1e-9);
  EXPECT_NEAR(reals(arcs[1], 10)[0], 10, 1e-12);
  EXPECT_NEAR(reals(arcs[1], 20)[0], 5, 1e-12);
  EXPECT_NEAR(reals(arcs[1], 40)[0], 5, 1e-12);
  EXPECT_NEAR(reals(arcs[1], 50)[0], 90, 1e-9);
  EXPECT_NEAR(std::remainder(reals(arcs[1], 51)[0], 360), -90, 1e-9);
  EXPECT_TRUE(entities_of(tags, "LINE").empty());  // open polyline: no closing segment
}

TEST(DrawingDxf, NonAsciiTextIsEscapedForTheAnsiCodePage) {
  const auto texts = entities_of(read_tags(to_dxf(sample_drawing())), "TEXT");
  ASSERT_EQ(texts.size(), 1u);
  std::string value;
  for (const Tag& t : texts[0])
    if (t.code == 1) value = t.value;
  EXPECT_EQ(value, "Leva \\U+03B8 = 30\\U+00B0");
}

TEST(DrawingDxf, NonFiniteCoordinatesAreRejected) {
  Drawing d;
  d.lines.push_back({"a", 0, 0, std::numeric_limits<double>::quiet_NaN(), 1});
  EXPECT_THROW(to_dxf(d), std::invalid_argument);
  EXPECT_THROW(to_svg(d), std::invalid_argument);
}

TEST(DrawingDxf, EzdxfAuditFindsNoErrors) {
  const auto dir = scratch_dir();
  for (bool lines_and_arcs : {false, true}) {
    const auto file = dir / (lines_and_arcs ? "sample_lines_arcs.dxf" : "sample.dxf");
    std::ofstream(file) << to_dxf(sample_drawing(), DxfOptions{lines_and_arcs});
    const auto result = ezdxf_check(file);
    ASSERT_FALSE(result.contains("read_error")) << result.dump();
    EXPECT_EQ(result["dxfversion"], "AC1015");
    EXPECT_EQ(result["insunits"], 4);
    EXPECT_TRUE(result["audit_errors"].empty()) << result.dump();
    EXPECT_TRUE(result["audit_fixes"].empty()) << result.dump();
    EXPECT_TRUE(result["handles_unique"].get<bool>());
    const auto& profile = result["entities"]["profile"];
    if (lines_and_arcs) {
      EXPECT_EQ(profile["ARC"], 2);
      EXPECT_EQ(profile["LINE"], 2);
    } else {
      EXPECT_EQ(profile["LWPOLYLINE"], 1);
      EXPECT_EQ(result["closed_polylines"]["profile"], 1);
    }
    EXPECT_EQ(result["entities"]["pitch_curve"]["CIRCLE"], 1);
    EXPECT_EQ(result["entities"]["text"]["TEXT"], 1);
  }
}

TEST(DrawingDxf, EzdxfReadsBackTheArcGeometry) {
  // A circle of radius 10 about (3,4) as two bulge-1 semicircles; every point on it must be read
  // back on the curve, with and without the LINE/ARC option.
  Drawing d;
  d.polylines.push_back({"profile", {{13, 4, 1}, {-7, 4, 1}}, true});
  const auto dir = scratch_dir();
  const auto points = dir / "circle_points.csv";
  {
    std::ofstream csv(points);
    csv.precision(17);
    csv << "x_mm,y_mm\n";
    for (int i = 0; i < 360; ++i) {
      const double t = i * 3.141592653589793 / 180;
      csv << 3 + 10 * std::cos(t) << "," << 4 + 10 * std::sin(t) << "\n";
    }
  }
  for (bool lines_and_arcs : {false, true}) {
    const auto file = dir / (lines_and_arcs ? "circle_la.dxf" : "circle.dxf");
    std::ofstream(file) << to_dxf(d, DxfOptions{lines_and_arcs});
    const auto result = ezdxf_check(file, "--points '" + points.string() + "' --layer profile --tol 1e-9");
    ASSERT_TRUE(result.contains("max_deviation_mm")) << result.dump();
    EXPECT_LT(result["max_deviation_mm"].get<double>(), 1e-9) << result.dump();
    EXPECT_TRUE(result["ok"].get<bool>()) << result.dump();
  }
}

TEST(DrawingSvg, FlipsYAndGroupsByLayer) {
  Drawing d;
  d.layers = {{"pitch_curve", 5, "#00c", true}};
  d.lines.push_back({"profile", 0, 0, 10, 20});
  d.circles.push_back({"pitch_curve", 1, 2, 3});
  const std::string svg = to_svg(d, SvgOptions{5, 0.25, "Cam <1>"});
  EXPECT_NE(svg.find("<line x1=\"0\" y1=\"0\" x2=\"10\" y2=\"-20\"/>"), std::string::npos) << svg;
  EXPECT_NE(svg.find("<circle cx=\"1\" cy=\"-2\" r=\"3\"/>"), std::string::npos) << svg;
  // Extents x -2..10, y -1..20 plus 5 mm margin: viewBox from (-7, -25), 22 x 31 mm.
  EXPECT_NE(svg.find("viewBox=\"-7 -25 22 31\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("<g id=\"layer-pitch_curve\""), std::string::npos);
  EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos);
  EXPECT_NE(svg.find("<title>Cam &lt;1&gt;</title>"), std::string::npos);
}

TEST(DrawingSvg, BulgeArcsUseTheSweepSeenOnScreen) {
  Drawing d;
  // Counter-clockwise in the drawing (y up) is counter-clockwise on screen too, which in SVG's
  // y-down frame is sweep-flag 0; a bulge of tan(60 deg) spans 240 deg: the large arc.
  // Check of the first arc by the SVG spec's centre construction (SVG 1.1 F.6.5): from (0,0) to
  // (10,0) with r = 6.25, flags (0, 0): x1' = -5, y1' = 0, coefficient -sqrt((r^2 - 25) / 25) =
  // -0.75 (minus: the flags are equal), centre (5, -0.75 * 5) = (5, -3.75) in SVG, i.e. (5, 3.75)
  // in the drawing: the centre of the bulge-0.5 arc (see LinesAndArcsOnlyTurnsBulgesIntoArcs).
  d.polylines.push_back({"p", {{0, 0, 0.5}, {10, 0, -std::tan(1.0471975511965976)}, {20, 0, 0}}, false});
  const std::string svg = to_svg(d);
  EXPECT_NE(svg.find("M0,0 A6.25 6.25 0 0 0 10,0 A"), std::string::npos) << svg;
  EXPECT_NE(svg.find(" 0 1 1 20,0"), std::string::npos) << svg;
}

}  // namespace
