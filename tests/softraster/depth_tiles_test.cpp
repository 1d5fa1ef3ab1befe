// The tiles' depth bounds (detail/fast/depth_tiles.hpp): the bounds a primitive gives hold every
// fragment's depth as the fast path computes it; a tile behind a whole tile's depth is not
// walked; and sequences of random draws (every compare op, writes on and off, bias, clamp,
// scissors, stencil, the mutable depthStorage() in between) give the fast path the scalar
// method's bytes on 1 and 3 threads while every tile's bounds hold every stored depth. Also: the
// fast path's one-clamp clampDepth gives the scalar two-clamp bits for every depth range a draw
// can have. And the parallel front end's rounds of every size give the scalar method's bytes.
#include "random_draws.hpp"

#include <softraster/detail/fast/batch.hpp>
#include <softraster/detail/fast/depth_tiles.hpp>
#include <softraster/pipeline.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace {

using softraster::DepthFormat;
using softraster::Framebuffer;
using softraster::detail::DepthTileRange;
using softraster::detail::FramebufferAccess;
using softraster::detail::kDepthTileSize;

using random_draws::Colour;
using random_draws::expectTilesHold;
using random_draws::fastPathHere;
using random_draws::quad;

// The key of a fragment at pixel (x, y) as the fast path computes its depth (two fmuladds at
// the integer coordinates, the bias, the clamp, the conversion).
template <DepthFormat Format>
float fragmentKey(const softraster::detail::PlaneEquation& p, float offset, softraster::detail::DepthRange range, int x,
                  int y) {
  const float z = std::fma(p.dady, static_cast<float>(y), std::fma(p.dadx, static_cast<float>(x), p.a0)) + offset;
  using namespace softraster::detail;
  return depthTileKey(Format, depthToStorage<Format>(clampDepth(z, range)));
}

template <DepthFormat Format>
void expectBoundsHold(std::mt19937& random) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const auto scaled = [&](float lowExp, float highExp) {
    const float magnitude = std::pow(10.0f, lowExp + (highExp - lowExp) * unit(random));
    return unit(random) < 0.5f ? -magnitude : magnitude;
  };
  int checked = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    softraster::detail::PlaneEquation plane{-0.5f + 2.0f * unit(random), scaled(-9, -1), scaled(-9, -1)};
    if (trial % 7 == 0) plane.dadx = 0;
    const float offset = trial % 3 == 0 ? scaled(-8, -2) : 0.0f;
    softraster::detail::DepthRange range;
    if (trial % 4 == 0) range = {0.25f * unit(random), 0.5f + 0.5f * unit(random)};
    const int x0 = static_cast<int>(unit(random) * 16000), y0 = static_cast<int>(unit(random) * 16000);
    const softraster::detail::PixelRect rect{x0, y0, x0 + static_cast<int>(unit(random) * 300),
                                             y0 + static_cast<int>(unit(random) * 300)};
    float lo = 0, hi = 0;
    ASSERT_TRUE(softraster::detail::fast::depthKeyBounds<Format>(plane, offset, range, rect, lo, hi));
    for (int k = 0; k < 24; ++k) {
      const int x = k < 4 ? (k & 1 ? rect.x1 : rect.x0) : rect.x0 + static_cast<int>(unit(random) * (rect.x1 - rect.x0 + 1));
      const int y = k < 4 ? (k & 2 ? rect.y1 : rect.y0) : rect.y0 + static_cast<int>(unit(random) * (rect.y1 - rect.y0 + 1));
      const float key = fragmentKey<Format>(plane, offset, range, std::min(x, rect.x1), std::min(y, rect.y1));
      ASSERT_LE(lo, key) << "trial " << trial;
      ASSERT_GE(hi, key) << "trial " << trial;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 4000 * 24);
}

}  // namespace

#if SOFTRASTER_HAS_FAST_PATH
namespace {
[[SOFTRASTER_FAST_TARGET]] void fastClampDepth(const float (&z)[8], softraster::detail::DepthRange range, float (&out)[8]) {
  const auto clamped = softraster::detail::fast::clampDepth(softraster::FloatBatch::load(z).native(), range);
  for (int lane = 0; lane < 8; ++lane) out[lane] = clamped[lane];
}
}  // namespace

