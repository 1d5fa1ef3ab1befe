// vkref's prepared frames on lavapipe, with the validation layer on (any message fails): a frame
// submitted again gives the same images as the first submission and as render(); pipelines are
// compiled once per Renderer, however many draws and frames use them; misuse is an error value;
// several colour attachments of different formats, each blended its own way, resolve and read
// back every sample.
#include <vkref/renderer.hpp>

#include <shaders/colour_outputs_frag.spv.h>
#include <shaders/colour_outputs_vert.spv.h>
#include <shaders/vertex_color_frag.spv.h>
#include <shaders/vertex_color_vert.spv.h>
#include <vertex_color.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace {

using shaders::VertexColor;

vkref::ShaderProgram vertexColorProgram() {
  vkref::ShaderProgram p;
  p.name = "vertex_color";
  p.vertexSpirv = vertex_color_vert_spirv;
  p.fragmentSpirv = vertex_color_frag_spirv;
  p.attributes.assign(VertexColor::kAttributes.begin(), VertexColor::kAttributes.end());
  p.vertexStride = sizeof(VertexColor::Vertex);
  return p;
}

// colour_outputs.frag: four outputs of the vertex colour (shaders/colour_outputs.frag).
vkref::ShaderProgram colourOutputsProgram() {
  vkref::ShaderProgram p = vertexColorProgram();
  p.name = "colour_outputs";
  p.vertexSpirv = colour_outputs_vert_spirv;
  p.fragmentSpirv = colour_outputs_frag_spirv;
  return p;
}

template <class T>
std::vector<std::byte> bytesOf(const T* data, std::size_t count) {
  std::vector<std::byte> bytes(sizeof(T) * count);
  std::memcpy(bytes.data(), data, bytes.size());
  return bytes;
}

// A triangle in clip space (identity matrix) at depth z with one colour.
vkref::DrawCall triangle(const vkref::ShaderProgram& program, float x, float y, float size, float z,
                         softraster::Vec4 colour) {
  vkref::DrawCall d;
  d.program = &program;
  d.state.rasterization.cullMode = softraster::CullMode::None;
  const VertexColor::Vertex v[3] = {{{x - size, y - size, z}, colour},
                                    {{x + size, y - size, z}, colour},
                                    {{x, y + size, z}, colour}};
  d.vertexData = bytesOf(v, 3);
  d.indices = {0, 1, 2};
  VertexColor::Uniforms u{};
  for (int c = 0; c < 4; ++c) u.modelViewProjection.columns[c][c] = 1;
  d.pushConstants = bytesOf(&u, 1);
  return d;
}

// Overlapping triangles: depth-tested ones, and additive ones that would show any leftover of an
// earlier submission (the counts would grow).
vkref::FrameRequest overlappingTriangles(const vkref::ShaderProgram& program, std::uint32_t samples,
                                         softraster::DepthFormat depthFormat) {
  vkref::FrameRequest r;
  r.width = 64;
  r.height = 48;
  r.clearColour = {0.1f, 0.2f, 0.3f, 1.0f};
  r.samples = samples;
  r.depthFormat = depthFormat;
  r.draws.push_back(triangle(program, -0.2f, 0.0f, 0.6f, 0.5f, {1, 0, 0, 1}));
  r.draws.push_back(triangle(program, 0.2f, 0.1f, 0.6f, 0.3f, {0, 1, 0, 1}));
  for (int i = 0; i < 3; ++i) {
    vkref::DrawCall d = triangle(program, 0.1f * i, -0.3f, 0.5f, 0.1f, {0.125f, 0.125f, 0.125f, 0});
    d.state.blend.enable = true;
    d.state.blend.dstColorBlendFactor = d.state.blend.dstAlphaBlendFactor = softraster::BlendFactor::One;
    d.state.depth.testEnable = false;
    r.draws.push_back(std::move(d));
  }
  return r;
}

