#pragma once
// `gearkit kin`: the report, in three parts so that a sweep can be streamed: the head (known
// before the first position), one row per position, the tail (dead points, limit positions,
// the single position's reactions and instant centres, warnings).
#include "kin_analysis.hpp"

#include <gearkit/io/json_writer.hpp>
#include <gearkit/io/report.hpp>

#include <string>
#include <vector>

namespace gearkit::cli {

/// Title, notes (Gruebler, rank, Grashof) and the JSON keys known before the first position.
io::Report kin_report_head(const mechanism::Mechanism& mech, const kin::DofReport& dof, int driver);

/// One position as a table row and as a JSON object. Its keys and headers are built once.
class KinRows {
 public:
  /// @param transmission, forces whether positions carry a transmission angle / forces.
  KinRows(const mechanism::Mechanism& mech, int driver, bool transmission, bool forces, bool single);

  /// The positions table without rows: title and header.
  const io::Table& table() const { return table_; }
  /// The cells of one position (reuses `cells`' storage).
  void cells(const KinPosition& p, std::vector<std::string>& cells) const;
  /// One position as a JSON object.
  void json(const KinPosition& p, io::JsonWriter& w) const;

 private:
  void coordinates_json(const Eigen::VectorXd& v, int order, io::JsonWriter& w) const;
  void forces_json(const KinPosition& p, io::JsonWriter& w) const;

  const mechanism::Mechanism& mech_;
  int driver_;
  io::Table table_;
  std::vector<bool> output_in_table_;  // false for an output that repeats the driver's column
  std::vector<io::JsonKey> coordinate_keys_[3];  // per coordinate: "crank.x_mm", "crank.vx_mm_s"...
  struct OutputKeys {
    io::JsonKey value, rate, acceleration, ratio;
    bool has_rate, has_acceleration, has_ratio;
  };
  std::vector<OutputKeys> output_keys_;
  io::JsonKey input_key_{""}, effort_key_{""}, lagrange_key_{""};
};

/// Dead points, limit positions, the single position's reactions, two-force members and instant
/// centres, and the analysis' warnings.
io::Report kin_report_tail(const mechanism::Mechanism& mech, const KinAnalysis& a);

}  // namespace gearkit::cli
