// Fuzz target: softraster's draw input. The input's bytes become a framebuffer (1..48 pixels a
// side, 1 or 4 samples, every depth and colour format), a PipelineState (every field, out-of-range enum
// values and non-finite floats included), the vertex_color twin's uniforms (a matrix of any
// floats or a tame one) and up to 64 vertices and 128 indices, drawn with Context::draw or
// drawIndexed.
// Properties: no crash and no undefined behaviour; the exact method (SIMD fast path, on one
// thread or in row bands on three) and the scalar reference agree on the Status and on every byte of every sample, as
// docs/architecture.md promises for every input. The course's methods (scanline, trapezoid,
// barycentric, with perspective or affine varyings) draw every input too: they must not crash,
// hang or touch memory outside the framebuffer, and give the same Status as the reference; their
// pixels are not compared (they are other algorithms).
// Deliberately no Vulkan: lavapipe is compared in the scene tests, this is softraster alone.
#include "fuzz_support.hpp"

#include <vertex_color.hpp>

#include <softraster/framebuffer.hpp>
#include <softraster/pipeline.hpp>

#include <vector>

namespace {

using namespace softraster;
using Shader = shaders::VertexColor;

PipelineState readState(fuzz::ByteReader& in) {
  PipelineState s;
  s.topology = static_cast<Topology>(in.below(7));  // 6: not a topology
  if (in.flag()) {
    s.viewport = {in.number(), in.number(), in.number(), in.number(), in.number(), in.number()};
  }
  if (in.flag()) {
    if (in.flag()) {
      s.scissor = {static_cast<std::int32_t>(in.word()), static_cast<std::int32_t>(in.word()), in.word(), in.word()};
    } else {
      s.scissor = {static_cast<std::int8_t>(in.byte()), static_cast<std::int8_t>(in.byte()), in.byte(), in.byte()};
    }
  }
  RasterizationState& r = s.rasterization;
  r.polygonMode = static_cast<PolygonMode>(in.below(3));
  r.cullMode = static_cast<CullMode>(in.below(4));
  r.frontFace = static_cast<FrontFace>(in.below(2));
  r.depthClampEnable = in.flag();
  r.depthBias = {in.flag(), in.number(), in.number(), in.number()};
  r.lineWidth = in.flag() ? in.number() : static_cast<float>(1 + in.below(8));
  r.lineRasterization = static_cast<LineRasterization>(in.below(2));
  s.depth.testEnable = in.flag();
  s.depth.writeEnable = in.flag();
  s.depth.compareOp = static_cast<CompareOp>(in.below(8));
  BlendState& b = s.blend;
  b.enable = in.flag();
  b.srcColorBlendFactor = static_cast<BlendFactor>(in.below(16));  // 15: not a factor
  b.dstColorBlendFactor = static_cast<BlendFactor>(in.below(16));
  b.colorBlendOp = static_cast<BlendOp>(in.below(6));              // 5: not an op
  b.srcAlphaBlendFactor = static_cast<BlendFactor>(in.below(16));
  b.dstAlphaBlendFactor = static_cast<BlendFactor>(in.below(16));
  b.alphaBlendOp = static_cast<BlendOp>(in.below(6));
  b.colorWriteMask = static_cast<std::uint8_t>(in.below(17));      // 16: a bit that is no channel
  for (float& c : b.blendConstants) c = in.number();
  return s;
}

Shader::Uniforms readUniforms(fuzz::ByteReader& in) {
  Shader::Uniforms u;
  u.modelViewProjection = Mat4::identity();
  if (in.flag()) {
    for (Vec4& column : u.modelViewProjection.columns) column = {in.number(), in.number(), in.number(), in.number()};
  } else if (in.flag()) {
    // A perspective-like matrix: w = z, so vertices at z > 0 are in front.
    u.modelViewProjection.columns[2] = {0, 0, 0.5f, 1};
    u.modelViewProjection.columns[3] = {0, 0, 0.25f, 0};
  }
  u.pointSize = in.flag() ? in.number() : static_cast<float>(1 + in.below(16));
  return u;
}

// Draws the same input with one Context; the Status and every sample are what is compared.
struct Outcome {
  Status status;
  std::vector<std::uint8_t> colour;
  std::vector<std::uint32_t> depth;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const Context exact(ContextOptions{Method::Exact, 1});
  static const Context exactThreads(ContextOptions{Method::Exact, 3});  // row bands on three threads
  static const Context scalar(ContextOptions{Method::ExactScalar, 1});
  const auto courseContext = [](Method method, bool affine) {
    ContextOptions options{method, 1};
    options.affineVaryings = affine;
    return options;
  };
  static const Context course[2][3] = {
      {Context(courseContext(Method::Scanline, false)), Context(courseContext(Method::Trapezoid, false)),
       Context(courseContext(Method::Barycentric, false))},
      {Context(courseContext(Method::Scanline, true)), Context(courseContext(Method::Trapezoid, true)),
       Context(courseContext(Method::Barycentric, true))}};
  fuzz::ByteReader in(data, size);
  const std::uint32_t width = 1 + in.below(48), height = 1 + in.below(48);
  const std::uint32_t samples = in.flag() ? 4 : 1;
  const auto format = static_cast<DepthFormat>(in.below(3));
  const Vec4 clearColour{in.number(), in.number(), in.number(), in.number()};
  const float clearDepth = in.flag() ? in.number() : static_cast<float>(in.below(5)) / 4;
  const PipelineState state = readState(in);
  const Shader::Uniforms uniforms = readUniforms(in);
  const bool indexed = in.flag();
  std::vector<Shader::Vertex> vertices(in.below(65));
  for (Shader::Vertex& v : vertices) {
    v.position = {in.number(), in.number(), in.number()};
    v.colour = {in.number(), in.number(), in.number(), in.number()};
  }
  std::vector<std::uint32_t> indices(in.below(129));
  for (std::uint32_t& i : indices) i = in.below(static_cast<unsigned>(vertices.size()) + 2);  // some past the end
  // Read last, so inputs that end before it keep their meaning: one in eight draws on three
  // threads (waking threads costs more than most of these small draws).
  const bool onThreads = in.below(8) == 7;
  const bool affine = in.flag();
  const auto colourFormat = static_cast<ColourFormat>(in.below(7));  // every colour format