class PreparedFrame : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    vkref::DeviceOptions options;
    options.validation = true;
    auto created = vkref::Renderer::create(options);
    ASSERT_TRUE(created) << created.error();
    renderer_ = std::move(*created).release();
  }
  static void TearDownTestSuite() {
    delete renderer_;
    renderer_ = nullptr;
  }
  void SetUp() override { ASSERT_NE(renderer_, nullptr); }
  void TearDown() override {
    for (const std::string& message : renderer_->validationMessages()) ADD_FAILURE() << "validation: " << message;
  }

  static vkref::Renderer* renderer_;
};
vkref::Renderer* PreparedFrame::renderer_ = nullptr;

void expectSameImages(const vkref::FrameImages& a, const vkref::FrameImages& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_TRUE(a.rgba == b.rgba) << "colour differs";
  EXPECT_TRUE(a.depthStorage == b.depthStorage) << "stored depth differs";
  EXPECT_EQ(std::memcmp(a.depth.data(), b.depth.data(), a.depth.size() * sizeof(float)), 0) << "depth differs";
  EXPECT_EQ(a.samples, b.samples);
  EXPECT_TRUE(a.sampleRgba == b.sampleRgba) << "colour samples differ";
  EXPECT_TRUE(a.sampleDepthStorage == b.sampleDepthStorage) << "depth samples differ";
  EXPECT_TRUE(a.sampleStencil == b.sampleStencil) << "stencil samples differ";
}

TEST_F(PreparedFrame, SubmittedTwiceGivesTheSameImages) {
  const vkref::ShaderProgram program = vertexColorProgram();
  for (std::uint32_t samples : {1u, 4u}) {
    for (softraster::DepthFormat depth : {softraster::DepthFormat::D16Unorm, softraster::DepthFormat::D32Sfloat}) {
      SCOPED_TRACE("samples " + std::to_string(samples) + ", depth format " + std::to_string(int(depth)));
      const vkref::FrameRequest request = overlappingTriangles(program, samples, depth);
      auto frame = renderer_->prepare(request);
      ASSERT_TRUE(frame) << frame.error();
      EXPECT_EQ(frame->width(), 64u);
      ASSERT_TRUE(renderer_->submit(*frame));
      auto first = renderer_->readBack(*frame);
      ASSERT_TRUE(first) << first.error();
      ASSERT_TRUE(renderer_->submit(*frame));
      ASSERT_TRUE(renderer_->submit(*frame));
      auto again = renderer_->readBack(*frame);
      ASSERT_TRUE(again) << again.error();
      auto twice = renderer_->readBack(*frame);  // reading back again changes nothing either
      ASSERT_TRUE(twice) << twice.error();
      auto once = renderer_->render(request);
      ASSERT_TRUE(once) << once.error();
      expectSameImages(*first, *again);
      expectSameImages(*first, *twice);
      expectSameImages(*first, *once);

      // The frame drew something: the three additive triangles overlap, and count up.
      const std::uint8_t* clear = first->rgba.data();  // the top-left pixel is not covered
      std::size_t drawn = 0, stacked = 0;
      for (std::size_t i = 0; i < first->rgba.size(); i += 4) {
        drawn += std::memcmp(&first->rgba[i], clear, 3) != 0;
        stacked += first->rgba[i + 2] > clear[2] + 2 * 32;  // three additive layers of 0.125 blue
      }
      EXPECT_GT(drawn, 200u);
      EXPECT_GT(stacked, 10u);
    }
  }
}

