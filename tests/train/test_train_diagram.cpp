// CLI tests of the train drawings (plugins/train/train_diagram.hpp), read back from the DXF by
// ezdxf (an independent reader): one gear bar per gear with its tooth count, as the example files
// give them; every member named; the speed diagram's rays with the slopes of the speeds derived by
// hand in the example files' comments (Willis' equation).
#include "dxf_drawing.hpp"
#include "run_gearkit.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using gearkit::testing::run_gearkit;
using gearkit::testing::shell_quote;

namespace {

bool have_ezdxf() { return std::system("/usr/bin/python3 -c 'import ezdxf' >/dev/null 2>&1") == 0; }

std::string example(const std::string& name) { return std::string(GEARKIT_SOURCE_DIR) + "/examples/trains/" + name + ".yaml"; }

nlohmann::json drawing_of(const std::string& name, const std::string& options = "") {
  const fs::path dir = gearkit::testing::scratch_dir("train-diagram-" + name);
  const fs::path dxf = dir / "train.dxf", svg = dir / "train.svg", dump = dir / "train.json";
  const auto r = run_gearkit("train " + shell_quote(example(name)) + " " + options + " --dxf " + shell_quote(dxf.string()) +
                             " --svg " + shell_quote(svg.string()));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(gearkit::testing::slurp(svg).find("layer-gear_labels"), std::string::npos);
  const std::string cmd = "/usr/bin/python3 " + shell_quote(std::string(GEARKIT_SOURCE_DIR) + "/tests/gear/dxf_dump.py") + " " +
                          shell_quote(dxf.string()) + " > " + shell_quote(dump.string());
  EXPECT_EQ(std::system(cmd.c_str()), 0);
  return nlohmann::json::parse(gearkit::testing::slurp(dump));
}

struct GearSpec {
  std::string name;
  int z;
  bool internal;
};

// The gears as the example file lists them, and its members (read by hand from examples/trains).
const std::map<std::string, std::pair<std::vector<GearSpec>, std::vector<std::string>>> kExamples = {
    {"simple_planetary", {{{"s", 24, false}, {"p", 18, false}, {"r", 60, true}}, {"sun", "carrier", "planet", "ring"}}},
    {"ravigneaux",
     {{{"zs1", 30, false}, {"zs2", 36, false}, {"zshort", 18, false}, {"zlong", 24, false}, {"zring", 84, true}},
      {"s1", "s2", "carrier", "ring", "short", "long"}}},
    {"wolfrom",
     {{{"s", 12, false}, {"p1", 24, false}, {"p2", 21, false}, {"r1", 60, true}, {"r2", 57, true}},
      {"sun", "carrier", "planet", "ring1", "ring2"}}},
    {"seed_two_epicyclic_stages",
     {{{"z1", 48, false}, {"z2", 24, false}, {"z3", 18, false}, {"z4", 90, true}, {"z5", 84, true}, {"z6", 30, false},
       {"z7", 24, false}},
      {"1", "b", "45", "7", "23", "6"}}},
    {"seed_cvt_train",
     {{{"z1", 35, false}, {"z2", 90, false}, {"z3", 20, false}, {"z4", 20, false}, {"z5", 60, true}}, {"1", "23", "b", "4", "5"}}},
    {"two_stage_reducer",
     {{{"1", 15, false}, {"2", 60, false}, {"3", 18, false}, {"4", 72, false}}, {"input", "counter", "output"}}},
};

bool named(const nlohmann::json& labels, const std::string& member) {
  return std::any_of(labels.begin(), labels.end(), [&](const nlohmann::json& t) {
    const std::string s = t.get<std::string>();
    return s == member || s.rfind(member + " (", 0) == 0;
  });
}

// dx/dy of each ray of the speed diagram: k n for a member turning at n (the diagram's v = n r).
std::vector<double> ray_slopes(const nlohmann::json& d) {
  std::vector<double> out;
  for (const auto& l : d["lines"]["speed_rays"]) {
    const double dx = l[2].get<double>() - l[0].get<double>(), dy = l[3].get<double>() - l[1].get<double>();
    out.push_back(dx / dy);
  }
  return out;
}

}  // namespace

TEST(TrainDiagram, OneBarPerGearWithItsToothCountAndEveryMemberNamed) {
  if (!have_ezdxf()) GTEST_SKIP() << "python3-ezdxf not installed";
  for (const auto& [name, spec] : kExamples) {
    const nlohmann::json d = drawing_of(name);
    EXPECT_EQ(d["audit_errors"], 0) << name;
    const auto& gears = spec.first;
    const auto& bars = d["polyline_shapes"]["gears"];
    ASSERT_EQ(bars.size(), gears.size()) << name;
    const auto& labels = d["texts"]["gear_labels"];
    ASSERT_EQ(labels.size(), gears.size()) << name;
    for (std::size_t i = 0; i < gears.size(); ++i) {
      EXPECT_EQ(labels[i], gears[i].name + ": z = " + std::to_string(gears[i].z)) << name;
      // External gears are closed bars, internal gears brackets open towards the axis.
      EXPECT_EQ(bars[i]["closed"].get<bool>(), !gears[i].internal) << name << " " << gears[i].name;
    }
    for (const std::string& member : spec.second) EXPECT_TRUE(named(d["texts"]["member_labels"], member)) << name << " " << member;
  }
}

