// A fixed table of temporary paths that a signal handler may read at any moment. Only
// async-signal-safe operations happen in the handler (atomic loads, unlink, sigaction, raise),
// so the table is static (no allocation) and each slot is published with an atomic state.
#include "temporary_registry.hpp"

#include <gearkit/io/output.hpp>

#include <atomic>
#include <cerrno>
#include <climits>
#include <cstring>
#include <signal.h>
#include <unistd.h>

namespace gearkit::io {

namespace detail {

namespace {

enum State : int { kFree = 0, kWriting = 1, kReady = 2 };

struct Slot {
  std::atomic<int> state{kFree};
  char path[PATH_MAX];
};

// 32 outputs at once is far more than any command writes (demo, the largest, writes 6).
constexpr int kSlots = 32;
Slot slots[kSlots];

static_assert(std::atomic<int>::is_always_lock_free, "the signal handler reads the slots");

}  // namespace

int remember_temporary(const char* path) noexcept {
  const std::size_t n = std::strlen(path);
  if (n >= PATH_MAX) return -1;
  for (int i = 0; i < kSlots; ++i) {
    int expected = kFree;
    if (!slots[i].state.compare_exchange_strong(expected, kWriting)) continue;
    std::memcpy(slots[i].path, path, n + 1);
    slots[i].state.store(kReady);
    return i;
  }
  return -1;
}

void forget_temporary(int slot) noexcept {
  if (slot >= 0 && slot < kSlots) slots[slot].state.store(kFree);
}

namespace {

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};

/// Removes every remembered temporary, then dies of the same signal (default action), so the
/// parent sees the signal as the cause (a shell shows 130 for SIGINT, 141 for SIGPIPE).
void remove_temporaries_and_die(int sig) {
  const int saved_errno = errno;
  for (auto& s : slots)
    if (s.state.load() == kReady) ::unlink(s.path);
  struct sigaction dfl{};
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  ::sigaction(sig, &dfl, nullptr);
  ::raise(sig);  // blocked until this handler returns, then the default action ends the process
  errno = saved_errno;
}

}  // namespace

}  // namespace detail

void remove_temporaries_on_signals() {
  for (int sig : detail::kSignals) {
    struct sigaction old{};
    if (::sigaction(sig, nullptr, &old) != 0) continue;
    // A signal ignored by whoever started us (nohup, a background job's SIGINT, a parent
    // that ignores SIGPIPE) stays ignored, as the shell's conventions ask.
    if (old.sa_handler == SIG_IGN) continue;
    struct sigaction act{};
    act.sa_handler = detail::remove_temporaries_and_die;
    sigemptyset(&act.sa_mask);
    for (int other : detail::kSignals) sigaddset(&act.sa_mask, other);  // one handler at a time
    ::sigaction(sig, &act, nullptr);
  }
}

}  // namespace gearkit::io
