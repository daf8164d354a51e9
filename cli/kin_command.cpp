// `gearkit kin FILE.yaml [--at VALUE | --sweep START:END:STEP] [--driver NAME] [--outputs A,B]
//                        [--plot FILE] [--animate FILE] [--format text|json|csv|md]`
// Planar mechanism analysis: degrees of freedom, positions, velocities, accelerations, dead
// points, limit positions of outputs, instant centres, Grashof class and transmission angle,
// driving torque and joint reactions.
#include "kin_analysis.hpp"
#include "kin_command.hpp"
#include "kin_equations.hpp"
#include "kin_example.hpp"
#include "kin_plot.hpp"
#include "kin_report.hpp"
#include "kin_units.hpp"

#include <gearkit/io/command_line.hpp>
#include <gearkit/io/error.hpp>
#include <gearkit/io/limits.hpp>
#include <gearkit/io/output.hpp>
#include <gearkit/io/report_stream.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace gearkit::cli {

namespace {

// START:END:STEP with the driver's unit as default.
mechanism::DriverRange parse_sweep(const std::string& text, io::Quantity q, std::string_view unit) {
  std::vector<std::string> parts;
  std::stringstream ss(text);
  for (std::string part; std::getline(ss, part, ':');) parts.push_back(part);
  if (parts.size() != 3)
    io::fail_option("--sweep", fmt::format("expected START:END:STEP (e.g. 0:360:1), found {}", io::quote(text)));
  mechanism::DriverRange r;
  try {
    r.start = io::parse_quantity_si(parts[0], q, unit);
    r.end = io::parse_quantity_si(parts[1], q, unit);
    r.step = io::parse_quantity_si(parts[2], q, unit);
  } catch (const std::exception& e) {
    io::fail_option("--sweep", e.what());
  }
  if (!(r.step > 0.0)) io::fail_option("--sweep", fmt::format("expected a STEP > 0, found {}", io::quote(parts[2])));
  if (r.start == r.end) io::fail_option("--sweep", "expected START different from END");
  if (std::abs(r.end - r.start) / r.step + 1 > io::limits::kSweepPositions)
    io::fail_option("--sweep", fmt::format("expected at most {:.0f} positions, found {:.6g}", io::limits::kSweepPositions,
                                           std::floor(std::abs(r.end - r.start) / r.step) + 1));
  return r;
}

// The work of a sweep grows with positions times coordinates (docs/cli.md, "Limits").
void check_sweep_work(const kin::Model& m, const mechanism::DriverRange& r, const std::string& where) {
  const double positions = std::floor(std::abs(r.end - r.start) / r.step) + 1;
  const double work = positions * m.coordinates();
  if (work > io::limits::kSweepWork)
    throw io::InputError(fmt::format("{}: expected at most {:.0f} positions times coordinates for a sweep, found {:.0f} "
                                     "positions x {} coordinates; take a larger step",
                                     where, io::limits::kSweepWork, positions, m.coordinates()));
}

// Continuation from the drawn input to --at takes |at - drawn| / step steps of the solver.
void check_continuation_work(const kin::Model& m, double distance, double step) {
  const double steps = std::ceil(std::abs(distance) / step);
  if (steps > io::limits::kContinuationSteps || steps * m.coordinates() > io::limits::kContinuationWork)
    io::fail_option("--at", fmt::format("expected a value within {:g} continuation steps of the drawn input (and at "
                                        "most {:g} steps times coordinates), found {:g} steps for {} coordinates",
                                        io::limits::kContinuationSteps, io::limits::kContinuationWork, steps,
                                        m.coordinates()));
}


// What the command line asks for, once checked.
struct KinRequest {
  std::string file;
  int driver = 0;
  std::optional<double> at;
  std::optional<mechanism::DriverRange> range;
  bool equations = false;
  std::optional<std::string> plot, animate;
  io::CommonOptions common;
};

int driver_named(const mechanism::Mechanism& mech, const io::po::variables_map& vm) {
  if (!vm.count("driver")) return 0;
  const std::string name = vm["driver"].as<std::string>();
  for (std::size_t k = 0; k < mech.drivers.size(); ++k)
    if (mech.drivers[k].name == name) return static_cast<int>(k);
  io::fail_option("--driver", fmt::format("expected the name of a driver of the model, found {}", io::quote(name)));
}

void choose_outputs(mechanism::Mechanism& mech, const io::po::variables_map& vm) {
  if (!vm.count("outputs")) return;
  std::vector<kin::Output> chosen;
  std::stringstream ss(vm["outputs"].as<std::string>());
  for (std::string name; std::getline(ss, name, ',');) {
    auto it = std::find_if(mech.outputs.begin(), mech.outputs.end(), [&](const kin::Output& o) { return o.name == name; });
    if (it == mech.outputs.end())
      io::fail_option("--outputs", fmt::format("expected names of outputs defined in the model, found {}", io::quote(name)));
    chosen.push_back(*it);
  }
  mech.outputs = chosen;
}

// --at, --sweep or the driver's range in the file; checked against the limits of docs/cli.md.
void read_position_options(const mechanism::Mechanism& mech, const io::po::variables_map& vm, KinRequest& r) {
  const io::Quantity q = angular(mech, r.driver) ? io::Quantity::angle : io::Quantity::length;
  const std::string unit = input_unit(mech, r.driver);
  r.range = mech.drivers[static_cast<std::size_t>(r.driver)].range;
  if (vm.count("at")) {
    try {
      r.at = io::parse_quantity_si(vm["at"].as<std::string>(), q, unit);
    } catch (const std::exception& e) {
      io::fail_option("--at", e.what());
    }
    r.range.reset();
  }
  if (vm.count("sweep")) r.range = parse_sweep(vm["sweep"].as<std::string>(), q, unit);
  if (r.range) check_sweep_work(mech.model, *r.range, vm.count("sweep") ? "option '--sweep'" : r.file);
  if (!r.range) {
    const double drawn = mech.model.drivers()[static_cast<std::size_t>(r.driver)].value;
    check_continuation_work(mech.model, r.at.value_or(drawn) - drawn, angular(mech, r.driver) ? 2.0 * M_PI / 180.0 : 0.002);
  }
}

// Mobility against the number of drivers at the drawn configuration: a model must be exactly
// driven. @returns the mobility analysis, which the report shows.
kin::DofReport checked_mobility(const mechanism::Mechanism& mech, const std::string& file) {
  const kin::Model& m = mech.model;
  kin::Data probe(m);
  kin::solve_position(m, probe, 0.0);
  const kin::DofReport d = kin::dof(m, probe);
  if (d.drivers < d.dof)
    io::fail_at({file, 0, 0}, fmt::format("under-driven: the mechanism has {} degree(s) of freedom ({}; rank of Phi_q {}) "
                                          "but {} driver(s)", d.dof, d.gruebler_count, d.rank, d.drivers));
  if (d.drivers > d.dof)
    io::fail_at({file, 0, 0}, fmt::format("over-constrained: the mechanism has {} degree(s) of freedom ({}; rank of Phi_q {}) "
                                          "but {} driver(s)", d.dof, d.gruebler_count, d.rank, d.drivers));
  return d;
}

// The files besides the report: every destination is checked before the first row is written.
struct KinFiles {
  io::OutputSet set;
  std::ostream* report = nullptr;
  explicit KinFiles(std::ostream& out, const KinRequest& r) : set(out) {
    report = &set.stream("--output", r.common.output);
    if (r.plot) set.reserve("--plot", *r.plot);
    if (r.animate) set.reserve("--animate", *r.animate);
  }
};

// Positions as they come: the report's rows (the report begins with the first position, once
// the equations, which may refuse the file's equations: section, are written at it: nothing is
// printed before the input is known good), the plot and the animation's frames.
class KinWriter {
 public:
  KinWriter(const mechanism::Mechanism& mech, const KinRequest& r, const kin::DofReport& dof, KinFiles& files)
      : mech_(mech), r_(r), dof_(dof), files_(files), stream_(*files.report, r.common.format),
        rows_(mech, r.driver, kin::find_four_bar(mech.model).has_value(), mech.model.has_loads(), !r.range) {}

