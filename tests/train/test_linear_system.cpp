#include <gearkit/train/linear_system.hpp>

#include <gtest/gtest.h>

namespace gearkit::train {
namespace {

SparseRow row(std::initializer_list<std::pair<std::size_t, long long>> entries) {
  SparseRow r;
  for (const auto& [c, v] : entries) r.emplace_back(c, Rational(v));
  return r;
}

// x0 + x1 = p, x0 - x1 = 0 -> x0 = x1 = p/2 (solved by hand).
TEST(EchelonSystem, SolvesWithParameters) {
  EchelonSystem s(2, 1, {0, 1});
  EXPECT_EQ(s.add_row(row({{0, 1}, {1, 1}, {2, -1}})).status, EchelonSystem::RowStatus::independent);
  EXPECT_EQ(s.add_row(row({{0, 1}, {1, -1}})).status, EchelonSystem::RowStatus::independent);
  const auto x = s.solve();
  ASSERT_EQ(x[0].size(), 1u);
  EXPECT_EQ(x[0][0].first, 2u);
  EXPECT_EQ(x[0][0].second, Rational(1, 2));
  EXPECT_EQ(x[1][0].second, Rational(1, 2));
  EXPECT_TRUE(s.free_unknowns().empty());
}

TEST(EchelonSystem, ClassifiesRedundantAndInconsistentRows) {
  EchelonSystem s(2, 1, {0, 1});
  s.add_row(row({{0, 2}, {1, 4}}));
  EXPECT_EQ(s.add_row(row({{0, 1}, {1, 2}})).status, EchelonSystem::RowStatus::redundant);
  EXPECT_EQ(s.add_row(row({{0, 3}, {1, 6}, {2, 1}})).status, EchelonSystem::RowStatus::inconsistent);
  EXPECT_EQ(s.rank(), 1u);
}

TEST(EchelonSystem, PreferenceChoosesThePivotAndLeavesTheRestFree) {
  EchelonSystem s(3, 0, {5, 1, 3});
  const auto r = s.add_row(row({{0, 1}, {1, 1}, {2, 1}}));
  EXPECT_EQ(r.pivot.value(), 0u);
  EXPECT_EQ(s.free_unknowns(), (std::vector<std::size_t>{1, 2}));
  const auto x = s.solve();
  // x0 = -x1 - x2
  ASSERT_EQ(x[0].size(), 2u);
  EXPECT_EQ(x[0][0], (std::pair<std::size_t, Rational>{1, Rational(-1)}));
  EXPECT_EQ(x[0][1], (std::pair<std::size_t, Rational>{2, Rational(-1)}));
}

// Numbers far beyond 64 bits stay exact: a chain x_{k+1} = (97/89) x_k over 200 unknowns.
TEST(EchelonSystem, NoOverflowOnLongChains) {
  const std::size_t n = 200;
  std::vector<long long> preference(n);
  for (std::size_t i = 0; i < n; ++i) preference[i] = static_cast<long long>(i);
  EchelonSystem s(n, 1, preference);
  s.add_row(row({{0, 1}, {n, -1}}));
  for (std::size_t k = 0; k + 1 < n; ++k) s.add_row(row({{k + 1, 89}, {k, -97}}));
  const auto x = s.solve();
  Rational expected(1);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    expected *= 97;
    expected /= 89;
  }
  EXPECT_EQ(x[n - 1][0].second, expected);
  EXPECT_GT(boost::multiprecision::msb(Integer(boost::multiprecision::numerator(expected))), 1000u);
}

TEST(EchelonSystem, RejectsBadColumnsAndPreferences) {
  EXPECT_THROW(EchelonSystem(2, 0, {0}), std::invalid_argument);
  EchelonSystem s(2, 0, {0, 1});
  EXPECT_THROW(s.add_row(row({{5, 1}})), std::out_of_range);
}

}  // namespace
}  // namespace gearkit::train