TEST(DepthTiles, FastClampDepthIsTheScalarClampForEveryRange) {
  if (!fastPathHere()) GTEST_SKIP() << "no AVX2 and FMA";
  constexpr float kInf = std::numeric_limits<float>::infinity();
  std::vector<float> depths = {std::numeric_limits<float>::quiet_NaN(), -std::numeric_limits<float>::quiet_NaN(), kInf, -kInf,
                               0.0f, -0.0f, 1.0f, -1.0f, 2.0f, 0.25f, 0.5f, 0.75f, std::nextafter(1.0f, 2.0f),
                               std::nextafter(0.0f, 1.0f), std::nextafter(0.0f, -1.0f), 1e30f, -1e30f};
  std::mt19937 random(23);
  for (int i = 0; i < 2000; ++i) depths.push_back(std::bit_cast<float>(static_cast<std::uint32_t>(random())));
  for (int i = 0; i < 2000; ++i) depths.push_back(std::uniform_real_distribution<float>(-0.5f, 1.5f)(random));
  // Every range fragmentDepthRange gives: [0, 1] without depth clamp; with it, min <= max from a
  // viewport's two depths in [0, 1], zeros of either sign included.
  std::vector<softraster::detail::DepthRange> ranges = {{0.0f, 1.0f}, {-0.0f, 1.0f}, {0.0f, 0.0f}, {-0.0f, -0.0f}, {-0.0f, 0.0f},
                                                        {0.0f, -0.0f}, {1.0f, 1.0f}, {0.25f, 0.75f}, {0.5f, 0.5f}, {0.0f, 0.5f},
                                                        {0.5f, 1.0f}};
  for (int i = 0; i < 50; ++i) {
    const float a = std::uniform_real_distribution<float>(0.0f, 1.0f)(random), b = std::uniform_real_distribution<float>(0.0f, 1.0f)(random);
    ranges.push_back({std::fmin(a, b), std::fmax(a, b)});
  }
  float z[8], out[8];
  for (const auto& range : ranges) {
    for (std::size_t first = 0; first < depths.size(); first += 8) {
      for (std::size_t lane = 0; lane < 8; ++lane) z[lane] = depths[(first + lane) % depths.size()];
      fastClampDepth(z, range, out);
      for (std::size_t lane = 0; lane < 8; ++lane) {
        ASSERT_EQ(std::bit_cast<std::uint32_t>(out[lane]), std::bit_cast<std::uint32_t>(softraster::detail::clampDepth(z[lane], range)))
            << "z " << z[lane] << " (bits 0x" << std::hex << std::bit_cast<std::uint32_t>(z[lane]) << std::dec << ") range ["
            << range.min << ", " << range.max << "]";
      }
    }
  }
}
#endif

TEST(DepthTiles, BoundsHoldEveryFragmentsDepth) {
  std::mt19937 random(20261205);
  expectBoundsHold<DepthFormat::D16Unorm>(random);
  expectBoundsHold<DepthFormat::X8D24UnormPack32>(random);
  expectBoundsHold<DepthFormat::D32Sfloat>(random);
}

TEST(DepthTiles, HugePlanesGiveNoBounds) {
  float lo = 0, hi = 0;
  const softraster::detail::PixelRect rect{0, 0, 31, 31};
  EXPECT_FALSE(softraster::detail::fast::depthKeyBounds<DepthFormat::D32Sfloat>({0.5f, 1e35f, 0}, 0, {}, rect, lo, hi));
  EXPECT_FALSE(softraster::detail::fast::depthKeyBounds<DepthFormat::D32Sfloat>({NAN, 0, 0}, 0, {}, rect, lo, hi));
}