  void plan(double first, double last, long count) {
    stride_ = std::max(1L, (count + kAnimationFrames - 1) / kAnimationFrames);
    if (r_.plot) plot_.emplace(mech_, r_.driver, shown_input(mech_, r_.driver, first), shown_input(mech_, r_.driver, last), count);
  }

  void add(const KinPosition& p) {
    if (!begun_) begin(&p);
    if (stream_.format() == io::Format::json) {
      rows_.json(p, stream_.begin_json_row());
      stream_.end_json_row();
    } else {
      rows_.cells(p, cells_);
      stream_.add_cells(cells_);
    }
    if (plot_) plot_->add(p);
    if (r_.animate && seen_++ % stride_ == 0) frames_.push_back(p);
    else if (r_.animate) last_ = p;
  }

  int finish(const KinAnalysis& a) {
    if (!begun_) begin(nullptr);
    io::Report tail = kin_report_tail(mech_, a);
    for (io::Table& t : equations_.tables) tail.tables.push_back(std::move(t));
    tail.notes.insert(tail.notes.end(), equations_.notes.begin(), equations_.notes.end());
    tail.warnings.insert(tail.warnings.end(), equations_.warnings.begin(), equations_.warnings.end());
    for (const auto& [key, value] : equations_.json.items()) tail.json[key] = value;
    if (r_.plot) {
      if (stream_.rows() == 0) tail.warnings.push_back("no positions to plot; --plot file not written");
      else files_.set.fill("--plot", plot_->svg());
    }
    if (r_.animate) {
      if (stream_.rows() == 0) {
        tail.warnings.push_back("no positions to animate; --animate file not written");
      } else {
        KinAnalysis frames = a;
        frames.positions = std::move(frames_);
        if (last_) frames.positions.push_back(*last_);
        files_.set.fill("--animate", animation_svg(mech_, frames));
      }
    }
    const std::vector<std::string> warnings = stream_.finish(tail);
    files_.set.commit();
    return r_.common.strict && !warnings.empty() ? 3 : 0;
  }

