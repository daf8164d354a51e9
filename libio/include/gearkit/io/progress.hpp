#pragma once
// A progress bar for long sweeps: drawn on stderr only when stdout is a terminal, so that
// piped or redirected output (and tests) stay clean.
#include <chrono>
#include <cstddef>
#include <string>

namespace gearkit::io {

class Progress {
 public:
  /// @param label shown before the bar, e.g. "sweep"
  /// @param total number of steps; 0 disables the bar
  Progress(std::string label, std::size_t total);
  ~Progress();  ///< clears the bar
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// Reports `done` steps completed; redraws at most every 100 ms.
  void update(std::size_t done);
  bool enabled() const { return enabled_; }

 private:
  void draw(std::size_t done);
  std::string label_;
  std::size_t total_;
  bool enabled_;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace gearkit::io