// With 4x MSAA every sample comes back as well as the resolve, in softraster's order, for every
// depth format: the samples' average (lavapipe's resolve: float sum in sample order times 0.25,
// round half to even) is the resolved colour, sample 0 of depth is the resolved depth (also
// checked by readBack itself), and stencil holds the clear value in every sample.
TEST_F(PreparedFrame, EverySampleIsReadBack) {
  const vkref::ShaderProgram program = vertexColorProgram();
  for (softraster::DepthFormat depth :
       {softraster::DepthFormat::D16Unorm, softraster::DepthFormat::X8D24UnormPack32, softraster::DepthFormat::D32Sfloat,
        softraster::DepthFormat::D24UnormS8Uint, softraster::DepthFormat::D32SfloatS8Uint}) {
    SCOPED_TRACE("depth format " + std::to_string(int(depth)));
    vkref::FrameRequest request = overlappingTriangles(program, 4, depth);
    request.clearStencil = 0x5a;
    auto images = renderer_->render(request);
    ASSERT_TRUE(images) << images.error();
    const std::size_t pixels = std::size_t{images->width} * images->height;
    ASSERT_EQ(images->samples, 4u);
    ASSERT_EQ(images->sampleRgba.size(), pixels * 16);
    ASSERT_EQ(images->sampleDepthStorage.size(), pixels * 4);
    ASSERT_EQ(images->sampleDepth.size(), pixels * 4);
    ASSERT_EQ(images->sampleStencil.size(), softraster::hasStencil(depth) ? pixels * 4 : 0);
    std::size_t partial = 0;  // pixels whose samples differ in depth (edges)
    for (std::size_t p = 0; p < pixels; ++p) {
      EXPECT_EQ(images->sampleDepthStorage[4 * p], images->depthStorage[p]) << p;
      bool differs = false;
      for (std::size_t s = 1; s < 4; ++s) differs = differs || images->sampleDepthStorage[4 * p + s] != images->depthStorage[p];
      partial += differs;
      for (std::size_t ch = 0; ch < 4; ++ch) {
        float sum = 0;
        for (std::size_t s = 0; s < 4; ++s) sum += float(images->sampleRgba[16 * p + 4 * s + ch]) * (1.0f / 255);
        const float resolved = std::nearbyint(sum * 0.25f * 255.0f);
        ASSERT_EQ(int(resolved), int(images->rgba[4 * p + ch])) << "pixel " << p << " channel " << ch;
      }
      for (std::size_t s = 0; s < images->sampleStencil.size() / pixels; ++s)
        ASSERT_EQ(int(images->sampleStencil[4 * p + s]), 0x5a) << p;
    }
    EXPECT_GT(partial, 20u);
  }
}

TEST_F(PreparedFrame, PipelinesAreCompiledOncePerRenderer) {
  // One ShaderProgram object per draw, as crosscheck makes them: the same code is one program.
  std::vector<vkref::ShaderProgram> programs(50, vertexColorProgram());
  vkref::FrameRequest request = overlappingTriangles(programs[0], 1, softraster::DepthFormat::D32Sfloat);
  for (std::size_t i = 0; i < programs.size(); ++i)
    request.draws.push_back(triangle(programs[i], 0.01f * i, 0.0f, 0.1f, 0.2f, {0, 0, 1, 1}));
  auto first = renderer_->prepare(request);
  ASSERT_TRUE(first) << first.error();
  const std::size_t pipelines = renderer_->cachedPipelines();
  auto second = renderer_->prepare(request);
  ASSERT_TRUE(second) << second.error();
  EXPECT_EQ(renderer_->cachedPipelines(), pipelines) << "a second frame compiled pipelines again";

  // One more state is one more pipeline, once.
  request.draws[0].state.depth.compareOp = softraster::CompareOp::LessOrEqual;
  request.draws[1].state.depth.compareOp = softraster::CompareOp::LessOrEqual;
  auto third = renderer_->prepare(request);
  ASSERT_TRUE(third) << third.error();
  EXPECT_EQ(renderer_->cachedPipelines(), pipelines + 1);
}

TEST_F(PreparedFrame, MisuseIsAnError) {
  const vkref::ShaderProgram program = vertexColorProgram();
  vkref::PreparedFrame empty;
  EXPECT_TRUE(empty.empty());
  const softraster::Status submitted = renderer_->submit(empty);
  EXPECT_FALSE(submitted);
  EXPECT_NE(submitted.message().find("empty"), std::string::npos) << submitted.message();

  auto frame = renderer_->prepare(overlappingTriangles(program, 1, softraster::DepthFormat::D32Sfloat));
  ASSERT_TRUE(frame) << frame.error();
  const auto early = renderer_->readBack(*frame);
  EXPECT_FALSE(early);
  EXPECT_EQ(early.error(), "readBack: the frame has not been submitted");

  vkref::PreparedFrame moved = std::move(*frame);
  EXPECT_FALSE(moved.empty());
  EXPECT_TRUE(renderer_->submit(moved));
  EXPECT_FALSE(renderer_->submit(*frame));  // moved from
}

