// Benchmarks of gearkit::dyn: the steady-cycle energy analysis, the drive-line power balance
// (called at every right-hand-side evaluation of the equation of motion) and whole integrations.
#include <gearkit/dyn/curve.hpp>
#include <gearkit/dyn/drive_line.hpp>
#include <gearkit/dyn/flywheel.hpp>
#include <gearkit/dyn/motion.hpp>
#include <gearkit/dyn/reduction.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

namespace gd = gearkit::dyn;
constexpr double pi = std::numbers::pi;

namespace {

// The seed conveyor (004_b4a8ce5a956e12a3.txt): motor curve, reducer 1/15 at 0.7, belt on a drum.
gd::DriveLine conveyor_line() {
  gd::DriveLine line;
  line.motor_efficiency = 0.6;
  line.stages = {{"reducer", 1.0 / 15.0, 0.7}};
  line.shaft_inertia = {0, 40};
  return line;
}

double conveyor_motor(double w) {
  const double x = w / (50 * pi);
  return 116 * (0.3 + 0.7 * x * x - x * x * x * x);
}

}  // namespace

// A cycle of 4 * n linear pieces: a resisting torque with n humps against a constant drive.
static void BM_AnalyseCycle(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const gd::PiecewiseLinear resist =
      gd::sample([n](double th) { return 100 + 80 * std::sin(n * th); }, 0, 2 * pi, 4 * n * 16, true);
  const gd::PiecewiseLinear drive = gd::PiecewiseLinear::constant(resist.mean(), 0, 2 * pi);
  for (auto _ : state) {
    gd::CycleEnergy c = gd::analyse_cycle(drive, resist, 1e-3);
    benchmark::DoNotOptimize(c.energy_excursion);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(resist.x().size()));
}
BENCHMARK(BM_AnalyseCycle)->Arg(1)->Arg(16)->Arg(256);

static void BM_DriveLineAcceleration(benchmark::State& state) {
  const gd::DriveLine line = conveyor_line();
  const std::vector<double> resisting{0, 60};
  double w = 10;
  for (auto _ : state) {
    benchmark::DoNotOptimize(gd::drive_line_acceleration(line, conveyor_motor(w), resisting, w));
    w = w < 150 ? w + 1 : 10;
  }
}
BENCHMARK(BM_DriveLineAcceleration);

// The seed conveyor's start-up from rest to its steady speed (about 2.6 s of machine time).
static void BM_ConveyorStartUp(benchmark::State& state) {
  const gd::DriveLine line = conveyor_line();
  const gd::AccelerationLaw law = [&line](double, double, double w) {
    return gd::drive_line_acceleration(line, conveyor_motor(w), {0, 60}, w);
  };
  gd::MotionOptions o;
  o.t_end = 20;
  o.output_step = 1e-3;
  for (auto _ : state) {
    gd::MotionResult r = gd::integrate_motion(law, 0, 0, o);
    benchmark::DoNotOptimize(r.steady_time);
  }
}
BENCHMARK(BM_ConveyorStartUp)->Unit(benchmark::kMillisecond);

// One second of a slider-crank with tabulated, position-dependent reduced inertia.
static void BM_TabulatedLinkageMotion(benchmark::State& state) {
  std::vector<double> th, in;
  for (int i = 0; i <= 360; ++i) {
    const double q = 2 * pi * i / 360;
    const double k = -0.1 * std::sin(q) - 0.01 * std::sin(q) * std::cos(q) / std::sqrt(0.16 - 0.01 * std::pow(std::sin(q), 2));
    th.push_back(q);
    in.push_back(0.02 + 5 * k * k);
  }
  in.back() = in.front();
  const gd::InertiaTable table(th, in, {}, true);
  gd::ReducedSystem sys;
  sys.inertia = [&table](double q) { return table.inertia(q); };
  sys.inertia_derivative = [&table](double q) { return table.derivative(q); };
  const gd::AccelerationLaw law = gd::acceleration_law(sys);
  gd::MotionOptions o;
  o.t_end = 1;
  o.output_step = 1e-3;
  o.stop_when_steady = false;
  for (auto _ : state) {
    gd::MotionResult r = gd::integrate_motion(law, 0, 30, o);
    benchmark::DoNotOptimize(r.samples.back().omega);
  }
}
BENCHMARK(BM_TabulatedLinkageMotion)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
