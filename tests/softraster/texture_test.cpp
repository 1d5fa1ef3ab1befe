// Textures: creation and its errors, the mip chain both renderers upload, the sampler states
// softraster refuses, and the pieces of lavapipe's 8-bit and float sampling paths on values
// worked out by hand from gallivm's instructions (pmulhrsw lerp, cvtps2dq rounding, wrap
// arithmetic, mirroring, the sRGB cubic, the LOD).
// Whole images are cross-checked against lavapipe by the texture_*.json scenes.
#include <softraster/texture.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace {

using namespace softraster;
namespace t = softraster::detail::texture;

std::vector<std::uint8_t> texels(std::uint32_t w, std::uint32_t h, std::uint8_t value = 0) {
  return std::vector<std::uint8_t>(std::size_t{w} * h * 4, value);
}

TEST(Texture, CreateRefusesBadSizesAndData) {
  EXPECT_FALSE(Texture::create(TextureFormat::R8G8B8A8Unorm, 0, 4, {}, false));
  EXPECT_FALSE(Texture::create(TextureFormat::R8G8B8A8Unorm, 16385, 1, texels(16385, 1), false));
  const auto shortData = texels(4, 4);
  const auto r = Texture::create(TextureFormat::R8G8B8A8Unorm, 4, 5, shortData, false);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error(), "texture data has 64 bytes where 4x5 RGBA8 needs 80");
}

TEST(Texture, MipChainHalvesDownToOneTexel) {
  const auto data = texels(48, 40, 7);
  const auto r = Texture::create(TextureFormat::R8G8B8A8Unorm, 48, 40, data, true);
  ASSERT_TRUE(r) << r.error();
  const std::vector<std::pair<std::uint32_t, std::uint32_t>> sizes{{48, 40}, {24, 20}, {12, 10}, {6, 5}, {3, 2}, {1, 1}};
  ASSERT_EQ(r->levels(), sizes.size());
  for (std::uint32_t i = 0; i < r->levels(); ++i) {
    EXPECT_EQ(r->level(i).width, sizes[i].first);
    EXPECT_EQ(r->level(i).height, sizes[i].second);
    EXPECT_EQ(r->level(i).rgba.size(), std::size_t{sizes[i].first} * sizes[i].second * 4);
    EXPECT_EQ(r->level(i).rgba[0], 7);  // a constant image stays constant
  }
}

TEST(Texture, MipLevelIsTheRoundedAverageWithOddEdgesRepeated) {
  TextureLevel level{3, 1, {}};
  level.rgba = {0, 0, 0, 0, 1, 2, 255, 255, 10, 20, 30, 40};
  const TextureLevel next = Texture::generateMipLevel(level);
  ASSERT_EQ(next.width, 1u);
  ASSERT_EQ(next.height, 1u);
  // texels (0,0) and (1,0), and the missing row read as row 0 again:
  EXPECT_EQ(next.rgba[0], 1);    // (0 + 1 + 0 + 1 + 2) / 4 = 1
  EXPECT_EQ(next.rgba[1], 1);    // (0 + 2 + 0 + 2 + 2) / 4 = 1
  EXPECT_EQ(next.rgba[2], 128);  // (0 + 255 + 0 + 255 + 2) / 4 = 128
}