TEST_F(PreparedFrame, AnUnexpressibleDrawNamesItself) {
  const vkref::ShaderProgram program = vertexColorProgram();
  vkref::FrameRequest request = overlappingTriangles(program, 1, softraster::DepthFormat::D32Sfloat);
  request.draws[1].pushConstants.resize(6);
  const auto frame = renderer_->prepare(request);
  ASSERT_FALSE(frame);
  EXPECT_EQ(frame.error(), "draw 1: 6 bytes of push constants (need a multiple of 4, at most 128)");
}


// Four colour attachments of four formats, each blended its own way, drawn by colour_outputs
// (output i to attachment i) with a flat colour c = (0.25, 0.5, 0.75, 1):
//   0 R8G8B8A8_UNORM, blending off: c;
//   1 A2B10G10R10_UNORM_PACK32, additive over its clear (0.25, 0.25, 0.25, 0): (1-b, 1-g, 1-r, a) + clear;
//   2 R16G16B16A16_SFLOAT, blending off: (r*4-2, g*b, -a, a*0.5+0.25) = (-1, 0.375, -1, 0.75) exactly;
//   3 R8G8B8A8_SRGB, write mask R|G: c.gbra * 0.75 in red and green, blue and alpha the clear's.
// Outside the triangle each attachment holds its own clear colour. With 4x MSAA the resolve of a
// pixel whose samples agree is that sample, in every attachment.
constexpr std::uint32_t kMrtSize = 32;

vkref::FrameRequest fourAttachments(const vkref::ShaderProgram& program, std::uint32_t samples) {
  vkref::FrameRequest r;
  r.width = r.height = kMrtSize;
  r.samples = samples;
  r.colourFormat = softraster::ColourFormat::R8G8B8A8Unorm;
  r.clearColour = {0.2f, 0.4f, 0.6f, 1.0f};
  r.moreColour = {{softraster::ColourFormat::A2B10G10R10Unorm, {0.25f, 0.25f, 0.25f, 0.0f}},
                  {softraster::ColourFormat::R16G16B16A16Sfloat, {-0.5f, 2.0f, 0.25f, 1.0f}},
                  {softraster::ColourFormat::R8G8B8A8Srgb, {0.0f, 0.0f, 1.0f, 0.6f}}};
  vkref::DrawCall d = triangle(program, 0.0f, 0.0f, 0.9f, 0.5f, {0.25f, 0.5f, 0.75f, 1.0f});
  softraster::AttachmentBlend& additive = d.state.moreBlend[0];
  additive.enable = true;
  additive.srcColorBlendFactor = additive.dstColorBlendFactor = softraster::BlendFactor::One;
  additive.srcAlphaBlendFactor = additive.dstAlphaBlendFactor = softraster::BlendFactor::One;
  d.state.moreBlend[2].colorWriteMask = softraster::kColourR | softraster::kColourG;
  r.draws.push_back(std::move(d));
  return r;
}

// The 8-bit sRGB encoding of a linear value (allowing the driver's rounding one step).
int srgbByte(float linear) {
  const double v = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(double(linear), 1 / 2.4) - 0.055;
  return int(std::lround(v * 255));
}

void expectNear(std::uint32_t actual, double expected, const std::string& what) {
  EXPECT_LE(std::fabs(double(actual) - expected), 1.0) << what << ": " << actual << ", expected " << expected;
}

