#pragma once
// `gearkit kin`: where the positions go as they are solved. Most reports stream (text, Markdown,
// JSON, CSV of the positions table): rows leave as they come and memory does not grow with the
// sweep. An HTML page, or a CSV of another table (--table), is rendered whole at the end; a page
// keeps at most io::limits::kHtmlTableRows positions (every k-th of a longer sweep), so that its
// memory and size do not grow with the sweep either.
#include "kin_analysis.hpp"
#include "kin_coupler.hpp"
#include "kin_plot.hpp"
#include "kin_report.hpp"
#include "kin_row_pipeline.hpp"
#include "kin_summary.hpp"

#include <gearkit/io/command_line.hpp>
#include <gearkit/io/output.hpp>
#include <gearkit/io/report_stream.hpp>

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace gearkit::cli {

/// What the command line asks for, once checked.
struct KinRequest {
  std::string file;
  int driver = 0;
  std::optional<double> at;
  std::optional<mechanism::DriverRange> range;
  bool equations = false;
  std::optional<std::string> plot, animate;
  std::optional<double> speed;  ///< --speed, SI, for the animation's loop time
  bool switch_branch = false;   ///< --branch switch: the other branch at each change point
  double min_transmission_angle = kDefaultMinTransmissionAngle;  ///< --min-transmission-angle [rad]
  io::CommonOptions common;
  const io::po::variables_map* vm = nullptr;  ///< for the coupler-curve options
};

class KinWriter {
 public:
  /// Checks and claims every destination (report, plot, animation, coupler files) before the
  /// first position, so that nothing is printed before a bad one is refused.
  /// @throws io::InputError for a bad destination, --table or --coupler.
  KinWriter(const mechanism::Mechanism& mech, const KinRequest& r, const kin::DofReport& dof, std::ostream& out,
            std::ostream& err);

  /// The sweep's input range and planned number of positions (plot columns, animation frames).
  void plan(double first, double last, long count);
  void add(const KinPosition& p);
  /// The rest of the report and the files, all committed together. @returns the exit status.
  int finish(const KinAnalysis& a);

 private:
  void begin(const KinPosition* first);
  void write_row(const KinPosition& p);
  io::Report tail_of(const KinAnalysis& a);
  void fill_pictures(const KinAnalysis& a, io::Report& tail);
  int finish_whole(io::Report tail);
  void note_undefined_rates(const KinPosition& p);

  const mechanism::Mechanism& mech_;
  const KinRequest& r_;
  const kin::DofReport& dof_;
  std::ostream& err_;
  io::OutputSet files_;
  bool whole_ = false;  // render the report at the end (HTML, CSV of another table)
  std::optional<io::ReportStream> stream_;
  KinRows rows_;
  KinSummary summary_;
  bool begun_ = false;
  long written_ = 0;
  io::Report equations_;
  std::vector<std::string> cells_;
  io::Table whole_rows_;      // whole_: the positions table
  std::string whole_json_;    // whole_: the positions as a JSON array, "[...]"
  io::JsonWriter whole_writer_{whole_json_};
  std::string skipped_json_;  // whole_ HTML: a position left off the page, as JSON, for its non-finite values
  io::JsonWriter skipped_writer_{skipped_json_};
  std::optional<KinPlot> plot_;
  std::optional<std::vector<CouplerPoint>> coupler_points_;
  std::optional<CouplerPaths> coupler_;
  std::vector<KinPosition> frames_;
  std::optional<KinPosition> last_;
  long stride_ = 1, seen_ = 0;
  long html_stride_ = 1;  // whole_ HTML: every html_stride_-th position is on the page
  bool positions_written_ = true;  // false: a CSV of another table, the positions' rows are not kept
  std::vector<long> undefined_rates_;  // per output: positions where a speed's rate is undefined
  long seen_positions_ = 0;
  long wedged_ = 0;          // positions of a sweep where friction wedges the mechanism
  double first_wedged_ = 0;  // the input of the first one
  std::optional<RowPipeline> rows_thread_;  // last: stopped before the stream it writes to goes
};

}  // namespace gearkit::cli