TEST(Sampler, ValidateRefusesOnlyWhatIsNotMatchedYet) {
  const auto data = texels(4, 4);
  const auto tex = Texture::create(TextureFormat::R8G8B8A8Unorm, 4, 4, data, false);
  const auto srgb = Texture::create(TextureFormat::R8G8B8A8Srgb, 4, 4, data, false);
  ASSERT_TRUE(tex && srgb);
  EXPECT_TRUE((Sampler2D{&*tex, {}}.validate()));
  EXPECT_EQ((Sampler2D{}.validate().message()), "the sampler has no texture");
  SamplerState mixed;
  mixed.minFilter = Filter::Nearest;
  EXPECT_TRUE((Sampler2D{&*tex, mixed}.validate()));  // the 8-bit path switches per quad, as lavapipe's does
  EXPECT_TRUE((Sampler2D{&*srgb, {}}.validate()));
  EXPECT_NE((Sampler2D{&*srgb, mixed}.validate().message().find("different min and mag filters")), std::string::npos);
  SamplerState mirrored;
  mirrored.addressModeV = AddressMode::MirroredRepeat;
  EXPECT_TRUE((Sampler2D{&*tex, mirrored}.validate()));
  mirrored.magFilter = Filter::Nearest;
  EXPECT_FALSE((Sampler2D{&*tex, mirrored}.validate()));
  SamplerState lod;
  lod.minLod = 3;
  lod.maxLod = 2;
  EXPECT_FALSE((Sampler2D{&*tex, lod}.validate()));
  lod.minLod = 0;
  lod.mipLodBias = 17;
  EXPECT_FALSE((Sampler2D{&*tex, lod}.validate()));
}

TEST(Sampling, LerpIsPmulhrswOnPrescaledWeights) {
  EXPECT_EQ(t::lerpUnorm8(0, 10, 200), 10);
  EXPECT_EQ(t::lerpUnorm8(255, 0, 255), 254);  // (255 * 255 * 128 + 2^14) >> 15 = 254: weight 255 is not 1
  EXPECT_EQ(t::lerpUnorm8(128, 0, 255), 128);
  EXPECT_EQ(t::lerpUnorm8(128, 255, 0), 128);  // 255 + ((128 * -255 * 128 + 2^14) >> 15) = 255 - 127: not symmetric
  EXPECT_EQ(t::lerpUnorm8(1, 0, 255), 1);      // (32640 + 16384) >> 15 = 1
  EXPECT_EQ(t::lerpUnorm8(1, 0, 127), 0);      // (16256 + 16384) >> 15 = 0
}

TEST(Sampling, RoundingAndTruncationAreTheSseConversions) {
  EXPECT_EQ(t::roundToInt(2.5f), 2);
  EXPECT_EQ(t::roundToInt(3.5f), 4);
  EXPECT_EQ(t::roundToInt(-0.5f), 0);
  EXPECT_EQ(t::roundToInt(3e9f), INT32_MIN);
  EXPECT_EQ(t::truncateToInt(-1.75f), -1);
  EXPECT_EQ(t::floorToInt(-0.25f), -1);
  EXPECT_EQ(t::floorToInt(std::numeric_limits<float>::quiet_NaN()), INT32_MIN);
}

TEST(Sampling, LinearAxisIsEightPointEightFixedPoint) {
  // u = 0.3 on 16 texels: 0.3 * 4096 = 1228.8 -> 1229, - 128 = 1101: texel 4, weight 77.
  const t::AxisTexels a = t::linearTexels(0.3f, 16, true, AddressMode::Repeat);
  EXPECT_EQ(a.i0, 4u);
  EXPECT_EQ(a.i1, 5u);
  EXPECT_EQ(a.weight, 77);
  // Below 0: repeat wraps to the last texel, clamp holds the first.
  const t::AxisTexels r = t::linearTexels(0.0f, 16, true, AddressMode::Repeat);
  EXPECT_EQ(r.i0, 15u);
  EXPECT_EQ(r.i1, 0u);
  EXPECT_EQ(r.weight, 128);
  const t::AxisTexels c = t::linearTexels(0.0f, 16, true, AddressMode::ClampToEdge);
  EXPECT_EQ(c.i0, 0u);
  EXPECT_EQ(c.i1, 0u);
  // Not a power of two: the fraction first (1.25 -> 0.25), 0.25 * 6 * 256 = 384, - 128: texel 1, weight 0.
  const t::AxisTexels n = t::linearTexels(1.25f, 6, false, AddressMode::Repeat);
  EXPECT_EQ(n.i0, 1u);
  EXPECT_EQ(n.i1, 2u);
  EXPECT_EQ(n.weight, 0);
}