// What pixel p of the four attachments holds, inside the triangle or outside (clear).
void expectFourAttachments(const vkref::FrameImages& f, std::size_t p, bool inside) {
  const std::string where = std::string(inside ? "inside" : "outside") + ", pixel " + std::to_string(p);
  // 0: R8G8B8A8_UNORM.
  const float c0[4] = {0.25f, 0.5f, 0.75f, 1.0f}, clear0[4] = {0.2f, 0.4f, 0.6f, 1.0f};
  for (std::size_t ch = 0; ch < 4; ++ch)
    expectNear(f.rgba[4 * p + ch], (inside ? c0 : clear0)[ch] * 255.0, where + " attachment 0 channel " + std::to_string(ch));
  // 1: A2B10G10R10, additive: (0.25, 0.5, 0.75, 1) + (0.25, 0.25, 0.25, 0).
  ASSERT_EQ(f.moreColour[0].colourWords.size(), f.rgba.size() / 4);
  const std::uint32_t word = f.moreColour[0].colourWords[p];
  const double tenBit[4] = {inside ? 0.5 * 1023 : 0.25 * 1023, inside ? 0.75 * 1023 : 0.25 * 1023,
                            inside ? 1023.0 : 0.25 * 1023, inside ? 3.0 : 0.0};
  for (int ch = 0; ch < 4; ++ch) {
    const std::uint32_t value = ch < 3 ? (word >> (10 * ch)) & 1023u : word >> 30;
    if (ch == 3 || (inside && ch == 2))
      EXPECT_EQ(double(value), tenBit[ch]) << where << " attachment 1 channel " << ch;
    else
      expectNear(value, tenBit[ch], where + " attachment 1 channel " + std::to_string(ch));
  }
  // 2: R16G16B16A16_SFLOAT, exact halves: inside (-1, 0.375, -1, 0.75), outside the clear
  // (-0.5, 2, 0.25, 1).
  ASSERT_EQ(f.moreColour[1].colourWords.size(), f.rgba.size() / 2);
  const std::uint32_t lo = f.moreColour[1].colourWords[2 * p], hi = f.moreColour[1].colourWords[2 * p + 1];
  EXPECT_EQ(lo, inside ? 0x3600BC00u : 0x4000B800u) << where << " attachment 2 (red, green halves)";
  EXPECT_EQ(hi, inside ? 0x3A00BC00u : 0x3C003400u) << where << " attachment 2 (blue, alpha halves)";
  // 3: R8G8B8A8_SRGB, red and green written: (0.375, 0.5625) encoded; blue and alpha the clear's.
  const std::uint8_t* s = &f.moreColour[2].rgba[4 * p];
  expectNear(s[0], inside ? srgbByte(0.375f) : 0, where + " attachment 3 red");
  expectNear(s[1], inside ? srgbByte(0.5625f) : 0, where + " attachment 3 green");
  EXPECT_EQ(int(s[2]), 255) << where << " attachment 3 blue";
  EXPECT_EQ(int(s[3]), 153) << where << " attachment 3 alpha";
  EXPECT_TRUE(f.moreColour[2].colourWords.empty()) << "8-bit formats have no stored words";
}

void expectSameColourImages(const vkref::FrameImages& a, const vkref::FrameImages& b) {
  ASSERT_EQ(a.moreColour.size(), b.moreColour.size());
  for (std::size_t i = 0; i < a.moreColour.size(); ++i) {
    EXPECT_TRUE(a.moreColour[i].rgba == b.moreColour[i].rgba) << "attachment " << i + 1 << " differs";
    EXPECT_TRUE(a.moreColour[i].colourWords == b.moreColour[i].colourWords) << "attachment " << i + 1 << " differs";
    EXPECT_TRUE(a.moreColour[i].sampleRgba == b.moreColour[i].sampleRgba) << "attachment " << i + 1 << " samples differ";
    EXPECT_TRUE(a.moreColour[i].sampleColourWords == b.moreColour[i].sampleColourWords)
        << "attachment " << i + 1 << " samples differ";
  }
}

