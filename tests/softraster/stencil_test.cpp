// The stencil stage (detail/fragment/stencil.hpp): every op against the Vulkan specification's
// table for every stored value, the masked compare with the reference on the left, the write
// mask, the op chosen by the two tests; then the fast path's lanes (detail/fast/stencil.hpp)
// against the scalar stage for every op, compare op, stored value, and random masks, references
// and test results.
#include <softraster/detail/fast/stencil.hpp>
#include <softraster/detail/fragment/stencil.hpp>
#include <softraster/formats.hpp>
#include <softraster/framebuffer.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>

namespace {

using softraster::CompareOp;
using softraster::StencilOp;
using softraster::detail::StencilFace;

constexpr std::array<StencilOp, 8> kOps = {StencilOp::Keep,
                                           StencilOp::Zero,
                                           StencilOp::Replace,
                                           StencilOp::IncrementAndClamp,
                                           StencilOp::DecrementAndClamp,
                                           StencilOp::Invert,
                                           StencilOp::IncrementAndWrap,
                                           StencilOp::DecrementAndWrap};

// The specification's table (VkStencilOp), in wider integers.
int specified(StencilOp op, int s, int reference) {
  switch (op) {
    case StencilOp::Keep: return s;
    case StencilOp::Zero: return 0;
    case StencilOp::Replace: return reference;
    case StencilOp::IncrementAndClamp: return s < 255 ? s + 1 : 255;
    case StencilOp::DecrementAndClamp: return s > 0 ? s - 1 : 0;
    case StencilOp::Invert: return 255 - s;
    case StencilOp::IncrementAndWrap: return (s + 1) % 256;
    case StencilOp::DecrementAndWrap: return (s + 255) % 256;
  }
  return -1;
}

}  // namespace

TEST(Stencil, EveryOpIsTheSpecificationsForEveryValue) {
  for (const StencilOp op : kOps) {
    for (int s = 0; s < 256; ++s) {
      EXPECT_EQ(int{softraster::detail::stencilOpResult(op, static_cast<std::uint8_t>(s), 0x3c)}, specified(op, s, 0x3c))
          << "op " << int(op) << " stored " << s;
    }
  }
}

TEST(Stencil, TheCompareIsMaskedWithTheReferenceOnTheLeft) {
  softraster::StencilOpState state;
  state.compareOp = CompareOp::Less;
  state.reference = 0x140;  // only the low 8 bits count: 0x40
  state.compareMask = 0x1f0;
  const StencilFace face = softraster::detail::stencilFace(state);
  EXPECT_EQ(face.reference, 0x40);
  EXPECT_EQ(face.compareMask, 0xf0);
  EXPECT_TRUE(softraster::detail::stencilTestPasses(face, 0x50));   // 0x40 < 0x50
  EXPECT_FALSE(softraster::detail::stencilTestPasses(face, 0x4f));  // 0x40 < 0x40 after the mask
  EXPECT_FALSE(softraster::detail::stencilTestPasses(face, 0x30));
}

TEST(Stencil, TheWriteMaskKeepsTheOtherBitsAndTheTestsPickTheOp) {
  softraster::StencilOpState state;
  state.failOp = StencilOp::Zero;
  state.depthFailOp = StencilOp::Invert;
  state.passOp = StencilOp::Replace;
  state.reference = 0xab;
  state.writeMask = 0x0f;
  const StencilFace face = softraster::detail::stencilFace(state);
  using softraster::detail::stencilOpFor;
  using softraster::detail::stencilUpdate;
  EXPECT_EQ(int{stencilUpdate(face, stencilOpFor(face, false, true), 0x5a)}, 0x50);  // zero, low bits only
  EXPECT_EQ(int{stencilUpdate(face, stencilOpFor(face, true, false), 0x5a)}, 0x55);  // invert
  EXPECT_EQ(int{stencilUpdate(face, stencilOpFor(face, true, true), 0x5a)}, 0x5b);   // replace with 0xab
}