TEST(Sampling, NearestAxisWrapsAndClamps) {
  EXPECT_EQ(t::nearestTexel(-0.01f, 16, true, AddressMode::Repeat), 15u);
  EXPECT_EQ(t::nearestTexel(-0.01f, 16, true, AddressMode::ClampToEdge), 0u);
  EXPECT_EQ(t::nearestTexel(1.0f, 16, true, AddressMode::ClampToEdge), 15u);
  EXPECT_EQ(t::nearestTexel(2.5f, 6, false, AddressMode::Repeat), 3u);  // fract 0.5 * 6
  EXPECT_EQ(t::nearestTexel(-1e-9f, 6, false, AddressMode::Repeat), 5u);  // fract rounds to 1, clamped below it
}

TEST(Sampling, LodFollowsFastLog2AndTheSpecialCases) {
  EXPECT_EQ(t::fastLog2(1.0f), 0.0f);
  EXPECT_EQ(t::fastLog2(8.0f), 3.0f);
  EXPECT_EQ(t::fastLog2(3.0f), 1.5f);  // piecewise linear: 1 + (1.5 - 1)
  EXPECT_EQ(t::ilog2Sqrt(16.0f), 2);   // iround(log2(sqrt(16)))
  EXPECT_EQ(t::ilog2Sqrt(8.0f), 2);    // log2(sqrt(8)) = 1.5 rounds up
  SamplerState s;
  s.mipmapMode = MipmapMode::Linear;
  const t::StaticSampler d = t::staticSampler(s, 7);
  // rho^2 = 12: lod = 0.5 * (3 + 0.5) = 1.75: levels 1 and 2, weight trunc(0.75 * 256) = 192.
  const t::QuadLod q = t::quadLod(d, 12.0f, 7);
  EXPECT_TRUE(q.minified);
  EXPECT_EQ(q.level0, 1u);
  EXPECT_EQ(q.level1, 2u);
  EXPECT_EQ(q.mipWeight, 192);
  // One level and maxLod > 0: no mip filter, no LOD at all (min == mag).
  const t::StaticSampler single = t::staticSampler(SamplerState{}, 1);
  EXPECT_EQ(single.mip, t::StaticSampler::Mip::None);
  EXPECT_EQ(t::quadLod(single, 1e6f, 1).level0, 0u);
}

TEST(Sampling, FloatPathWrapsMirrorsAndBorders) {
  EXPECT_EQ(t::mirrorCoordinate(0.25f), 0.25f);
  EXPECT_EQ(t::mirrorCoordinate(1.25f), 0.75f);   // reflected at 1
  EXPECT_EQ(t::mirrorCoordinate(-0.25f), 0.25f);  // reflected at 0
  EXPECT_EQ(t::mirrorCoordinate(std::numeric_limits<float>::quiet_NaN()), 0.0f);
  EXPECT_EQ(t::nearestTexelFloat(1.25f, 8, true, AddressMode::MirroredRepeat), 6);  // 0.75 * 8
  EXPECT_EQ(t::nearestTexelFloat(-0.1f, 8, true, AddressMode::ClampToBorder), -1);  // outside: the border
  const t::AxisTexelsFloat b = t::linearTexelsFloat(0.0f, 8, true, AddressMode::ClampToBorder);
  EXPECT_EQ(b.i0, -1);
  EXPECT_EQ(b.i1, 0);
  EXPECT_EQ(b.weight, 0.5f);
  const t::AxisTexelsFloat m = t::linearTexelsFloat(0.0f, 8, true, AddressMode::MirroredRepeat);
  EXPECT_EQ(m.i0, 0);  // -1 held at 0: the mirror of texel 0 is texel 0
  EXPECT_EQ(m.i1, 0);
  // sRGB: linear below 16 (v / 3213), the cubic above; both ends as lavapipe's approximation gives them.
  EXPECT_EQ(softraster::detail::srgbToLinear(0), 0.0f);
  EXPECT_EQ(softraster::detail::srgbToLinear(10), 10.0f * (1.0f / (12.6f * 255.0f)));
  EXPECT_NEAR(softraster::detail::srgbToLinear(255), 1.0f, 0.001f);
  EXPECT_NEAR(softraster::detail::srgbToLinear(128), 0.2158f, 0.002f);  // the sRGB curve gives 0.2159
}

