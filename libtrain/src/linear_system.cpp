#include <gearkit/train/linear_system.hpp>

#include <algorithm>
#include <functional>
#include <queue>
#include <stdexcept>

namespace gearkit::train {

EchelonSystem::EchelonSystem(std::size_t unknowns, std::size_t parameters, std::vector<long long> preference)
    : unknowns_(unknowns), parameters_(parameters), preference_(std::move(preference)),
      order_of_column_(unknowns + parameters, -1) {
  if (preference_.size() != unknowns_) throw std::invalid_argument("EchelonSystem: one preference per unknown");
}

namespace {

// Rows of a gear train have a handful of entries, so a small unsorted vector with linear search
// beats a tree; entries never move, so pointers stay valid until the next insertion.
Rational& entry(SparseRow& row, std::size_t column) {
  for (auto& [c, v] : row)
    if (c == column) return v;
  row.emplace_back(column, Rational());
  return row.back().second;
}

}  // namespace

EchelonSystem::AddResult EchelonSystem::add_row(const SparseRow& row) {
  // Pivot rows are subtracted in creation order (a min-heap of pending rows): row k holds no pivot
  // of an earlier row, so subtracting in that order never reintroduces a column already cleared.
  SparseRow work;
  work.reserve(row.size() + 4);
  std::priority_queue<long long, std::vector<long long>, std::greater<>> pending;
  std::vector<long long> queued;
  const auto note = [&](std::size_t column) {
    const long long order = order_of_column_[column];
    if (order >= 0 && std::find(queued.begin(), queued.end(), order) == queued.end()) {
      queued.push_back(order);
      pending.push(order);
    }
  };
  for (const auto& [column, value] : row) {
    if (column >= unknowns_ + parameters_) throw std::out_of_range("EchelonSystem::add_row: column out of range");
    entry(work, column) += value;
    note(column);
  }
  while (!pending.empty()) {
    const auto k = static_cast<std::size_t>(pending.top());
    pending.pop();
    const Rational factor = entry(work, pivots_[k]);
    if (factor.is_zero()) continue;
    for (const auto& [column, value] : rows_[k]) {
      if (column == pivots_[k]) {
        entry(work, column) = 0;  // exact by construction: the pivot coefficient is 1
      } else {
        entry(work, column) -= factor * value;
        note(column);
      }
    }
  }

  SparseRow reduced;
  std::optional<std::size_t> pivot;
  bool has_parameter = false;
  for (auto& [column, value] : work) {
    if (value.is_zero()) continue;
    if (column < unknowns_) {
      if (!pivot || preference_[column] > preference_[*pivot]) pivot = column;
    } else {
      has_parameter = true;
    }
    reduced.emplace_back(column, std::move(value));
  }
  if (!pivot) return AddResult{has_parameter ? RowStatus::inconsistent : RowStatus::redundant, std::nullopt};

  std::sort(reduced.begin(), reduced.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  const Rational scale = entry(reduced, *pivot);
  if (scale != 1)
    for (auto& e : reduced) e.second /= scale;
  order_of_column_[*pivot] = static_cast<long long>(pivots_.size());
  pivots_.push_back(*pivot);
  rows_.push_back(std::move(reduced));
  return AddResult{RowStatus::independent, pivot};
}

std::vector<std::size_t> EchelonSystem::free_unknowns() const {
  std::vector<std::size_t> result;
  for (std::size_t c = 0; c < unknowns_; ++c)
    if (order_of_column_[c] < 0) result.push_back(c);
  return result;
}

std::vector<SparseRow> EchelonSystem::solve() const {
  std::vector<SparseRow> expression(unknowns_);
  for (std::size_t c = 0; c < unknowns_; ++c)
    if (order_of_column_[c] < 0) expression[c] = SparseRow{{c, Rational(1)}};
  // Back substitution: row k mentions only free unknowns, parameters and pivots of later rows.
  for (std::size_t k = pivots_.size(); k-- > 0;) {
    SparseRow sum;
    for (const auto& [column, value] : rows_[k]) {
      if (column == pivots_[k]) continue;
      if (column >= unknowns_) {
        entry(sum, column) -= value;
      } else {
        for (const auto& [inner, inner_value] : expression[column]) entry(sum, inner) -= value * inner_value;
      }
    }
    SparseRow result;
    for (auto& [column, value] : sum)
      if (!value.is_zero()) result.emplace_back(column, std::move(value));
    std::sort(result.begin(), result.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    expression[pivots_[k]] = std::move(result);
  }
  return expression;
}

}  // namespace gearkit::train