 private:
  void begin(const KinPosition* first) {
    if (r_.equations) {
      KinAnalysis at_first;
      at_first.driver = r_.driver;
      at_first.dof = dof_;
      if (first) at_first.positions.push_back(*first);
      add_equations_section_from_module(equations_, mech_, at_first, r_.common.format);
    }
    stream_.begin(kin_report_head(mech_, dof_, r_.driver), rows_.table(), "positions");
    begun_ = true;
  }

  static constexpr long kAnimationFrames = 240;  // the browser interpolates between them

  const mechanism::Mechanism& mech_;
  const KinRequest& r_;
  const kin::DofReport& dof_;
  KinFiles& files_;
  io::ReportStream stream_;
  KinRows rows_;
  bool begun_ = false;
  io::Report equations_;
  std::vector<std::string> cells_;
  std::optional<KinPlot> plot_;
  std::vector<KinPosition> frames_;
  std::optional<KinPosition> last_;
  long stride_ = 1, seen_ = 0;
};

int run_analysis(const mechanism::Mechanism& mech, const KinRequest& r, std::ostream& out) {
  const kin::DofReport dof = checked_mobility(mech, r.file);
  KinFiles files(out, r);
  KinWriter writer(mech, r, dof, files);
  kin::Data data(mech.model);
  if (!r.range) {
    const KinAnalysis a = analyse_single(mech, data, r.driver, r.at, dof);
    writer.plan(a.positions.empty() ? 0.0 : a.positions.front().input, a.positions.empty() ? 0.0 : a.positions.front().input, 1);
    for (const KinPosition& p : a.positions) writer.add(p);
    return writer.finish(a);
  }
  kin::SweepOptions planned;
  planned.start = r.range->start;
  planned.end = r.range->end;
  planned.step = r.range->step;
  writer.plan(r.range->start, r.range->end, kin::sweep_sample_count(planned));
  const KinAnalysis a = analyse_sweep(mech, data, r.driver, *r.range, dof, [&](const KinPosition& p) { writer.add(p); });
  return writer.finish(a);
}

io::po::options_description kin_options() {
  io::po::options_description desc("gearkit kin options");
  desc.add_options()("file", io::po::value<std::string>()->value_name("FILE.yaml"), "mechanism model (see docs/kin.md)")(
      "at", io::po::value<std::string>()->value_name("VALUE"), "analyse one position at this input (deg or mm by default)")(
      "sweep", io::po::value<std::string>()->value_name("START:END:STEP"), "sweep the driver over a range")(
      "driver", io::po::value<std::string>()->value_name("NAME"), "which driver --at/--sweep move (default: the first)")(
      "outputs", io::po::value<std::string>()->value_name("A,B,..."), "only these named outputs of the model")(
      "plot", io::po::value<std::string>()->value_name("FILE.svg"), "SVG plot of the outputs against the input")(
      "animate", io::po::value<std::string>()->value_name("FILE.svg"), "animated SVG of the mechanism through the sweep")(
      "equations", io::po::bool_switch(), "constraint equations, Jacobian, velocity and acceleration equations and "
      "velocity ratios in the coordinates of the file's equations: section (docs/kin.md)")(
      "example", io::po::value<std::string>()->value_name("chain:N"),
      "write a generated mechanism file instead of analysing one (chain:N: N four-bar loops)");
  io::add_common_options(desc);
  return desc;
}

}  // namespace