TEST(Sampling, MagnifiedQuadFiltersEachLane) {
  // A 2x1 texture, black then white, linear: lanes across u from 0.25 to 0.75.
  const std::vector<std::uint8_t> data{0, 0, 0, 255, 255, 255, 255, 255};
  const auto tex = Texture::create(TextureFormat::R8G8B8A8Unorm, 2, 1, data, false);
  ASSERT_TRUE(tex);
  SamplerState s;
  s.addressModeU = s.addressModeV = AddressMode::ClampToEdge;
  alignas(32) float u[8] = {0.25f, 0.5f, 0.5f, 0.75f, 0.25f, 0.5f, 0.5f, 0.75f};
  alignas(32) float v[8] = {0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f};
  const Vec4T<FloatBatch> c = texture(Sampler2D{&*tex, s}, FloatBatch::load(u), FloatBatch::load(v));
  EXPECT_EQ(c.x[0], 0.0f);                           // at texel 0's centre
  EXPECT_EQ(c.x[1], 128.0f * static_cast<float>(1.0 / 255.0));  // halfway: weight 128 of 255
  EXPECT_EQ(c.x[3], 255.0f * static_cast<float>(1.0 / 255.0));  // texel 1's centre: weight 0 from texel 1
  EXPECT_EQ(c.w[0], 1.0f);
}

}  // namespace

// The library guide's example (docs/library.md, "Textures"): a shader twin that samples, drawn
// through Context with a 2x2 texture magnified over the framebuffer, nearest filtering.
#include <softraster/pipeline.hpp>

namespace {

struct GuideTextured {
  struct Vertex {
    softraster::Vec3 position;
    softraster::Vec2 uv;
  };
  struct Uniforms {
    softraster::Mat4 mvp;
    softraster::Sampler2D albedo;
  };
  static constexpr int kVaryings = 2;
  static constexpr bool kQuads = true;
  static softraster::Vec4 vertex(const Uniforms& u, const Vertex& in, float* out) {
    out[0] = in.uv.x;
    out[1] = in.uv.y;
    const softraster::Mat4& m = u.mvp;
    return m.columns[0] * in.position.x + m.columns[1] * in.position.y + m.columns[2] * in.position.z + m.columns[3];
  }
  template <class F>
  static softraster::Vec4T<F> fragment(const Uniforms& u, const F* v) {
    return softraster::texture(u.albedo, v[0], v[1]);
  }
};

TEST(Sampling, GuideShaderDrawsTheTextureOnEveryPath) {
  const std::vector<std::uint8_t> rgba{255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
  const auto texture = Texture::create(TextureFormat::R8G8B8A8Unorm, 2, 2, rgba, true);
  ASSERT_TRUE(texture);
  SamplerState sampler;
  sampler.magFilter = sampler.minFilter = Filter::Nearest;
  const Sampler2D albedo{&*texture, sampler};
  ASSERT_TRUE(albedo.validate());
  const std::vector<GuideTextured::Vertex> vertices{
      {{-1, -1, 0.5f}, {0, 0}}, {{1, -1, 0.5f}, {1, 0}}, {{1, 1, 0.5f}, {1, 1}}, {{-1, 1, 0.5f}, {0, 1}}};
  const std::vector<std::uint32_t> indices{0, 2, 1, 0, 3, 2};
  PipelineState state;
  state.rasterization.cullMode = CullMode::None;
  for (Method method : {Method::Exact, Method::ExactScalar}) {
    const Context context(ContextOptions{method, 2});
    auto framebuffer = Framebuffer::create(16, 16, DepthFormat::D32Sfloat, 1);
    ASSERT_TRUE(framebuffer);
    framebuffer->clear({0, 0, 0, 1}, 1.0f);
    ASSERT_TRUE((context.drawIndexed<GuideTextured>(state, {Mat4::identity(), albedo}, vertices, indices, *framebuffer)));
    // Each quarter of the framebuffer shows one texel (row 0 at the top, as the texture's).
    const auto at = [&](std::uint32_t x, std::uint32_t y) { return framebuffer->colourAt(x, y, 0); };
    EXPECT_EQ(at(2, 2)[0], 255);
    EXPECT_EQ(at(2, 2)[1], 0);
    EXPECT_EQ(at(13, 2)[1], 255);
    EXPECT_EQ(at(2, 13)[2], 255);
    EXPECT_EQ(at(13, 13)[0], 255);
    EXPECT_EQ(at(13, 13)[1], 255);
  }
}

}  // namespace

// ---- Depth textures and comparison samplers (shadow maps) ----------------------------------

// A width x height D32_SFLOAT framebuffer whose depth at (x, y) is `depth(x, y)`.
template <class Depth>
Framebuffer depthFramebuffer(std::uint32_t width, std::uint32_t height, Depth depth) {
  Framebuffer f = *Framebuffer::create(width, height, DepthFormat::D32Sfloat, 1);
  f.clear({0, 0, 0, 0}, 1.0f);
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      const float d = depth(x, y);
      std::memcpy(&f.depthStorage()[f.sampleIndex(x, y)], &d, sizeof d);
    }
  }
  return f;
}