// A clear gives each tile its value; a quad at 0.25 narrows the tiles one of its triangles covers
// whole; then a plane at 0.5 with LESS walks every tile but those; the mutable depthStorage()
// forgets them all.
TEST(DepthTiles, TilesBehindAWholeTileAreNotWalked) {
  if (!fastPathHere()) GTEST_SKIP() << "no fast path here";
  constexpr DepthFormat kFormat = DepthFormat::X8D24UnormPack32;
  Framebuffer framebuffer = Framebuffer::create(256, 128, kFormat).value();
  framebuffer.clear({0, 0, 0, 1}, 1.0f);
  for (const DepthTileRange& t : FramebufferAccess::depthTiles(framebuffer)) {
    EXPECT_EQ(t.lo, 16777215.0f);
    EXPECT_EQ(t.hi, 16777215.0f);
  }
  softraster::PipelineState state;
  state.rasterization.cullMode = softraster::CullMode::None;
  softraster::ContextOptions options;
  options.threads = 1;
  const softraster::Context context(options);
  const auto vertices = quad(0.25f, {1, 0, 0, 1});
  ASSERT_TRUE(context.draw<Colour>(state, {}, std::span<const Colour::Vertex>(vertices), framebuffer).ok());
  expectTilesHold(framebuffer, "after the quad");
  // 8 x 4 tiles; the diagonal of the quad crosses 8 of them (one per column), and those each
  // triangle covers in part keep hi = 1.0's key: the other 24 are narrowed to 0.25's, but for
  // the bound's slack (2^-20 of 0.25: 4 steps of D24).
  const float quarter = 4194304.0f;  // nearbyint(0.25f * 16777215.0f)
  std::vector<bool> narrowed;
  for (const DepthTileRange& t : FramebufferAccess::depthTiles(framebuffer)) {
    EXPECT_EQ(t.lo, -softraster::detail::fast::kNoDepthBound) << "LESS opens lo";
    const bool nearQuarter = t.hi >= quarter && t.hi <= quarter + 8;
    EXPECT_TRUE(nearQuarter || t.hi == 16777215.0f) << t.hi;
    narrowed.push_back(nearQuarter);
  }
  EXPECT_EQ(std::count(narrowed.begin(), narrowed.end(), true), 24);

  const softraster::detail::FragmentTarget target = softraster::detail::fragmentTarget(
      state, framebuffer, softraster::detail::resolveViewport(state.viewport, 256, 128), {0, 0, 255, 127}, false);
  const auto walkedTiles = [&](Framebuffer& f) {
    const softraster::detail::fast::DepthTiles<kFormat> tiles(f, target, false, false, false);
    const softraster::detail::EdgeFunction everywhere[3] = {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}};
    std::vector<int> walked(32, 0);  // pixels walked per tile
    tiles.shade(everywhere, {0, 0, 255, 127}, {0.5f, 0, 0}, 0.0f, [&](const softraster::detail::PixelRect& part) {
      for (int y = part.y0; y <= part.y1; ++y) {
        for (int x = part.x0; x <= part.x1; ++x) ++walked[static_cast<std::size_t>((y / 32) * 8 + x / 32)];
      }
    });
    return walked;
  };
  const std::vector<int> walked = walkedTiles(framebuffer);
  for (std::size_t i = 0; i < 32; ++i) EXPECT_EQ(walked[i], narrowed[i] ? 0 : 32 * 32) << "tile " << i;
  framebuffer.depthStorage();  // may be written through: the bounds are forgotten
  for (const int pixels : walkedTiles(framebuffer)) EXPECT_EQ(pixels, 32 * 32);
}

