#include "kin_writer.hpp"
#include "kin_equations.hpp"
#include "kin_units.hpp"

#include <gearkit/io/error.hpp>
#include <gearkit/io/limits.hpp>
#include <gearkit/io/report_output.hpp>
#include <gearkit/kin/fourbar.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <system_error>

namespace gearkit::cli {

namespace {

constexpr long kAnimationFrames = 240;  // the browser interpolates between them
constexpr long kPipelinedSweep = 1000;  // positions from which rows are written on a second thread

// The report is rendered whole for an HTML page, and for a CSV of a table other than the
// positions (those come at the end of a sweep).
bool rendered_whole(const io::CommonOptions& c, const io::Table& positions) {
  if (c.format == io::Format::html) return true;
  if (c.table.empty() || c.table == "all") return false;
  return c.table != io::table_key(positions.title, 0) && c.table != "1";
}

}  // namespace

KinWriter::KinWriter(const mechanism::Mechanism& mech, const KinRequest& r, const kin::DofReport& dof, std::ostream& out,
                     std::ostream& err)
    : mech_(mech), r_(r), dof_(dof), err_(err), files_(out),
      rows_(mech, r.driver, kin::find_four_bar(mech.model).has_value(), mech.model.has_loads(), !r.range),
      summary_(mech, r.driver, r.min_transmission_angle) {
  if (r.common.format == io::Format::json && !r.common.table.empty())
    io::fail_option("--table", "expected no --table with --format json (it holds every table), found one");
  whole_ = rendered_whole(r.common, rows_.table());
  // A CSV of another table: the positions are not written, so none is kept (a sweep of a million
  // positions held them all) unless --table could still name them (a prefix of their key).
  positions_written_ = !(whole_ && r.common.format == io::Format::csv &&
                         io::table_key(rows_.table().title, 1).rfind(r.common.table, 0) != 0);
  if (whole_) {
    files_.reserve("--output", r.common.output);
    whole_rows_ = rows_.table();
    whole_writer_.set_path_prefix("positions[]");
    skipped_writer_.set_path_prefix("positions[]");
  } else {
    stream_.emplace(files_.stream("--output", r.common.output), r.common.format);
    stream_->set_csv_streamed_table_only(r.common.format == io::Format::csv && r.common.table != "all");
  }
  if (r.plot) files_.reserve("--plot", *r.plot);
  if (r.animate) files_.reserve("--animate", *r.animate);
  coupler_points_ = reserve_coupler_outputs(*r.vm, mech.model, files_);
}

void KinWriter::plan(double first, double last, long count) {
  stride_ = std::max(1L, (count + kAnimationFrames - 1) / kAnimationFrames);
  if (whole_ && r_.common.format == io::Format::html)
    html_stride_ = std::max(1L, (count + io::limits::kHtmlTableRows - 1) / io::limits::kHtmlTableRows);
  if (r_.plot) plot_.emplace(mech_, r_.driver, shown_input(mech_, r_.driver, first), shown_input(mech_, r_.driver, last), count);
  if (coupler_points_) coupler_.emplace(*coupler_points_, count);
  // A long streamed sweep writes its rows on a second thread (kin_row_pipeline.hpp); a short one
  // is not worth the thread's start. Where no thread can be had (address-space limit), the rows
  // are written here as before.
  if (whole_ || count < kPipelinedSweep) return;
  try {
    rows_thread_.emplace([this](const KinPosition& p) { write_row(p); });
  } catch (const std::system_error&) {
    rows_thread_.reset();
  }
}

void KinWriter::begin(const KinPosition* first) {
  // The equations are written at the first position, before anything is printed: a malformed
  // equations: section of the file is refused with nothing on standard output.
  if (r_.equations) {
    KinAnalysis at_first;
    at_first.driver = r_.driver;
    at_first.dof = dof_;
    if (first) at_first.positions.push_back(*first);
    add_equations_section_from_module(equations_, mech_, at_first, r_.common.format);
  }
  if (stream_) stream_->begin(kin_report_head(mech_, dof_, r_.driver), rows_.table(), "positions");
  begun_ = true;
}

void KinWriter::write_row(const KinPosition& p) {
  ++written_;
  if (whole_) {
    if (!positions_written_ || (written_ - 1) % html_stride_ != 0) {
      // Not on the page, but a non-finite value in it is still a warning: its JSON is written
      // (and dropped) for the writer to remember the paths of such values.
      skipped_json_.clear();
      rows_.json(p, skipped_writer_);
      return;
    }
    whole_json_ += whole_json_.empty() ? "[" : ",";
    rows_.json(p, whole_writer_);
    rows_.cells(p, cells_);
    whole_rows_.add_row(cells_);
  } else if (stream_->format() == io::Format::json) {
    rows_.json(p, stream_->begin_json_row());
    stream_->end_json_row();
  } else {
    rows_.cells(p, cells_);
    stream_->add_cells(cells_);
  }
}

void KinWriter::add(const KinPosition& p) {
  if (!begun_) begin(&p);
  note_undefined_rates(p);
  summary_.add(p);
  ++seen_positions_;
  if (rows_thread_)
    rows_thread_->push(p);
  else
    write_row(p);
  if (plot_) plot_->add(p);
  if (coupler_) coupler_->add(p);
  if (!r_.animate) return;
  if (seen_++ % stride_ == 0) {
    frames_.push_back(p);
    last_.reset();
  } else {
    last_ = p;
  }
}

// The rate of a speed output, d|v|/dt = v.a/|v|, has no value where the point stands still (a
// point of the ground, or a dead point): JSON shows null, the text table has no rate column, so
// every format says so by a warning (issue 26, section 3).
// Likewise a sweep through positions where friction wedges the mechanism: the effort is null in
// JSON and "wedged" in the table, and the one-position report's warning becomes a count.
void KinWriter::note_undefined_rates(const KinPosition& p) {
  if (undefined_rates_.empty()) undefined_rates_.assign(mech_.outputs.size(), 0);
  for (std::size_t k = 0; k < mech_.outputs.size() && k < p.outputs.size(); ++k)
    if (mech_.outputs[k].kind == kin::OutputKind::point_speed && !std::isfinite(p.outputs[k].rate)) ++undefined_rates_[k];
  if (r_.range && p.forces && p.forces->friction && p.forces->friction->forward.wedged && wedged_++ == 0)
    first_wedged_ = p.input;
}

io::Report KinWriter::tail_of(const KinAnalysis& a) {
  io::Report tail;
  summary_.write(a, tail);  // first: the summary follows the positions
  io::Report rest = kin_report_tail(mech_, a);
  for (io::Table& t : rest.tables) tail.tables.push_back(std::move(t));
  tail.notes = std::move(rest.notes);
  tail.warnings.insert(tail.warnings.begin(), rest.warnings.begin(), rest.warnings.end());
  for (const auto& [key, value] : rest.json.items()) tail.json[key] = value;
  for (std::size_t k = 0; k < undefined_rates_.size(); ++k)
    if (undefined_rates_[k] > 0)
      tail.warnings.push_back(fmt::format("output {}: the point stands still at {} of {} positions, where the rate of its "
                                          "speed (d|v|/dt) is undefined (null in JSON)",
                                          io::quote(mech_.outputs[k].name), undefined_rates_[k], seen_positions_));
  if (wedged_ > 0)
    tail.warnings.push_back(fmt::format("wedged (self-locking) at {} of {} positions, the first at {:.6g} {}: no finite "
                                        "driving effort moves the mechanism in the analysed sense there (the effort is "
                                        "'wedged' in the table, null in JSON)",
                                        wedged_, seen_positions_, shown_input(mech_, r_.driver, first_wedged_),
                                        input_unit(mech_, r_.driver)));
  for (io::Table& t : equations_.tables) tail.tables.push_back(std::move(t));
  tail.notes.insert(tail.notes.end(), equations_.notes.begin(), equations_.notes.end());
  tail.warnings.insert(tail.warnings.end(), equations_.warnings.begin(), equations_.warnings.end());
  for (const auto& [key, value] : equations_.json.items()) tail.json[key] = value;
  return tail;
}

void KinWriter::fill_pictures(const KinAnalysis& a, io::Report& tail) {
  if (r_.plot) {
    if (written_ == 0) {
      tail.warnings.push_back("no positions to plot; --plot file not written");
    } else {
      std::vector<io::PlotMark> marks;
      for (const kin::DeadPoint& d : a.dead_points)
        marks.push_back({shown_input(mech_, a.driver, d.input),
                         fmt::format("dead point at {:.4g} {}: the sweep stops{}", shown_input(mech_, a.driver, d.input),
                                     input_unit(mech_, a.driver), mech_.model.has_loads() ? " (effort unbounded: not plotted)" : "")});
      for (const kin::ChangePoint& c : a.change_points)
        marks.push_back({shown_input(mech_, a.driver, c.input),
                         fmt::format("change point at {:.4g} {}: branches cross", shown_input(mech_, a.driver, c.input),
                                     input_unit(mech_, a.driver))});
      files_.fill("--plot", plot_->svg(marks));
    }
  }
  if (r_.animate) {
    if (written_ == 0) {
      tail.warnings.push_back("no positions to animate; --animate file not written");
    } else {
      KinAnalysis frames = a;
      frames.positions = std::move(frames_);
      if (last_) frames.positions.push_back(*last_);
      files_.fill("--animate", animation_svg(mech_, frames, r_.speed));
    }
  }
  if (coupler_) {
    coupler_->finish();
    fill_coupler_outputs(*r_.vm, mech_, r_.driver, *coupler_, tail, files_);
  }
}

int KinWriter::finish_whole(io::Report tail) {
  io::Report whole = kin_report_head(mech_, dof_, r_.driver);
  const std::size_t shown = whole_rows_.rows.size();
  whole.tables.push_back(std::move(whole_rows_));
  for (io::Table& t : tail.tables) whole.tables.push_back(std::move(t));
  whole.notes.insert(whole.notes.end(), tail.notes.begin(), tail.notes.end());
  whole.warnings.insert(whole.warnings.end(), tail.warnings.begin(), tail.warnings.end());
  for (const auto& [key, value] : tail.json.items()) whole.json[key] = value;
  whole.json["positions"] = nlohmann::json::parse(whole_json_.empty() ? std::string("[]") : whole_json_ + "]");
  if (html_stride_ > 1) {
    whole.json["positions_shown_every"] = html_stride_;
    whole.json["positions_swept"] = written_;
    whole.notes.push_back(fmt::format("The positions table shows one position in {} ({} of the {} positions swept, from "
                                      "the first; a page holds at most {}): the warnings, dead points and extremes are of "
                                      "every position, and --format csv or json writes them all.",
                                      html_stride_, shown, written_, io::limits::kHtmlTableRows));
  }
  // The positions' JSON was written as text: its non-finite values are nulls there already.
  std::vector<std::string> names = io::non_finite_quantities(whole);
  for (const io::JsonWriter* w : {&whole_writer_, &skipped_writer_})
    for (const std::string& p : w->non_finite_paths())
      if (std::find(names.begin(), names.end(), "'" + p + "'") == names.end()) names.push_back("'" + p + "'");
  for (std::string& w : io::non_finite_warnings(names)) whole.warnings.push_back(std::move(w));
  files_.fill("--output", io::render_for_output(whole, r_.common, files_));
  files_.commit();
  io::print_moved_warnings(whole, r_.common, err_);
  return io::exit_status(whole, r_.common);
}

int KinWriter::finish(const KinAnalysis& a) {
  if (rows_thread_) rows_thread_->finish();
  if (!begun_) begin(nullptr);
  io::Report tail = tail_of(a);
  fill_pictures(a, tail);
  if (whole_) return finish_whole(std::move(tail));
  const std::vector<std::string> warnings = stream_->finish(tail);
  files_.commit();
  if (r_.common.format == io::Format::csv && r_.common.table != "all") {
    // The CSV holds the positions alone; the report's warnings go to stderr, one line each. The
    // names of the other tables only when the user chose neither a table nor a file: with
    // --table or --output FILE the positions CSV is what was asked for (issue 25).
    std::vector<std::string> left_out;
    for (std::size_t i = 0; i < tail.tables.size(); ++i) left_out.push_back(io::table_key(tail.tables[i].title, i + 2));
    for (const std::string& w : warnings) err_ << "gearkit: warning: " << w << "\n";
    if (!left_out.empty() && r_.common.table.empty() && r_.common.output == "-")
      err_ << fmt::format("gearkit: warning: the CSV holds the positions; the other tables ({}) with --table NAME\n",
                          fmt::join(left_out, ", "));
  }
  return r_.common.strict && !warnings.empty() ? 3 : 0;
}

}  // namespace gearkit::cli