TEST(Stencil, StencilFormatsShareTheirDepthAspect) {
  using softraster::DepthFormat;
  EXPECT_TRUE(softraster::hasStencil(DepthFormat::D24UnormS8Uint));
  EXPECT_TRUE(softraster::hasStencil(DepthFormat::D32SfloatS8Uint));
  EXPECT_FALSE(softraster::hasStencil(DepthFormat::X8D24UnormPack32));
  EXPECT_EQ(softraster::depthAspect(DepthFormat::D24UnormS8Uint), DepthFormat::X8D24UnormPack32);
  EXPECT_EQ(softraster::depthAspect(DepthFormat::D32SfloatS8Uint), DepthFormat::D32Sfloat);
  EXPECT_EQ(softraster::unormDepthBits(DepthFormat::D24UnormS8Uint), 24);
  EXPECT_EQ(softraster::unormDepthBits(DepthFormat::D32SfloatS8Uint), 0);
  auto fb = softraster::Framebuffer::create(3, 2, DepthFormat::D32SfloatS8Uint, 4);
  ASSERT_TRUE(fb) << fb.error();
  fb->clear({0, 0, 0, 0}, 1.0f, 0x7e);
  ASSERT_EQ(fb->stencilStorage().size(), 3u * 2 * 4);
  for (std::uint8_t s : fb->stencilStorage()) EXPECT_EQ(s, 0x7e);
  fb->stencilStorage()[4] = 9;  // pixel 1, sample 0
  const softraster::Framebuffer resolved = fb->resolve();
  EXPECT_EQ(resolved.stencilStorage().size(), 6u);
  EXPECT_EQ(resolved.stencilStorage()[1], 9) << "the resolve keeps sample 0";
}

#if SOFTRASTER_HAS_FAST_PATH

namespace {

namespace fast = softraster::detail::fast;

// The fast path's update of eight stored values with the given test results.
[[SOFTRASTER_FAST_TARGET]] void fastUpdate(const StencilFace& face, const std::uint8_t* stored, unsigned depthPasses,
                                           std::uint8_t* out, unsigned& stencilPasses) {
  const auto offset = [](int lane) { return static_cast<std::size_t>(lane); };
  const fast::Words s = fast::loadStencil(stored, 0xffu, offset);
  const fast::Mask passes = fast::stencilTestLanes(face, s);
  fast::storeStencil(out, 0xffu, fast::stencilUpdateLanes(face, s, passes, fast::laneMask(depthPasses)), offset);
  stencilPasses = fast::maskBits(passes);
}

}  // namespace

TEST(Stencil, FastLanesAreTheScalarStage) {
  if (!fast::cpuRunsFastPath()) GTEST_SKIP() << "no AVX2 and FMA";
  std::mt19937 random(13);
  for (int round = 0; round < 4000; ++round) {
    softraster::StencilOpState state;
    state.failOp = kOps[random() % 8];
    state.depthFailOp = kOps[random() % 8];
    state.passOp = kOps[random() % 8];
    state.compareOp = static_cast<CompareOp>(random() % 8);
    state.compareMask = round % 5 == 0 ? 0xff : random() % 256;
    state.writeMask = round % 7 == 0 ? 0xff : random() % 256;
    state.reference = random() % 256;
    const StencilFace face = softraster::detail::stencilFace(state);
    std::uint8_t stored[8], out[8];
    for (int l = 0; l < 8; ++l) stored[l] = static_cast<std::uint8_t>((round * 8 + l) % 256);  // every value, often
    stored[round % 8] = static_cast<std::uint8_t>(round % 2 == 0 ? 0 : 255);
    const unsigned depthPasses = random() % 256;
    unsigned stencilPasses = 0;
    fastUpdate(face, stored, depthPasses, out, stencilPasses);
    for (int l = 0; l < 8; ++l) {
      const bool sp = softraster::detail::stencilTestPasses(face, stored[l]);
      const bool dp = (depthPasses >> l) & 1u;
      ASSERT_EQ(((stencilPasses >> l) & 1u) != 0, sp) << "round " << round << " lane " << l;
      ASSERT_EQ(int{out[l]}, int{softraster::detail::stencilUpdate(face, softraster::detail::stencilOpFor(face, sp, dp), stored[l])})
          << "round " << round << " lane " << l << " stored " << int{stored[l]} << " ops " << int(state.failOp) << "/"
          << int(state.depthFailOp) << "/" << int(state.passOp);
    }
  }
}

#endif  // SOFTRASTER_HAS_FAST_PATH