  const auto drawWith = [&](const Context& context) {
    Framebuffer framebuffer = Framebuffer::create(width, height, format, samples, colourFormat).value();
    framebuffer.clear(clearColour, clearDepth);
    Outcome out;
    out.status = indexed ? context.drawIndexed<Shader>(state, uniforms, vertices, indices, framebuffer)
                         : context.draw<Shader>(state, uniforms, vertices, framebuffer);
    out.colour = framebuffer.colour();
    out.depth = framebuffer.depthStorage();
    return out;
  };
  const Outcome fast = drawWith(onThreads ? exactThreads : exact);
  const Outcome reference = drawWith(scalar);
  fuzz::require(fast.status.ok() == reference.status.ok() && fast.status.message() == reference.status.message(),
                "both methods give the same Status", fast.status.message() + " / " + reference.status.message());
  for (std::size_t i = 0; i < fast.colour.size(); ++i) {
    fuzz::require(fast.colour[i] == reference.colour[i], "both methods give the same colour bytes",
                  "byte " + std::to_string(i) + " of sample " + std::to_string(i / 4));
  }
  for (std::size_t i = 0; i < fast.depth.size(); ++i) {
    fuzz::require(fast.depth[i] == reference.depth[i], "both methods give the same depth",
                  "sample " + std::to_string(i));
  }
  for (const Context& context : course[affine ? 1 : 0]) {
    const Outcome drawn = drawWith(context);
    fuzz::require(drawn.status.ok() == reference.status.ok() && drawn.status.message() == reference.status.message(),
                  "a course method gives the reference's Status", drawn.status.message() + " / " + reference.status.message());
  }
  return 0;
}