TEST_F(PreparedFrame, SeveralColourAttachmentsBlendAndResolveEachTheirOwnWay) {
  const vkref::ShaderProgram program = colourOutputsProgram();
  for (std::uint32_t samples : {1u, 4u}) {
    SCOPED_TRACE("samples " + std::to_string(samples));
    auto frame = renderer_->prepare(fourAttachments(program, samples));
    ASSERT_TRUE(frame) << frame.error();
    ASSERT_TRUE(renderer_->submit(*frame));
    auto first = renderer_->readBack(*frame);
    ASSERT_TRUE(first) << first.error();
    ASSERT_TRUE(renderer_->submit(*frame));  // again: the same images
    auto again = renderer_->readBack(*frame);
    ASSERT_TRUE(again) << again.error();
    expectSameImages(*first, *again);
    expectSameColourImages(*first, *again);

    const vkref::FrameImages& f = *first;
    const std::size_t pixels = std::size_t{kMrtSize} * kMrtSize;
    ASSERT_EQ(f.moreColour.size(), 3u);
    for (const vkref::ColourImages& more : f.moreColour) ASSERT_EQ(more.rgba.size(), 4 * pixels);
    // The triangle spans x in [-0.9, 0.9] at its base (y = -0.9, the top rows) and its apex at
    // (0, 0.9): the centre is inside, the corners are not.
    expectFourAttachments(f, (kMrtSize / 2) * kMrtSize + kMrtSize / 2, true);
    expectFourAttachments(f, (kMrtSize / 3) * kMrtSize + kMrtSize / 2, true);
    expectFourAttachments(f, 0, false);
    expectFourAttachments(f, pixels - 1, false);

    if (samples == 1) {
      EXPECT_EQ(f.samples, 1u);
      for (const vkref::ColourImages& more : f.moreColour) {
        EXPECT_TRUE(more.sampleRgba.empty());
        EXPECT_TRUE(more.sampleColourWords.empty());
      }
      continue;
    }
    // Every sample of every attachment: where a pixel's samples agree, the resolve is that sample.
    ASSERT_EQ(f.samples, 4u);
    std::size_t agreeing = 0;
    for (std::size_t a = 0; a < 4; ++a) {
      SCOPED_TRACE("attachment " + std::to_string(a));
      const std::vector<std::uint8_t>& rgba = a == 0 ? f.rgba : f.moreColour[a - 1].rgba;
      const std::vector<std::uint8_t>& sampleRgba = a == 0 ? f.sampleRgba : f.moreColour[a - 1].sampleRgba;
      const std::vector<std::uint32_t>& words = a == 0 ? f.colourWords : f.moreColour[a - 1].colourWords;
      const std::vector<std::uint32_t>& sampleWords = a == 0 ? f.sampleColourWords : f.moreColour[a - 1].sampleColourWords;
      ASSERT_EQ(sampleRgba.size(), 16 * pixels);
      ASSERT_EQ(sampleWords.size(), 4 * words.size());
      const std::size_t w = words.size() / pixels;  // stored words per sample: 0, 1 or 2
      for (std::size_t p = 0; p < pixels; ++p) {
        bool agree = true;
        for (std::size_t s = 1; s < 4; ++s) {
          agree = agree && std::memcmp(&sampleRgba[16 * p], &sampleRgba[16 * p + 4 * s], 4) == 0;
          for (std::size_t k = 0; k < w; ++k) agree = agree && sampleWords[4 * w * p + k] == sampleWords[4 * w * p + w * s + k];
        }
        if (!agree) continue;
        ++agreeing;
        ASSERT_EQ(std::memcmp(&rgba[4 * p], &sampleRgba[16 * p], 4), 0) << "pixel " << p;
        for (std::size_t k = 0; k < w; ++k) ASSERT_EQ(words[w * p + k], sampleWords[4 * w * p + k]) << "pixel " << p;
      }
    }
    EXPECT_GT(agreeing, 4 * pixels / 2);
    EXPECT_LT(agreeing, 4 * pixels);  // the triangle's edges cover some samples only
  }
}

TEST_F(PreparedFrame, TooManyColourAttachmentsOrAnUnusableFormatIsAnError) {
  const vkref::ShaderProgram program = colourOutputsProgram();
  vkref::FrameRequest request = fourAttachments(program, 1);
  request.moreColour.resize(8);  // 9 attachments
  const auto tooMany = renderer_->prepare(request);
  ASSERT_FALSE(tooMany);
  EXPECT_EQ(tooMany.error(), "9 colour attachments (at most 8)");

  request = fourAttachments(program, 1);
  request.moreColour[1].format = static_cast<softraster::ColourFormat>(99);
  const auto unusable = renderer_->prepare(request);
  ASSERT_FALSE(unusable);
  EXPECT_NE(unusable.error().find("colour attachment 2: colour format 99"), std::string::npos) << unusable.error();

  request = fourAttachments(program, 1);
  request.draws[0].state.moreBlend[1].dstColorBlendFactor = static_cast<softraster::BlendFactor>(20);
  const auto badFactor = renderer_->prepare(request);
  ASSERT_FALSE(badFactor);
  EXPECT_EQ(badFactor.error(), "draw 0: colour attachment 2: unknown blend factor");
}

}  // namespace
