#include "kin_row_pipeline.hpp"

#include <utility>

namespace gearkit::cli {

RowPipeline::RowPipeline(Write write, std::size_t batch)
    : write_(std::move(write)), filling_(batch), writing_(batch), thread_([this] { run(); }) {}

RowPipeline::~RowPipeline() { stop(); }

void RowPipeline::stop() {
  if (!thread_.joinable()) return;
  {
    const std::lock_guard lock(mutex_);
    done_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void RowPipeline::run() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [this] { return full_ || done_; });
    if (!full_) return;
    lock.unlock();
    std::exception_ptr error;
    try {
      for (std::size_t i = 0; i < to_write_; ++i) write_(writing_[i]);
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    full_ = false;
    error_ = error;
    changed_.notify_all();
    if (error) return;  // the caller rethrows it at its next hand-over
  }
}

void RowPipeline::hand_over() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [this] { return !full_; });
  if (error_) std::rethrow_exception(error_);
  std::swap(filling_, writing_);
  to_write_ = filled_;
  filled_ = 0;
  full_ = true;
  lock.unlock();
  changed_.notify_all();
}

void RowPipeline::push(const KinPosition& p) {
  filling_[filled_++] = p;
  if (filled_ == filling_.size()) hand_over();
}

void RowPipeline::finish() {
  if (filled_ > 0) hand_over();
  {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return !full_; });
  }
  stop();
  if (error_) std::rethrow_exception(error_);
}

}  // namespace gearkit::cli
