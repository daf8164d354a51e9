#pragma once
// `gearkit kin`: the rows of a long sweep written on a second thread. Writing a position (in JSON,
// 41 numbers in their shortest round-trip form and their keys) costs about as much as solving it;
// with the rows of one batch written while the next batch is solved, a sweep on two cores takes
// the longer of the two instead of their sum. Rows keep their order: batches are handed over
// whole, one at a time, and only the pipeline's thread writes rows once it has started.
#include "kin_analysis.hpp"

#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace gearkit::cli {

class RowPipeline {
 public:
  using Write = std::function<void(const KinPosition&)>;

  /// Starts the writing thread. `write` is called there on every position, in order; it must not
  /// touch what the calling thread changes until finish() returns.
  /// @param batch positions per hand-over (> 0).
  explicit RowPipeline(Write write, std::size_t batch = 256);
  /// Stops the thread. Positions not handed over are dropped (the writer is unwinding an error).
  ~RowPipeline();
  RowPipeline(const RowPipeline&) = delete;
  RowPipeline& operator=(const RowPipeline&) = delete;

  /// Copies `p` into the batch being filled (reusing its storage) and hands the batch over when
  /// it is full. @throws what `write` threw on an earlier position.
  void push(const KinPosition& p);
  /// Writes what is left and waits for the thread. @throws what `write` threw.
  void finish();

 private:
  void run();
  void hand_over();
  void stop();

  Write write_;
  std::vector<KinPosition> filling_, writing_;
  std::size_t filled_ = 0, to_write_ = 0;
  std::mutex mutex_;
  std::condition_variable changed_;
  bool full_ = false;  // writing_ holds to_write_ positions the thread has not written yet
  bool done_ = false;  // no batch will follow
  std::exception_ptr error_;
  std::thread thread_;
};

}  // namespace gearkit::cli