int run_kin_command(plugin::CommandContext& context) {
  const io::po::options_description desc = kin_options();
  io::po::positional_options_description positional;
  positional.add("file", 1);
  io::po::variables_map vm;
  const char* usage =
      "gearkit kin FILE.yaml [--at VALUE | --sweep START:END:STEP] [--driver NAME] [--outputs A,B] [--plot FILE] "
      "[--animate FILE] [--equations] [--format text|json|csv|md]";
  if (!io::parse_command_line(context.args, desc, positional, vm, usage, context.out)) return 0;
  KinRequest r;
  r.common = io::common_options(vm);
  if (vm.count("example")) {
    if (vm.count("file")) io::fail_option("--example", "expected no mechanism file with --example, found one");
    io::OutputSet outputs(context.out);
    outputs.add("--output", r.common.output, example_mechanism_yaml(vm["example"].as<std::string>()));
    outputs.commit();
    return 0;
  }
  if (!vm.count("file")) throw io::InputError(fmt::format("expected the FILE argument, found none; usage: {}", usage));
  if (vm.count("at") && vm.count("sweep")) io::fail_option("--at", "expected either --at or --sweep, found both");
  r.file = vm["file"].as<std::string>();
  mechanism::Mechanism mech =
      mechanism::load_mechanism(r.file, [&context](std::string_view type) { return context.host.find_element_type(type); });
  if (mech.drivers.empty())
    io::fail_at({r.file, 0, 0}, "expected at least one driver (an input angle or slider displacement), found none");
  r.driver = driver_named(mech, vm);
  choose_outputs(mech, vm);
  read_position_options(mech, vm, r);
  r.equations = vm["equations"].as<bool>();
  if (vm.count("plot")) r.plot = vm["plot"].as<std::string>();
  if (vm.count("animate")) r.animate = vm["animate"].as<std::string>();
  return run_analysis(mech, r, context.out);
}

}  // namespace gearkit::cli