TEST(DepthTexture, FromDepthCopiesTheFloatsOfASingleSampleD32Framebuffer) {
  const Framebuffer f = depthFramebuffer(3, 2, [](std::uint32_t x, std::uint32_t y) { return 0.125f * x + 0.5f * y; });
  const auto t = Texture::fromDepth(f);
  ASSERT_TRUE(t) << t.error();
  EXPECT_EQ(t->format(), TextureFormat::D32Sfloat);
  ASSERT_EQ(t->levels(), 1u);
  EXPECT_EQ(t->width(), 3u);
  EXPECT_EQ(t->height(), 2u);
  float texel;
  std::memcpy(&texel, t->level(0).rgba.data() + (1 * 3 + 2) * 4, sizeof texel);
  EXPECT_EQ(texel, 0.75f);  // (2, 1)

  const auto d16 = Texture::fromDepth(*Framebuffer::create(4, 4, DepthFormat::D16Unorm, 1));
  ASSERT_FALSE(d16);
  EXPECT_EQ(d16.error(), "a depth texture is made from a D32_SFLOAT framebuffer only");
  const auto msaa = Texture::fromDepth(*Framebuffer::create(4, 4, DepthFormat::D32Sfloat, 4));
  ASSERT_FALSE(msaa);
  EXPECT_EQ(msaa.error(), "a depth texture is made from a single-sample framebuffer only");
  EXPECT_FALSE(Texture::fromDepth(Framebuffer{}));
}

TEST(DepthTexture, ValidateRefusesCompareOnColourAndLinearFilteringOfDepth) {
  const auto colour = Texture::create(TextureFormat::R8G8B8A8Unorm, 4, 4, texels(4, 4), false);
  const auto depth = Texture::fromDepth(depthFramebuffer(4, 4, [](std::uint32_t, std::uint32_t) { return 0.5f; }));
  ASSERT_TRUE(colour && depth);
  SamplerState compare;
  compare.compareEnable = true;
  compare.compareOp = CompareOp::LessOrEqual;
  compare.magFilter = compare.minFilter = Filter::Nearest;
  EXPECT_EQ(Sampler2D({&*colour, compare}).validate().message(), "a comparison sampler needs a depth texture");
  EXPECT_TRUE(Sampler2D({&*depth, compare}).validate()) << Sampler2D({&*depth, compare}).validate().message();
  SamplerState linear = compare;
  linear.magFilter = Filter::Linear;
  EXPECT_NE(Sampler2D({&*depth, linear}).validate().message().find("nearest filters only"), std::string::npos);
  SamplerState plain;  // a plain sampler on a depth texture (the manual compare) is fine when nearest
  plain.magFilter = plain.minFilter = Filter::Nearest;
  EXPECT_TRUE(Sampler2D({&*depth, plain}).validate());
}

