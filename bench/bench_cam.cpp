// Cam benchmarks. Synthesis (issue 5): a 3600-sample cycloidal rise-dwell-return cam with a
// translating roller follower -- design checks at 3600 cam angles, biarc fit of the pitch curve,
// CGAL inset by the roller radius, DXF export -- must take under 50 ms together. Counters: the
// profile's largest deviation from the analytic roller profile (X - R_r n at the 3600 cam
// angles) and the fit tolerance it is held to.
// Dynamics (issue 18): the follower train over 3600 cam angles with its spring sized, under 5 ms;
// the whole `gearkit cam` process (start-up, plugins, checks, profile, dynamics, report) for the
// benchmark cam, the dynamics example and the groove example, under 25 ms.
#include <gearkit/cam/cam_checks.hpp>
#include <gearkit/cam/cam_profile.hpp>
#include <gearkit/cam/follower_dynamics.hpp>
#include <gearkit/cam/follower_vibration.hpp>
#include <gearkit/io/drawing.hpp>

#include "spawn_process.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

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

/// examples/cams/double_dwell_dynamics.yaml: rise 10 mm in 90 deg, dwell 45 deg, fall in 180 deg,
/// dwell, 3-4-5; roller 12.5 mm on a 63.7 mm base circle.
CamDesign double_dwell() {
  Follower f;
  f.contact = Contact::roller;
  f.roller_radius = 12.5;
  auto law = [](SegmentKind kind, double from, double to, double lift) {
    Segment s = segment(kind, from, to, lift);
    s.law = Law::polynomial_345;
    return s;
  };
  CamDesign d{MotionProgram({law(SegmentKind::rise, 0, 90, 10), segment(SegmentKind::dwell, 90, 135, 0),
                             law(SegmentKind::fall, 135, 315, 10), segment(SegmentKind::dwell, 315, 360, 0)}),
              f, 63.7, Rotation::ccw};
  validate(d);
  return d;
}

/// The dynamics example's follower train: 7.5 kg, 2.74 N s/m, 2 N/um of its own stiffness.
FollowerTrain double_dwell_train() {
  FollowerTrain t;
  t.mass = 7.5, t.damping = 2.74, t.stiffness = 2e6;
  return t;
}

/// What `gearkit cam` computes of a force-closed follower at its design speed: the spring sized
/// for 5 N of contact up to 10 rad/s (rate and preload both free), the kinetostatic state at
/// 3600 cam angles with Hertz stress, the jump speed and the least contact margin.
void BM_DynamicsWithSpringSizing(benchmark::State& state) {
  const CamDesign d = double_dwell();
  FollowerTrain t = double_dwell_train();
  t.stiffness = 0;
  const ContactMaterial steel{0.015};
  const double omega = 10;
  SpringSizing spring;
  for (auto _ : state) {
    spring = size_spring(d, t, {omega, 5, std::nullopt, std::nullopt, std::nullopt});
    FollowerTrain sized = t;
    sized.spring_rate = spring.spring_rate, sized.preload = spring.preload;
    const auto states = dynamics_over_turn(d, sized, omega, 3600, &steel);
    const auto jump = jump_speed(d, sized, 0, 20 * omega);
    benchmark::DoNotOptimize(states.data());
    benchmark::DoNotOptimize(jump);
    benchmark::DoNotOptimize(least_contact_margin(d, sized, omega, 5));
  }
  state.counters["spring_rate_N_per_mm"] = spring.spring_rate / 1000;
  state.counters["preload_N"] = spring.preload;
}
BENCHMARK(BM_DynamicsWithSpringSizing)->Unit(benchmark::kMillisecond);

/// The flexible follower on top (2 N/um): its periodic response at 3600 angles, the residual
/// vibration after each rise and return, and the comparison of the eight laws.
void BM_FlexibleFollowerAndLaws(benchmark::State& state) {
  const CamDesign d = double_dwell();
  FollowerTrain t = double_dwell_train();
  t.spring_rate = 1887, t.preload = 5;
  for (auto _ : state) {
    const FlexibleResponse f = flexible_response(d, t, 10, 3600);
    benchmark::DoNotOptimize(residual_vibrations(d, t, f).size());
    for (const std::string& name : law_names())
      benchmark::DoNotOptimize(residual_vibration_of_law(*law_from_name(name), 0.01, std::numbers::pi / 2, 10,
                                                         f.natural_frequency, f.damping_ratio, f.static_ratio));
  }
}
BENCHMARK(BM_FlexibleFollowerAndLaws)->Unit(benchmark::kMillisecond);

/// `gearkit cam FILE`, the whole process: wall time (Google Benchmark's real time) and the
/// child's CPU time (user + system) as a counter, the figure that does not depend on the load.
void BM_Process_Cam(benchmark::State& state, const std::string& example) {
  const std::string file = std::string(GEARKIT_SOURCE_DIR) + "/examples/cams/" + example;
  std::vector<double> cpu;
  for (auto _ : state) {
    const gearkit::bench::ProcessRun run = gearkit::bench::run_process({GEARKIT_EXE, "cam", file});
    if (!run.ok) state.SkipWithError("gearkit cam failed");
    cpu.push_back(run.cpu_s);
  }
  std::sort(cpu.begin(), cpu.end());
  state.counters["cpu_ms_median"] = cpu.empty() ? 0 : 1e3 * cpu[cpu.size() / 2];
  state.counters["cpu_ms_min"] = cpu.empty() ? 0 : 1e3 * cpu.front();
}
BENCHMARK_CAPTURE(BM_Process_Cam, benchmark_cam, std::string("translating_roller_cycloidal.yaml"))
    ->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(50)->Repetitions(3);
BENCHMARK_CAPTURE(BM_Process_Cam, dynamics_example, std::string("double_dwell_dynamics.yaml"))
    ->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(50)->Repetitions(3);
BENCHMARK_CAPTURE(BM_Process_Cam, groove_example, std::string("groove_cam.yaml"))
    ->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(50)->Repetitions(3);

}  // namespace

BENCHMARK_MAIN();
