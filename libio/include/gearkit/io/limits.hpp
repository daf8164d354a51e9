#pragma once
// Limits of the inputs that set an amount of work, in one place so that docs/cli.md ("Limits")
// can list them all. Each keeps a run of the `gearkit` process under a few seconds and a few
// hundred MB on a 2-core machine (measured figures in docs/benchmarks.md); a value beyond one
// is bad input (status 2) naming the option or file:line:column.
#include <cstddef>

namespace gearkit::io::limits {

/// kin: positions of a sweep (--sweep, or a driver's range in the model file). A sweep streams
/// its report (memory does not grow with its length) at about 1-3 us per four-bar position, and
/// shows a progress bar on a terminal: 10 million positions take under a minute.
inline constexpr double kSweepPositions = 1e7;
/// kin: positions of a sweep times the mechanism's coordinates (3 per body): the work grows
/// with both (about 0.2 us per coordinate and position).
inline constexpr double kSweepWork = 1e8;
/// kin --at: the solver reaches the asked input by continuation from the drawn configuration
/// in steps of 2 deg or 2 mm: at most this many steps (200,000 deg, 200 m) ...
inline constexpr double kContinuationSteps = 100'000;
/// ... and at most this many steps times coordinates.
inline constexpr double kContinuationWork = 2e7;

/// train synth: tooth counts searched (--z-min, --z-max, --z1; --z-ring-max for planetary).
/// The reducer search grows with the cube of the range, the planetary one with its square.
inline constexpr int kSynthReducerTeeth = 500;
inline constexpr int kSynthPlanetaryTeeth = 2000;
/// train synth --tolerance: the accepted relative ratio error (a wider one admits every set).
inline constexpr double kSynthTolerance = 0.1;
/// train synth --max-results: candidates kept and listed.
inline constexpr int kSynthResults = 1000;

/// gear --svg/--dxf: teeth drawn (z1 + z2 for --draw pair); about 50 kB per tooth.
inline constexpr long long kDrawnTeeth = 4000;

/// train: entries of a train file. Speeds and torques are exact fractions whose digits grow with
/// every stage of a chain (a 20:21 stage adds 2.6, a 99999:100000 one 10), so the work and the
/// report grow with the square of the stages: 2,000 stages of 99999:100000 with --torque take
/// 1.6 s and 160 MB (docs/benchmarks.md); 20,000 would take minutes and gigabytes.
inline constexpr std::size_t kTrainMeshes = 2000;
inline constexpr std::size_t kTrainMembers = 4000;
inline constexpr std::size_t kTrainGears = 8000;

/// train --modes: members that are not planets, input or output (each is held in turn and each
/// pair coupled: 820 modes at the limit).
inline constexpr std::size_t kModesMembers = 40;

}  // namespace gearkit::io::limits
