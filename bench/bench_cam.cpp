// Cam synthesis benchmark (issue 5): a 3600-sample cycloidal rise-dwell-return cam with a
// translating roller follower -- design checks at 3600 cam angles, biarc fit of the pitch curve,
// CGAL inset by the roller radius, DXF export -- must take under 50 ms together.
// Counters: the profile's largest deviation from the analytic roller profile (X - R_r n at the
// 3600 cam angles) and the fit tolerance it is held to.
#include <gearkit/cam/cam_checks.hpp>
#include <gearkit/cam/cam_profile.hpp>
#include <gearkit/io/drawing.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

namespace {

using namespace gearkit::cam;

constexpr int kSamples = 3600;
constexpr double kTolerance = 1e-3;  // mm

double rad(double deg) { return deg * std::numbers::pi / 180; }

Segment segment(SegmentKind kind, double from, double to, double lift) {
  Segment s;
  s.kind = kind;
  s.start = rad(from), s.end = rad(to);
  s.law = Law::cycloidal;
  s.lift = lift;
  return s;
}

/// Cycloidal rise 20 mm over 120 deg, dwell 60 deg, cycloidal return over 120 deg, dwell 60 deg;
/// base circle 40 mm, roller 10 mm (examples/cams/translating_roller_cycloidal.yaml).
CamDesign bench_cam() {
  Follower f;
  f.contact = Contact::roller;
  f.roller_radius = 10;
  CamDesign d{MotionProgram({segment(SegmentKind::rise, 0, 120, 20), segment(SegmentKind::dwell, 120, 180, 0),
                             segment(SegmentKind::fall, 180, 300, 20), segment(SegmentKind::dwell, 300, 360, 0)}),
              f, 40, Rotation::ccw};
  validate(d);
  return d;
}

gearkit::io::Drawing drawing_of(const CamDesign& d, const CamProfile& p) {
  gearkit::io::Drawing drawing;
  drawing.layers = {{"profile", 7, "#000", false}, {"pitch_curve", 5, "#25c", true}, {"base_circle", 8, "#888", true}};
  auto add = [&](const std::vector<Piece>& loop, const char* layer) {
    gearkit::io::Polyline poly{layer, {}, true};
    for (const BulgeVertex& v : bulge_vertices(loop)) poly.vertices.push_back({v.x, v.y, v.bulge});
    drawing.polylines.push_back(poly);
  };
  for (const auto& loop : p.profile) add(loop, "profile");
  add(p.pitch_curve, "pitch_curve");
  drawing.circles.push_back({"base_circle", 0, 0, d.base_radius});
  return drawing;
}

void BM_CamSynthesisInsetAndDxf(benchmark::State& state) {
  const CamDesign d = bench_cam();
  double deviation = 0;
  std::size_t arcs = 0, bytes = 0;
  for (auto _ : state) {
    const CamChecks checks = check_design(d, {kSamples, rad(30)});
    const CamProfile profile = synthesize_profile(d, {kTolerance, std::nullopt});
    const std::string dxf = gearkit::io::to_dxf(drawing_of(d, profile));
    benchmark::DoNotOptimize(dxf.data());
    state.PauseTiming();  // the deviation is a measurement of the result, not part of the work
    std::vector<Vec2> analytic;
    for (const ContactState& c : checks.samples) analytic.push_back(c.contact);
    deviation = max_deviation(profile.profile, analytic);
    arcs = bulge_vertices(profile.profile.front()).size();
    bytes = dxf.size();
    state.ResumeTiming();
  }
  state.counters["deviation_mm"] = deviation;
  state.counters["tolerance_mm"] = kTolerance;
  state.counters["profile_arcs"] = static_cast<double>(arcs);
  state.counters["dxf_bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_CamSynthesisInsetAndDxf)->Unit(benchmark::kMillisecond);

void BM_ChecksAt3600Angles(benchmark::State& state) {
  const CamDesign d = bench_cam();
  for (auto _ : state) benchmark::DoNotOptimize(check_design(d, {kSamples, rad(30)}).pressure_angle_max.value);
}
BENCHMARK(BM_ChecksAt3600Angles)->Unit(benchmark::kMillisecond);

/// Fit and inset alone, for fit tolerances 10^-arg mm: how the arc count and time grow.
void BM_BiarcFitAndCgalInset(benchmark::State& state) {
  const CamDesign d = bench_cam();
  const double tolerance = std::pow(10.0, -static_cast<double>(state.range(0)));
  CamProfile p;
  for (auto _ : state) {
    p = synthesize_profile(d, {tolerance, std::nullopt});
    benchmark::DoNotOptimize(p.profile.data());
  }
  std::vector<Vec2> analytic;
  for (int i = 0; i < kSamples; ++i) analytic.push_back(contact_at(d, 2 * std::numbers::pi * i / kSamples).contact);
  state.counters["biarcs"] = static_cast<double>(p.biarcs);
  state.counters["tolerance_mm"] = tolerance;
  state.counters["deviation_mm"] = max_deviation(p.profile, analytic);
}
BENCHMARK(BM_BiarcFitAndCgalInset)->Arg(3)->Arg(4)->Arg(5)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
