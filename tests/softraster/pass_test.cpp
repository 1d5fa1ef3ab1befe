// Pass (softraster/pass.hpp): draws deferred into a pass and drawn band by band at its end give the
// bytes the scalar method gives drawing them one by one, on 2 and 3 threads:
//   - random sequences of draws (every compare op, depth writes on and off, bias, clamp, scissors,
//     stencil), with draws that cannot be deferred among them (a shader without batches, uniforms
//     that cannot be copied), while every depth tile's bounds hold every stored depth after each pass;
//   - a pass whose records pass the flush budget many times, inside draws and between them;
//   - 4x MSAA;
//   - a pass repeated frame after frame gives the same bytes each time.
// And its errors: a draw before begin() is an error; a draw that fails leaves the pass's kept
// draws to be drawn at end(); end() without a pass does nothing.
#include "random_draws.hpp"

#include <softraster/pass.hpp>
#include <softraster/pipeline.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <random>
#include <span>
#include <string>
#include <vector>

namespace {

using random_draws::Colour;
using random_draws::expectTilesHold;
using random_draws::fastPathHere;
using random_draws::quad;
using softraster::CompareOp;
using softraster::DepthFormat;
using softraster::Framebuffer;

// The same, with a fragment function for floats only: drawn at its call, on the scalar stage.
struct ScalarColour {
  using Vertex = Colour::Vertex;
  using Uniforms = Colour::Uniforms;
  static constexpr int kVaryings = 4;
  static softraster::Vec4 vertex(const Uniforms& u, const Vertex& v, float* out) { return Colour::vertex(u, v, out); }
  static softraster::Vec4 fragment(const Uniforms& u, const float* in) { return {in[0] * u.alpha, in[1], in[2], in[3]}; }
};

// Batches, but uniforms that cannot be copied: drawn at its call.
struct PinnedColour {
  using Vertex = Colour::Vertex;
  struct Uniforms {
    float alpha = 1;
    Uniforms() = default;
    Uniforms(const Uniforms&) = delete;
    Uniforms& operator=(const Uniforms&) = delete;
  };
  static constexpr int kVaryings = 4;
  static softraster::Vec4 vertex(const Uniforms&, const Vertex& v, float* out) {
    return Colour::vertex(Colour::Uniforms{}, v, out);
  }
  template <class F>
  static softraster::Vec4T<F> fragment(const Uniforms& u, const F* in) {
    return {in[0] * u.alpha, in[1], in[2], in[3]};
  }
};

void expectSameBytes(const Framebuffer& fast, const Framebuffer& scalar, const std::string& where) {
  EXPECT_TRUE(fast.depthStorage() == scalar.depthStorage()) << where << ": depth differs";
  EXPECT_TRUE(fast.colour() == scalar.colour()) << where << ": colour differs";
  EXPECT_TRUE(fast.stencilStorage() == scalar.stencilStorage()) << where << ": stencil differs";
}

// A random draw (random_draws.hpp) and the shader it is drawn with: one in eight is drawn by a
// shader the pass cannot keep.
struct RandomDraw : random_draws::RandomDraw {
  int shader = 0;  // 0: Colour, 1: ScalarColour, 2: PinnedColour
};

RandomDraw randomDraw(std::mt19937& random, DepthFormat format, std::uint32_t width, std::uint32_t height) {
  RandomDraw d;
  static_cast<random_draws::RandomDraw&>(d) = random_draws::randomDraw(random, format, width, height);
  d.shader = random() % 8 == 0 ? 1 + static_cast<int>(random() % 2) : 0;
  return d;
}

softraster::Status drawOne(const softraster::Context& context, const RandomDraw& d, Framebuffer& framebuffer) {
  const std::span<const Colour::Vertex> span(d.vertices);
  if (d.shader == 1) return context.draw<ScalarColour>(d.state, {d.alpha}, span, framebuffer);
  if (d.shader == 2) {
    PinnedColour::Uniforms u;
    u.alpha = d.alpha;
    return context.draw<PinnedColour>(d.state, u, span, framebuffer);
  }
  return context.draw<Colour>(d.state, {d.alpha}, span, framebuffer);
}

softraster::Status drawOne(softraster::Pass& pass, const RandomDraw& d) {
  const std::span<const Colour::Vertex> span(d.vertices);
  if (d.shader == 1) return pass.draw<ScalarColour>(d.state, {d.alpha}, span);
  if (d.shader == 2) {
    PinnedColour::Uniforms u;  // gone when the call returns: the draw must not be kept
    u.alpha = d.alpha;
    return pass.draw<PinnedColour>(d.state, u, span);
  }
  // The uniforms are a temporary too: a kept draw holds its own copy.
  return pass.draw<Colour>(d.state, Colour::Uniforms{d.alpha}, span);
}

softraster::Context scalarContext() {
  softraster::ContextOptions options;
  options.method = softraster::Method::ExactScalar;
  options.threads = 1;
  return softraster::Context(options);
}

softraster::Context fastContext(unsigned threads) {
  softraster::ContextOptions options;
  options.threads = threads;
  return softraster::Context(options);
}

}  // namespace

