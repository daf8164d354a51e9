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
/// kin --format html: positions of a sweep on the page. A page is a report to read and print
/// (about 4 kB per four-bar position with its JSON): a longer sweep shows one position in k,
/// stated on the page, and --format csv/json hold every position.
inline constexpr long kHtmlTableRows = 2000;
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

/// Lists of a model file. Every list is bounded by the YAML node limit (1,000,000 nodes, about
/// 500 MB of yaml-cpp nodes: docs/cli.md); these are the lists whose work grows faster than their
/// length or whose items are costly, each refused at its first item beyond the limit.
/// kin: links of a mechanism (3 coordinates each), and the items of every other list of it
/// (joints, ground points, elements, drivers, outputs, forces, torques, springs): a chain of
/// 10,000 four-bar loops (`kin --example chain:10000`, 20,001 links, 30,001 joints) is the largest.
inline constexpr std::size_t kMechanismLinks = 20'001;
inline constexpr std::size_t kMechanismItems = 30'001;
/// cam: points of the `table` segments of a motion program, all tables together (each cam angle
/// of the report finds its interval in a table: 30,000 points took 3 s, 100,000 over a minute).
inline constexpr std::size_t kCamTablePoints = 10'000;
/// cam: segments of a motion program.
inline constexpr std::size_t kCamSegments = 1'000;
/// dyn: rows of a table over the turn (`inertia_table`, a torque law's `table`): as many as a
/// computed inertia table has at the most `mechanism_steps` (36,000 intervals).
inline constexpr std::size_t kDynTableRows = 36'001;
/// dyn: stages, energy loads, phases and reduced-force terms, each list.
inline constexpr std::size_t kDynListItems = 1'000;

/// train --modes: members that are not planets, input or output (each is held in turn and each
/// pair coupled: 820 modes at the limit).
inline constexpr std::size_t kModesMembers = 40;

}  // namespace gearkit::io::limits
