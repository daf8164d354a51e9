#include <gearkit/io/progress.hpp>

#include <fmt/format.h>

#include <cstdio>
#include <unistd.h>

namespace gearkit::io {

Progress::Progress(std::string label, std::size_t total)
    : label_(std::move(label)), total_(total), enabled_(total > 0 && ::isatty(STDOUT_FILENO) && ::isatty(STDERR_FILENO)),
      last_() {}

Progress::~Progress() {
  if (enabled_) std::fputs("\r\033[K", stderr);
}

void Progress::update(std::size_t done) {
  if (!enabled_) return;
  auto now = std::chrono::steady_clock::now();
  if (done < total_ && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  draw(done);
}

void Progress::draw(std::size_t done) {
  constexpr int width = 40;
  double f = total_ ? static_cast<double>(done) / static_cast<double>(total_) : 1.0;
  int filled = static_cast<int>(f * width + 0.5);
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.resize(width, '.');
  std::fputs(fmt::format("\r{} [{}] {:3.0f}%", label_, bar, 100 * f).c_str(), stderr);
  std::fflush(stderr);
}

}  // namespace gearkit::io