TEST(Pass, RandomDrawsMatchTheScalarMethodDrawnOneByOne) {
  if (!fastPathHere()) GTEST_SKIP() << "no fast path here";
  const DepthFormat formats[] = {DepthFormat::D16Unorm, DepthFormat::X8D24UnormPack32, DepthFormat::D32Sfloat,
                                 DepthFormat::D24UnormS8Uint};
  constexpr std::uint32_t kWidth = 173, kHeight = 151;
  std::mt19937 random(23);
  const softraster::Context scalar = scalarContext();
  for (const DepthFormat format : formats) {
    for (const unsigned threads : {2u, 3u}) {
      const softraster::Context context = fastContext(threads);
      softraster::Pass pass(context);
      Framebuffer fast = Framebuffer::create(kWidth, kHeight, format).value();
      Framebuffer reference = Framebuffer::create(kWidth, kHeight, format).value();
      for (int frame = 0; frame < 4; ++frame) {
        const float clearDepth = frame == 1 ? 0.0f : 1.0f;
        fast.clear({0, 0, 0, 1}, clearDepth);
        reference.clear({0, 0, 0, 1}, clearDepth);
        pass.begin(fast);
        for (int draw = 0; draw < 40; ++draw) {
          const RandomDraw d = randomDraw(random, format, kWidth, kHeight);
          ASSERT_TRUE(drawOne(pass, d).ok());
          ASSERT_TRUE(drawOne(scalar, d, reference).ok());
        }
        pass.end();
        const std::string where = "format " + std::to_string(static_cast<int>(format)) + ", " +
                                  std::to_string(threads) + " threads, frame " + std::to_string(frame);
        expectSameBytes(fast, reference, where);
        expectTilesHold(fast, where);
      }
      // Something was drawn in every channel the draws write (else equal bytes would prove little).
      const auto& c = reference.colour();
      EXPECT_GT(std::count_if(c.begin(), c.end(), [](std::uint8_t b) { return b != 0 && b != 255; }),
                static_cast<std::ptrdiff_t>(c.size() / 4));
    }
  }
}

// 180k tiny triangles in 30 draws of unequal sizes (each over 512 triangles: front ends shared
// out in rounds), four times the pass's flush budget of records: flushes inside draws and between.
TEST(Pass, FlushesOverTheBudgetKeepTheOrder) {
  if (!fastPathHere()) GTEST_SKIP() << "no fast path here";
  std::mt19937 random(5);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<Colour::Vertex> vertices;
  for (int t = 0; t < 180000; ++t) {
    const float x = -1.0f + 2.0f * unit(random), y = -1.0f + 2.0f * unit(random), z = unit(random);
    const float size = 0.01f + 0.03f * unit(random);
    const softraster::Vec4 c{unit(random), unit(random), unit(random), 1};
    vertices.push_back({{x, y, z}, c});
    vertices.push_back({{x + size, y, z}, c});
    vertices.push_back({{x, y + size, z}, c});
  }
  const softraster::Context scalar = scalarContext();
  Framebuffer reference = Framebuffer::create(320, 240, DepthFormat::D32Sfloat).value();
  Framebuffer fast = Framebuffer::create(320, 240, DepthFormat::D32Sfloat).value();
  for (const unsigned threads : {2u, 3u}) {
    const softraster::Context context = fastContext(threads);
    softraster::Pass pass(context);
    reference.clear({0, 0, 0, 1}, 1.0f);
    fast.clear({0, 0, 0, 1}, 1.0f);
    pass.begin(fast);
    std::size_t at = 0;
    for (int draw = 0; at < vertices.size(); ++draw) {
      const std::size_t triangles = std::min<std::size_t>(vertices.size() - at, 3 * (600 + 1000 * (draw % 7)));
      softraster::PipelineState state;
      state.rasterization.cullMode = softraster::CullMode::None;
      state.depth.compareOp = draw % 3 == 0 ? CompareOp::Always : CompareOp::LessOrEqual;
      state.rasterization.polygonMode = draw % 5 == 4 ? softraster::PolygonMode::Line : softraster::PolygonMode::Fill;
      const std::span<const Colour::Vertex> span(vertices.data() + at, triangles);
      const Colour::Uniforms u{0.5f + 0.01f * static_cast<float>(draw)};
      ASSERT_TRUE(pass.draw<Colour>(state, u, span).ok());
      ASSERT_TRUE(scalar.draw<Colour>(state, u, span, reference).ok());
      at += triangles;
    }
    pass.end();
    expectSameBytes(fast, reference, std::to_string(threads) + " threads");
    expectTilesHold(fast, std::to_string(threads) + " threads");
  }
}