TEST(DepthTexture, CompareOpsAreOrderedButNotEqual) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_TRUE(t::compareDepth(CompareOp::LessOrEqual, 0.5f, 0.5f));
  EXPECT_FALSE(t::compareDepth(CompareOp::Less, 0.5f, 0.5f));
  EXPECT_TRUE(t::compareDepth(CompareOp::Greater, 0.6f, 0.5f));
  EXPECT_TRUE(t::compareDepth(CompareOp::GreaterOrEqual, 0.5f, 0.5f));
  EXPECT_TRUE(t::compareDepth(CompareOp::Equal, 0.5f, 0.5f));
  EXPECT_FALSE(t::compareDepth(CompareOp::Never, 0.5f, 0.5f));
  EXPECT_TRUE(t::compareDepth(CompareOp::Always, nan, 0.5f));
  for (CompareOp op : {CompareOp::Less, CompareOp::Equal, CompareOp::LessOrEqual, CompareOp::Greater,
                       CompareOp::GreaterOrEqual}) {
    EXPECT_FALSE(t::compareDepth(op, nan, 0.5f)) << static_cast<int>(op);  // ordered: false with a NaN
    EXPECT_FALSE(t::compareDepth(op, 0.5f, nan)) << static_cast<int>(op);
  }
  EXPECT_TRUE(t::compareDepth(CompareOp::NotEqual, nan, 0.5f));  // unordered: true with a NaN
  EXPECT_FALSE(t::compareDepth(CompareOp::NotEqual, 0.5f, 0.5f));
}

TEST(DepthTexture, TextureShadowComparesTheNearestTexelAndTheBorder) {
  // A 4x4 map: depth 0.25 in the left half, 0.75 in the right.
  const auto map = Texture::fromDepth(depthFramebuffer(4, 4, [](std::uint32_t x, std::uint32_t) { return x < 2 ? 0.25f : 0.75f; }));
  ASSERT_TRUE(map);
  SamplerState s;
  s.magFilter = s.minFilter = Filter::Nearest;
  s.compareEnable = true;
  s.compareOp = CompareOp::LessOrEqual;
  s.addressModeU = s.addressModeV = AddressMode::ClampToBorder;
  s.borderColor = BorderColor::OpaqueWhite;
  const Sampler2D sampler{&*map, s};
  alignas(32) const float u[kBatchLanes] = {0.1f, 0.1f, 0.9f, 0.9f, 0.49f, 0.51f, -0.1f, 1.2f};
  alignas(32) const float v[kBatchLanes] = {0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f};
  alignas(32) const float r[kBatchLanes] = {0.2f, 0.3f, 0.7f, 0.8f, 0.3f, 0.3f, 0.99f, 1.0f};
  alignas(32) float out[kBatchLanes];
  textureShadow(sampler, FloatBatch::load(u), FloatBatch::load(v), FloatBatch::load(r)).store(out);
  const float expected[kBatchLanes] = {1, 0, 1, 0, 0, 1, 1, 1};  // the border's red is depth 1
  for (int lane = 0; lane < kBatchLanes; ++lane) EXPECT_EQ(out[lane], expected[lane]) << "lane " << lane;

  // texture() on the same map reads the depth as (d, 0, 0, 1); textureShadow without compare gives 0.
  SamplerState plain = s;
  plain.compareEnable = false;
  const Vec4T<FloatBatch> c = texture(Sampler2D{&*map, plain}, FloatBatch::load(u), FloatBatch::load(v));
  EXPECT_EQ(c.x[0], 0.25f);
  EXPECT_EQ(c.x[2], 0.75f);
  EXPECT_EQ(c.y[0], 0.0f);
  EXPECT_EQ(c.w[0], 1.0f);
  EXPECT_EQ(c.x[6], 1.0f);  // the border
  textureShadow(Sampler2D{&*map, plain}, FloatBatch::load(u), FloatBatch::load(v), FloatBatch::load(r)).store(out);
  for (float lane : out) EXPECT_EQ(lane, 0.0f);
}