TEST(TrainDiagram, MeshingBarsTouchAtTheirPitchRadii) {
  if (!have_ezdxf()) GTEST_SKIP() << "python3-ezdxf not installed";
  // Simple planetary, module 2 mm: r_s = 24, r_p = 18, r_r = 60 mm (m z / 2). Drawn to one scale,
  // the sun bar ends where the planet bar begins and the planet bar ends at the ring's teeth.
  const nlohmann::json d = drawing_of("simple_planetary");
  const auto& bars = d["polyline_shapes"]["gears"];
  auto top = [](const nlohmann::json& bar) {
    double y = -1e300;
    for (const auto& p : bar["points"]) y = std::max(y, p[1].get<double>());
    return y;
  };
  auto bottom = [](const nlohmann::json& bar) {
    double y = 1e300;
    for (const auto& p : bar["points"]) y = std::min(y, p[1].get<double>());
    return y;
  };
  const double sun = top(bars[0]), planet_lo = bottom(bars[1]), planet_hi = top(bars[1]), ring = bottom(bars[2]);
  EXPECT_NEAR(sun, planet_lo, 1e-9);
  EXPECT_NEAR(planet_hi, ring, 1e-9);
  EXPECT_NEAR(sun / ring, 24.0 / 60.0, 1e-9);
  EXPECT_NEAR((planet_hi - planet_lo) / ring, 36.0 / 60.0, 1e-9);
}

TEST(TrainDiagram, SpeedRaysHaveTheSlopesOfTheSpeedsDerivedByHand) {
  if (!have_ezdxf()) GTEST_SKIP() << "python3-ezdxf not installed";
  // Simple planetary, ring fixed (examples/trains/simple_planetary.yaml): w_c/w_s = z_s/(z_s + z_r)
  // = 24/84 = 2/7; the planet w_p = w_c - (z_s/z_p)(w_s - w_c) = (2/7 - (4/3)(5/7)) w_s = -2/3 w_s;
  // the ring 0.
  {
    const nlohmann::json d = drawing_of("simple_planetary");
    std::vector<double> s = ray_slopes(d);
    ASSERT_EQ(s.size(), 4u);
    const double sun = *std::max_element(s.begin(), s.end());
    for (double& v : s) v /= sun;
    std::sort(s.begin(), s.end());
    const std::vector<double> expected{-2.0 / 3.0, 0.0, 2.0 / 7.0, 1.0};
    for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(s[i], expected[i], 1e-6) << i;
    const auto& labels = d["texts"]["speed_labels"];
    EXPECT_TRUE(std::find(labels.begin(), labels.end(), "sun: n = 3000 rpm") != labels.end());
    EXPECT_TRUE(std::find(labels.begin(), labels.end(), "carrier: n = 857.1429 rpm") != labels.end());  // 3000 x 2/7
  }
  // Wolfrom (examples/trains/wolfrom.yaml): w_r2/w_s = 1/76, w_c/w_s = 1/6; ring r1 fixed.
  {
    const nlohmann::json d = drawing_of("wolfrom");
    std::vector<double> s = ray_slopes(d);
    ASSERT_EQ(s.size(), 5u);  // sun, carrier, ring1, ring2 and the planet
    const double sun = *std::max_element(s.begin(), s.end());
    auto has = [&](double ratio) {
      return std::any_of(s.begin(), s.end(), [&](double v) { return std::abs(v / sun - ratio) < 1e-6; });
    };
    EXPECT_TRUE(has(1.0 / 76.0));
    EXPECT_TRUE(has(1.0 / 6.0));
    EXPECT_TRUE(has(0.0));
  }
}

TEST(TrainDiagram, WithoutInputSpeedTheRaysShowRatios) {
  if (!have_ezdxf()) GTEST_SKIP() << "python3-ezdxf not installed";
  const nlohmann::json d = drawing_of("simple_planetary", "--fix ring --input sun");
  const auto& labels = d["texts"]["speed_labels"];
  EXPECT_TRUE(std::find(labels.begin(), labels.end(), "carrier: n = 0.2857 x w_sun") != labels.end()) << labels.dump();
}

