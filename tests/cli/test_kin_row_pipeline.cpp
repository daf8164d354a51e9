// cli/kin_row_pipeline.hpp: a long sweep's rows written on a second thread must arrive whole, in
// order, on that thread, and a writer's error must reach the caller; the whole `gearkit kin`
// report of a sweep long enough to use the thread must hold the same rows, in the same order, as
// the reports of shorter sweeps written without it.
#include "kin_row_pipeline.hpp"
#include "run_gearkit.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace gearkit::cli {
namespace {

KinPosition position(int i) {
  KinPosition p;
  p.input = i;
  p.q = Eigen::VectorXd::Constant(3 + i % 5, i);  // sizes change, so storage is reused and regrown
  p.outputs.resize(static_cast<std::size_t>(i % 3));
  return p;
}

TEST(RowPipeline, WritesEveryPositionInOrderOnItsOwnThread) {
  std::vector<double> inputs;
  std::vector<double> q_sums;
  bool on_caller_thread = false;
  const std::thread::id caller = std::this_thread::get_id();
  RowPipeline rows(
      [&](const KinPosition& p) {
        on_caller_thread = on_caller_thread || std::this_thread::get_id() == caller;
        inputs.push_back(p.input);
        q_sums.push_back(p.q.sum());
      },
      7);
  constexpr int kCount = 10000;  // not a multiple of the batch: the last batch is partial
  for (int i = 0; i < kCount; ++i) rows.push(position(i));
  rows.finish();
  ASSERT_EQ(inputs.size(), static_cast<std::size_t>(kCount));
  for (int i = 0; i < kCount; ++i) {
    EXPECT_EQ(inputs[static_cast<std::size_t>(i)], i);
    EXPECT_EQ(q_sums[static_cast<std::size_t>(i)], static_cast<double>(i) * (3 + i % 5));
  }
  EXPECT_FALSE(on_caller_thread);
}

TEST(RowPipeline, AWritersErrorReachesTheCallerAndStopsTheWriting) {
  int written = 0;
  RowPipeline rows(
      [&](const KinPosition& p) {
        if (p.input == 50) throw std::runtime_error("cannot write to standard output");
        ++written;
      },
      8);
  bool thrown = false;
  try {
    for (int i = 0; i < 1000; ++i) rows.push(position(i));
    rows.finish();
  } catch (const std::runtime_error& e) {
    thrown = true;
    EXPECT_STREQ(e.what(), "cannot write to standard output");
  }
  EXPECT_TRUE(thrown);
  EXPECT_EQ(written, 50);  // positions 0..49; none after the failed one
}

TEST(RowPipeline, StopsWithoutFinishWhenTheCallerUnwinds) {
  int written = 0;
  {
    RowPipeline rows([&](const KinPosition&) { ++written; }, 4);
    for (int i = 0; i < 10; ++i) rows.push(position(i));  // two batches handed over, two kept
  }  // no finish(): the destructor must stop the thread, not hang
  EXPECT_EQ(written, 8);
}

TEST(RowPipeline, ALongSweepHoldsTheRowsOfTheShortSweepsWrittenWithoutIt) {
  // 1000 positions use the writing thread (kin_writer.cpp, kPipelinedSweep); 999 and 2 do not.
  // The sweep's positions do not depend on where it ends, so the rows must agree, in order.
  const auto positions = [](const std::string& sweep) {
    const testing::RunResult r =
        testing::run_gearkit("kin " + testing::shell_quote(std::string(GEARKIT_SOURCE_DIR) + "/examples/mechanisms/four_bar.yaml") +
                             " --sweep " + sweep + " --format json");
    EXPECT_EQ(r.status, 0) << r.err;
    return nlohmann::json::parse(r.out).at("positions");
  };
  const nlohmann::json threaded = positions("0:99.9:0.1");
  const nlohmann::json direct = positions("0:99.8:0.1");
  ASSERT_EQ(threaded.size(), 1000u);
  ASSERT_EQ(direct.size(), 999u);
  for (std::size_t i = 0; i < direct.size(); ++i) ASSERT_EQ(threaded[i], direct[i]) << "position " << i;
  EXPECT_DOUBLE_EQ(threaded[999].at("input_deg").get<double>(), 99.9);
}

}  // namespace
}  // namespace gearkit::cli
