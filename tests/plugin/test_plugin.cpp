// Tests for gearkit/plugin/plugin.hpp: the ABI fingerprint and the stamp GEARKIT_PLUGIN writes.
#include <gearkit/plugin/plugin.hpp>

#include <gtest/gtest.h>

#include <cstring>

namespace gearkit::plugin {
namespace {

TEST(PluginAbi, FingerprintSeesEverySizeAndOffset) {
  constexpr std::uint64_t base = abi::fingerprint({8, 16, 24});
  static_assert(base == abi::fingerprint({8, 16, 24}), "the same layout gives the same fingerprint");
  EXPECT_NE(base, abi::fingerprint({8, 16, 32}));     // a size changed
  EXPECT_NE(base, abi::fingerprint({8, 24, 16}));     // two members swapped
  EXPECT_NE(base, abi::fingerprint({8, 16, 24, 0}));  // a member added
  EXPECT_NE(base, abi::fingerprint({8, 16, 24 + (1ull << 40)}));  // high bytes count too
}

TEST(PluginAbi, StampLayoutIsFixed) {
  // The host reads the stamp from files before loading them: its layout must never change.
  EXPECT_EQ(sizeof(PluginStamp), 24u);
  EXPECT_EQ(offsetof(PluginStamp, api_version), 8u);
  EXPECT_EQ(offsetof(PluginStamp, stamp_size), 12u);
  EXPECT_EQ(offsetof(PluginStamp, command_abi), 16u);
}

}  // namespace
}  // namespace gearkit::plugin