TEST(Pass, MultisampledMatchesTheScalarMethod) {
  if (!fastPathHere()) GTEST_SKIP() << "no fast path here";
  std::mt19937 random(31);
  const softraster::Context scalar = scalarContext();
  const softraster::Context context = fastContext(2);
  softraster::Pass pass(context);
  Framebuffer fast = Framebuffer::create(150, 130, DepthFormat::D32Sfloat, 4).value();
  Framebuffer reference = Framebuffer::create(150, 130, DepthFormat::D32Sfloat, 4).value();
  fast.clear({0, 0, 0, 1}, 1.0f);
  reference.clear({0, 0, 0, 1}, 1.0f);
  pass.begin(fast);
  for (int draw = 0; draw < 40; ++draw) {
    const RandomDraw d = randomDraw(random, DepthFormat::D32Sfloat, 150, 130);
    ASSERT_TRUE(drawOne(pass, d).ok());
    ASSERT_TRUE(drawOne(scalar, d, reference).ok());
  }
  pass.end();
  expectSameBytes(fast, reference, "4x MSAA");
}

TEST(Pass, RepeatedFramesGiveTheSameBytes) {
  if (!fastPathHere()) GTEST_SKIP() << "no fast path here";
  std::mt19937 random(41);
  std::vector<RandomDraw> draws;
  for (int k = 0; k < 30; ++k) draws.push_back(randomDraw(random, DepthFormat::D32Sfloat, 200, 100));
  const softraster::Context context = fastContext(2);
  softraster::Pass pass(context);
  Framebuffer framebuffer = Framebuffer::create(200, 100, DepthFormat::D32Sfloat).value();
  std::vector<std::uint8_t> first;
  for (int frame = 0; frame < 3; ++frame) {
    framebuffer.clear({0, 0, 0, 1}, 1.0f);
    pass.begin(framebuffer);
    for (const RandomDraw& d : draws) ASSERT_TRUE(drawOne(pass, d).ok());
    pass.end();
    if (frame == 0) first = framebuffer.colour();
    EXPECT_TRUE(framebuffer.colour() == first) << "frame " << frame;
  }
}

TEST(Pass, Errors) {
  const softraster::Context context = fastContext(2);
  softraster::Pass pass(context);
  const std::vector<Colour::Vertex> vertices = quad(0.5f, {1, 0, 0, 1});
  const std::span<const Colour::Vertex> span(vertices);
  // Before begin().
  const softraster::Status early = pass.draw<Colour>({}, {}, span);
  ASSERT_FALSE(early.ok());
  EXPECT_EQ(early.message(), "the pass has no framebuffer: call Pass::begin first");
  pass.end();  // no pass: nothing happens
  EXPECT_FALSE(pass.open());

  Framebuffer framebuffer = Framebuffer::create(64, 64, DepthFormat::D32Sfloat).value();
  framebuffer.clear({0, 0, 0, 1}, 1.0f);
  pass.begin(framebuffer);
  EXPECT_TRUE(pass.open());
  softraster::PipelineState state;
  state.rasterization.cullMode = softraster::CullMode::None;
  ASSERT_TRUE(pass.draw<Colour>(state, {}, span).ok());
  EXPECT_TRUE(framebuffer.clearPending()) << "the draw is kept, not drawn (so not even the clear is written yet)";
  // A draw that fails is the draw's error; the kept one is still drawn at end().
  const std::vector<std::uint32_t> indices{0, 1, 7};
  const softraster::Status failed = pass.drawIndexed<Colour>(state, {}, span, indices);
  ASSERT_FALSE(failed.ok());
  EXPECT_EQ(failed.message(), "index 2 (7) is past the last vertex (6 vertices)");
  softraster::PipelineState bad = state;
  bad.rasterization.lineWidth = 0;
  EXPECT_FALSE(pass.draw<Colour>(bad, {}, span).ok());
  pass.end();
  EXPECT_FALSE(pass.open());
  EXPECT_FALSE(framebuffer.clearPending());
  EXPECT_EQ(framebuffer.colour()[0], 255);  // red, drawn
  EXPECT_EQ(framebuffer.colour()[1], 0);
}
