#pragma once
// Exact sparse Gaussian elimination, used for the speeds (Willis equations plus conditions) and
// for the torques (member equilibrium). Rows are added one at a time and reduced against the rows
// already accepted, so each new row is classified on arrival: independent, redundant (a
// consequence of the others) or inconsistent (contradicts them). That is what lets a command say
// which condition over-determines a train. Columns [0, unknowns) are unknowns; columns from
// `unknowns` on are parameters (input speeds, a given torque) that are never eliminated, so the
// solution is each unknown as an exact linear combination of parameters and free unknowns.
#include <gearkit/train/rational.hpp>

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace gearkit::train {

/// A sparse row: (column, coefficient) sorted by column, no zero coefficients.
using SparseRow = std::vector<std::pair<std::size_t, Rational>>;

class EchelonSystem {
 public:
  enum class RowStatus { independent, redundant, inconsistent };
  struct AddResult {
    RowStatus status = RowStatus::redundant;
    std::optional<std::size_t> pivot;  ///< the unknown this row determines (independent rows only)
  };

  /// @param unknowns number of unknown columns.
  /// @param parameters number of parameter columns after them.
  /// @param preference one value per unknown: a new row pivots on its unknown with the highest
  ///        preference, so unknowns with low preference are the ones left free.
  /// @throws std::invalid_argument if preference.size() != unknowns.
  EchelonSystem(std::size_t unknowns, std::size_t parameters, std::vector<long long> preference);

  /// Adds `row` (columns < unknowns + parameters, any order, duplicates summed).
  /// Redundant and inconsistent rows are not kept.
  /// @throws std::out_of_range for a column beyond the last parameter.
  AddResult add_row(const SparseRow& row);

  std::size_t unknowns() const { return unknowns_; }
  std::size_t parameters() const { return parameters_; }
  std::size_t rank() const { return pivots_.size(); }
  /// Unknowns that no row determines, ascending.
  std::vector<std::size_t> free_unknowns() const;

  /// Every unknown as a combination of free unknowns (coefficient 1 on itself) and parameters.
  std::vector<SparseRow> solve() const;

 private:
  std::size_t unknowns_;
  std::size_t parameters_;
  std::vector<long long> preference_;
  std::vector<std::size_t> pivots_;     // pivot column of each kept row, in creation order
  std::vector<SparseRow> rows_;         // kept rows, pivot coefficient 1
  std::vector<long long> order_of_column_;  // creation index of the row pivoting on the column, or -1
};

}  // namespace gearkit::train