// Random sequences of large triangles, the fast path on 1 and 3 threads against the scalar
// method after every draw, with the tiles' bounds checked to hold every stored depth.
// One draw under ALWAYS or NOT_EQUAL: a quad covering whole tiles at 0.25, then, in the same
// draw, a small triangle inside one of them at 0.75. The quad's whole tiles must not be closed to
// its depth while the draw may still write there (found by the random draws below: bounds of
// [0.24, 0.51] over a stored 0.61).
TEST(DepthTiles, OpsThatMoveDepthBothWaysKeepTheBoundsOpenForTheRestOfTheDraw) {
  if (!fastPathHere()) GTEST_SKIP() << "no fast path here";
  for (const softraster::CompareOp op : {softraster::CompareOp::Always, softraster::CompareOp::NotEqual}) {
    for (const unsigned threads : {1u, 2u}) {
      Framebuffer framebuffer = Framebuffer::create(128, 128, DepthFormat::D32Sfloat).value();
      framebuffer.clear({0, 0, 0, 1}, 1.0f);
      softraster::PipelineState state;
      state.rasterization.cullMode = softraster::CullMode::None;
      state.depth.compareOp = op;
      softraster::ContextOptions options;
      options.threads = threads;
      const softraster::Context context(options);
      std::vector<Colour::Vertex> vertices = quad(0.25f, {1, 0, 0, 1});
      // Inside tile (2, 0), which the quad's first triangle covers whole.
      for (const Colour::Vertex& v : {Colour::Vertex{{0.1f, -0.9f, 0.75f}, {0, 1, 0, 1}},
                                      Colour::Vertex{{0.3f, -0.9f, 0.75f}, {0, 1, 0, 1}},
                                      Colour::Vertex{{0.1f, -0.7f, 0.75f}, {0, 1, 0, 1}}}) {
        vertices.push_back(v);
      }
      ASSERT_TRUE(context.draw<Colour>(state, {}, std::span<const Colour::Vertex>(vertices), framebuffer).ok());
      const std::string where =
          std::string(op == softraster::CompareOp::Always ? "always" : "not_equal") + ", " + std::to_string(threads) + " threads";
      expectTilesHold(framebuffer, where);
      // A LESS wall at 0.5 then passes over the small triangle (0.75) alone: with the tile closed
      // to the quad's 0.25 it would have been skipped there.
      softraster::PipelineState less;
      less.rasterization.cullMode = softraster::CullMode::None;
      const std::vector<Colour::Vertex> wall = quad(0.5f, {0, 0, 1, 1});
      ASSERT_TRUE(context.draw<Colour>(less, {}, std::span<const Colour::Vertex>(wall), framebuffer).ok());
      Framebuffer reference = Framebuffer::create(128, 128, DepthFormat::D32Sfloat).value();
      reference.clear({0, 0, 0, 1}, 1.0f);
      softraster::ContextOptions scalar;
      scalar.method = softraster::Method::ExactScalar;
      const softraster::Context scalarContext(scalar);
      ASSERT_TRUE(scalarContext.draw<Colour>(state, {}, std::span<const Colour::Vertex>(vertices), reference).ok());
      ASSERT_TRUE(scalarContext.draw<Colour>(less, {}, std::span<const Colour::Vertex>(wall), reference).ok());
      EXPECT_TRUE(framebuffer.colour() == reference.colour()) << where << ": colour differs";
      const std::size_t inside = 4 * (8 * 128 + 72);  // pixel (72, 8), inside the small triangle: the wall's blue
      EXPECT_EQ(reference.colour()[inside], 0);
      EXPECT_EQ(reference.colour()[inside + 2], 255);
    }
  }
}

TEST(DepthTiles, RandomDrawsMatchTheScalarMethodAndKeepTrueBounds) {
  if (!fastPathHere()) GTEST_SKIP() << "no fast path here";
  const DepthFormat formats[] = {DepthFormat::D16Unorm, DepthFormat::X8D24UnormPack32, DepthFormat::D32Sfloat,
                                 DepthFormat::D24UnormS8Uint};
  std::mt19937 random(7);
  for (const DepthFormat format : formats) {
    for (const unsigned threads : {1u, 3u}) {
      Framebuffer fast = Framebuffer::create(173, 151, format).value();
      Framebuffer scalar = Framebuffer::create(173, 151, format).value();
      softraster::ContextOptions options;
      options.threads = threads;
      const softraster::Context fastContext(options);
      options.method = softraster::Method::ExactScalar;
      options.threads = 1;
      const softraster::Context scalarContext(options);
      for (int frame = 0; frame < 3; ++frame) {
        const float clearDepth = frame == 1 ? 0.0f : 1.0f;
        fast.clear({0, 0, 0, 1}, clearDepth);
        scalar.clear({0, 0, 0, 1}, clearDepth);
        for (int draw = 0; draw < 40; ++draw) {
          const random_draws::RandomDraw d = random_draws::randomDraw(random, format, 173, 151);
          const std::span<const Colour::Vertex> span(d.vertices);
          ASSERT_TRUE(fastContext.draw<Colour>(d.state, {d.alpha}, span, fast).ok());
          ASSERT_TRUE(scalarContext.draw<Colour>(d.state, {d.alpha}, span, scalar).ok());
          const std::string where = "format " + std::to_string(static_cast<int>(format)) + ", " +
                                    std::to_string(threads) + " threads, frame " + std::to_string(frame) + ", draw " +
                                    std::to_string(draw);
          ASSERT_TRUE(std::equal(FramebufferAccess::depthWords(fast), FramebufferAccess::depthWords(fast) + 173 * 151,
                                 FramebufferAccess::depthWords(scalar)))
              << where << ": depth differs";
          ASSERT_TRUE(fast.colour() == scalar.colour()) << where << ": colour differs";
          ASSERT_TRUE(fast.stencilStorage() == scalar.stencilStorage()) << where << ": stencil differs";
          expectTilesHold(fast, where);
          if (draw == 20) {  // written from outside: seen by the next draws
            std::vector<std::uint32_t>& depth = fast.depthStorage();
            std::vector<std::uint32_t>& reference = scalar.depthStorage();
            for (std::size_t i = 0; i < depth.size(); i += 3) depth[i] = reference[i] = reference[(i * 7) % depth.size()];
          }
        }
      }
    }
  }
}