TEST(TrainDiagram, FixedAxisReducerHasNoSpeedDiagramAndIsCoaxial) {
  if (!have_ezdxf()) GTEST_SKIP() << "python3-ezdxf not installed";
  // OTM 2015 problem 3: a = (15 + 60) 6/2 = (18 + 72) 5/2 = 225 mm for both stages, so the output
  // shaft lies on the input's axis.
  const nlohmann::json d = drawing_of("two_stage_reducer");
  EXPECT_FALSE(d["lines"].contains("speed_rays"));
  std::vector<double> axes;
  for (const auto& l : d["lines"]["axes"]) axes.push_back(l[1].get<double>());
  std::sort(axes.begin(), axes.end());
  axes.erase(std::unique(axes.begin(), axes.end(), [](double a, double b) { return std::abs(a - b) < 1e-9; }), axes.end());
  EXPECT_EQ(axes.size(), 2u);  // input/output axis and the countershaft
}

namespace {

// Whether segments a and b cross at a point inside both (orientation tests; touching ends do not).
bool segments_cross(const nlohmann::json& a, const nlohmann::json& b) {
  auto side = [](double ax, double ay, double bx, double by, double cx, double cy) {
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
  };
  const double a0 = a[0], a1 = a[1], a2 = a[2], a3 = a[3], b0 = b[0], b1 = b[1], b2 = b[2], b3 = b[3];
  const double d1 = side(a0, a1, a2, a3, b0, b1), d2 = side(a0, a1, a2, a3, b2, b3);
  const double d3 = side(b0, b1, b2, b3, a0, a1), d4 = side(b0, b1, b2, b3, a2, a3);
  return d1 * d2 < 0 && d3 * d4 < 0;
}

}  // namespace

TEST(TrainDiagram, LabelsClearOfEachOtherAndOfLinesAndLeadersDoNotCross) {
  if (!have_ezdxf()) GTEST_SKIP() << "python3-ezdxf not installed";
  // Every shipped train: no label box overlaps another or is crossed by a line (the audit saw the
  // Ravigneaux set's planet pins through "zshort: z = 18"), and the speed diagram's leaders do not
  // cross each other (they did, in a fan from the label column).
  std::vector<std::string> names;
  for (const auto& [name, spec] : kExamples) names.push_back(name);
  names.push_back("ljubljana_planetary");
  for (const std::string& name : names) {
    const auto j = drawing_of(name);
    EXPECT_EQ(gearkit::testing::layout_faults(gearkit::testing::drawing_from_dump(j)), "") << name;
    const auto& leaders = j["lines"]["speed_labels"];
    for (std::size_t a = 0; a < leaders.size(); ++a)
      for (std::size_t b = a + 1; b < leaders.size(); ++b) EXPECT_FALSE(segments_cross(leaders[a], leaders[b])) << name << " " << a << " " << b;
  }
}

TEST(TrainDiagram, GearLabelNextToAnotherBarHasALeaderToItsOwn) {
  if (!have_ezdxf()) GTEST_SKIP() << "python3-ezdxf not installed";
  // Gear labels sit right of their bars; one pushed to the left of its bar, within 1.5 text
  // heights of another gear's bar on its left (at its mid-height), reads as that gear's: the
  // Ravigneaux's "zs2: z = 36", pushed left by the carrier, sat beside the small sun's bar under
  // "zs1: z = 30". Such a label has a leader from its end to its own bar.
  for (const auto& [name, spec] : kExamples) {
    const nlohmann::json d = drawing_of(name);
    const auto& bars = d["polyline_shapes"]["gears"];
    const auto& at = d["text_at"]["gear_labels"];
    const nlohmann::json leaders = d["lines"].contains("gear_labels") ? d["lines"]["gear_labels"] : nlohmann::json::array();
    auto box = [&](std::size_t i) {  // x0, x1, y0, y1 of bar i
      double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
      for (const auto& p : bars[i]["points"]) {
        x0 = std::min(x0, p[0].get<double>()), x1 = std::max(x1, p[0].get<double>());
        y0 = std::min(y0, p[1].get<double>()), y1 = std::max(y1, p[1].get<double>());
      }
      return std::array<double, 4>{x0, x1, y0, y1};
    };
    for (std::size_t i = 0; i < spec.first.size(); ++i) {
      if (spec.first[i].internal) continue;
      const double h = d["text_height"]["gear_labels"][i], tx = at[i][1], ty = at[i][2];
      const double w = 0.62 * h * static_cast<double>(at[i][0].get<std::string>().size()), mid = ty + 0.35 * h;
      bool near_other = false;
      for (std::size_t j = 0; j < bars.size(); ++j) {
        const auto b = box(j);
        if (j == i || mid < b[2] || mid > b[3]) continue;
        near_other = near_other || (b[1] <= tx && tx - b[1] < 1.5 * h);
      }
      const auto own = box(i);
      if (!near_other || tx + w > own[0]) continue;
      const bool led = std::any_of(leaders.begin(), leaders.end(), [&](const nlohmann::json& l) {
        return std::abs(l[0].get<double>() - (tx + w)) < 0.5 * h && std::abs(l[2].get<double>() - own[0]) < 1e-6;
      });
      EXPECT_TRUE(led) << name << " " << at[i][0];
    }
  }
}
