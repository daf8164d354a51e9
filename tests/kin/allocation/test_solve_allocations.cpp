// The per-position analysis does not allocate (issue 27, item 7; docs/design.md, "Model and
// Data": a Data is sized once so that a sweep does not allocate). Every heap allocation of the
// process is counted while a measurement runs: this executable replaces malloc and its
// relatives (which operator new, Eigen and SuiteSparse all end in) by counting wrappers around
// glibc's own allocator. It is a program of its own so that no other test runs with them, and
// it does not run under AddressSanitizer, which replaces malloc itself.
#include "../mechanisms.hpp"

#include <gearkit/kin/data.hpp>
#include <gearkit/kin/solve.hpp>
#include <gearkit/kin/sweep.hpp>

#include <gtest/gtest.h>

#include <atomic>
#include <cerrno>
#include <cstddef>
#include <utility>

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};
}  // namespace

#ifndef GEARKIT_SANITIZED
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* p, std::size_t size);
void* __libc_memalign(std::size_t alignment, std::size_t size);
}

namespace {
void count() {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1, std::memory_order_relaxed);
}
}  // namespace

// free() stays glibc's: every block below comes from glibc's allocator.
extern "C" void* malloc(std::size_t size) {
  count();
  return __libc_malloc(size);
}
extern "C" void* calloc(std::size_t n, std::size_t size) {
  count();
  return __libc_calloc(n, size);
}
extern "C" void* realloc(void* p, std::size_t size) {
  count();
  return __libc_realloc(p, size);
}
extern "C" void* memalign(std::size_t alignment, std::size_t size) {
  count();
  return __libc_memalign(alignment, size);
}
extern "C" void* aligned_alloc(std::size_t alignment, std::size_t size) {
  count();
  return __libc_memalign(alignment, size);
}
extern "C" int posix_memalign(void** p, std::size_t alignment, std::size_t size) {
  count();
  *p = __libc_memalign(alignment, size);
  return *p ? 0 : ENOMEM;
}
#endif

namespace gearkit::kin {
namespace {

// Heap allocations made by f().
template <class F>
long allocations_of(F&& f) {
  g_allocations = 0;
  g_counting = true;
  f();
  g_counting = false;
  return g_allocations.load();
}

// Positions, velocities, accelerations and the input sensitivity at `inputs` of driver 0, each
// from the last solution (as a sweep solves them).
long per_position_allocations(const Model& model, Data& data, double first, double step, int positions) {
  Eigen::VectorXd dq;
  data.inputs(0) = first;
  EXPECT_TRUE(solve_position(model, data, 0.0).converged);  // the first solve may size scratch
  EXPECT_TRUE(input_sensitivity(model, data, 0, dq));
  return allocations_of([&] {
    for (int k = 1; k <= positions; ++k) {
      data.inputs(0) = first + k * step;
      const PositionReport r = solve_position(model, data, 0.0);
      if (!r.converged || !solve_velocity(model, data) || !solve_acceleration(model, data) ||
          !input_sensitivity(model, data, 0, dq))
        ADD_FAILURE() << "position " << k << " failed: " << r.message;
    }
  });
}

class KinAllocations : public ::testing::Test {
 protected:
  void SetUp() override {
#ifdef GEARKIT_SANITIZED
    GTEST_SKIP() << "AddressSanitizer replaces malloc: allocations are counted in the release build";
#endif
  }
};

TEST_F(KinAllocations, TheCounterSeesOperatorNewAndEigen) {
  // A counter that sees nothing would pass every test below.
  EXPECT_GE(allocations_of([] { delete new int(3); }), 1);
  EXPECT_GE(allocations_of([] { Eigen::VectorXd v(1000); v.setZero(); }), 1);
}

TEST_F(KinAllocations, FourBarPositionVelocityAccelerationAllocateNothing) {
  const Model model = testing::four_bar({0.040, 0.120, 0.080, 0.100}, 30 * testing::kDeg);
  Data data(model);
  EXPECT_EQ(per_position_allocations(model, data, 30 * testing::kDeg, 0.05, 50), 0);
}

TEST_F(KinAllocations, LargeSparseChainAllocatesNothingPerPosition) {
  // 25 loops, 153 coordinates: above 64 the LU uses KLU's block triangular form.
  const Model model = testing::four_bar_chain({0.040, 0.120, 0.080, 0.100}, 25, 30 * testing::kDeg);
  Data data(model);
  EXPECT_EQ(per_position_allocations(model, data, 30 * testing::kDeg, 0.01, 20), 0);
}

TEST_F(KinAllocations, AStreamedSweepDoesNotAllocatePerSample) {
  // The same full turn of a crank-rocker at 360 and at 3600 samples: what the sweep allocates
  // (its result's dead points and extremes, the anchors' first sizing) must not grow with the
  // number of samples.
  const Model model = testing::four_bar({0.040, 0.120, 0.080, 0.100}, 0.0);
  const auto run = [&](double step) {
    Data data(model);
    SweepOptions o;
    o.start = 0.0;
    o.end = 2 * M_PI;
    o.step = step;
    SweepResult result;
    long samples = 0;
    const SampleVisitor visit = [&](const SweepSample&) { ++samples; };
    const long n = allocations_of([&] { sweep(model, data, o, result, visit); });
    EXPECT_TRUE(result.complete) << result.message;
    return std::pair(n, samples);
  };
  const auto [coarse, coarse_samples] = run(2 * M_PI / 360);
  const auto [fine, fine_samples] = run(2 * M_PI / 3600);
  EXPECT_EQ(coarse_samples, 361);
  EXPECT_EQ(fine_samples, 3601);
  EXPECT_LE(fine, coarse + 8) << "coarse " << coarse << ", fine " << fine;
}

}  // namespace
}  // namespace gearkit::kin