// The parallel front end's rounds (exact/draw.hpp) are sized by the records the round before
// kept: a draw whose culled and visible runs of small triangles give rounds of every size, filled
// and in polygon mode line (three records a triangle), gives the fast path on 2 and 3 threads the
// scalar method's bytes.
TEST(ParallelFrontEnd, RoundsOfEverySizeMatchTheScalarMethod) {
  if (!fastPathHere()) GTEST_SKIP() << "no fast path here";
  std::mt19937 random(11);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  // Runs of tiny triangles of one winding, then the other (one of the two is culled).
  std::vector<Colour::Vertex> vertices;
  for (const auto& [count, clockwise] : {std::pair{40000, true}, std::pair{90000, false}, std::pair{30000, true},
                                        std::pair{20000, false}}) {
    for (int t = 0; t < count; ++t) {
      const float x = -1.0f + 2.0f * unit(random), y = -1.0f + 2.0f * unit(random), z = unit(random);
      const float size = 0.004f + 0.02f * unit(random);
      const softraster::Vec4 c{unit(random), unit(random), unit(random), 1};
      vertices.push_back({{x, y, z}, c});
      vertices.push_back(clockwise ? Colour::Vertex{{x, y + size, z}, c} : Colour::Vertex{{x + size, y, z}, c});
      vertices.push_back(clockwise ? Colour::Vertex{{x + size, y, z}, c} : Colour::Vertex{{x, y + size, z}, c});
    }
  }
  const std::span<const Colour::Vertex> span(vertices);
  for (const softraster::PolygonMode mode : {softraster::PolygonMode::Fill, softraster::PolygonMode::Line}) {
    softraster::PipelineState state;
    state.rasterization.cullMode = softraster::CullMode::Back;
    state.rasterization.polygonMode = mode;
    softraster::ContextOptions options;
    options.method = softraster::Method::ExactScalar;
    options.threads = 1;
    Framebuffer scalar = Framebuffer::create(320, 240, DepthFormat::D32Sfloat).value();
    scalar.clear({0, 0, 0, 1}, 1.0f);
    ASSERT_TRUE(softraster::Context(options).draw<Colour>(state, {}, span, scalar).ok());
    for (const unsigned threads : {2u, 3u}) {
      options.method = softraster::Method::Exact;
      options.threads = threads;
      Framebuffer fast = Framebuffer::create(320, 240, DepthFormat::D32Sfloat).value();
      fast.clear({0, 0, 0, 1}, 1.0f);
      ASSERT_TRUE(softraster::Context(options).draw<Colour>(state, {}, span, fast).ok());
      const std::string where = std::to_string(threads) + " threads, polygon mode " + std::to_string(static_cast<int>(mode));
      EXPECT_TRUE(std::equal(FramebufferAccess::depthWords(fast), FramebufferAccess::depthWords(fast) + 320 * 240,
                             FramebufferAccess::depthWords(scalar)))
          << where << ": depth differs";
      EXPECT_TRUE(fast.colour() == scalar.colour()) << where << ": colour differs";
    }
    // Something was drawn (else the comparisons above would prove nothing).
    EXPECT_NE(std::count(scalar.colour().begin(), scalar.colour().end(), std::uint8_t{0}),
              static_cast<std::ptrdiff_t>(scalar.colour().size()) * 3 / 4);
  }
}
