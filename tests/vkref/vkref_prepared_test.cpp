// vkref's prepared frames on lavapipe, with the validation layer on (any message fails): a frame
// submitted again gives the same images as the first submission and as render(); pipelines are
// compiled once per Renderer, however many draws and frames use them; misuse is an error value.
#include <vkref/renderer.hpp>

#include <shaders/vertex_color_frag.spv.h>
#include <shaders/vertex_color_vert.spv.h>
#include <vertex_color.hpp>

#include <gtest/gtest.h>

#include <cmath>
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

}  // namespace
