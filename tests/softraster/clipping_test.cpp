// Clipping in clip space as Mesa's draw module does it.
#include <softraster/detail/geometry/clipping.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using namespace softraster::detail;
using softraster::Vec4;

ShadedVertex<1> vertex(Vec4 clip, float varying, const ViewportTransform& vp) {
  ShadedVertex<1> v;
  v.clip = clip;
  v.clipMask = computeClipMask(clip);
  v.window = windowPosition<false>(clip, vp);
  v.varyings[0] = varying;
  return v;
}

constexpr softraster::InterpolationSet<1> kSmooth{softraster::Interpolation::Perspective};

ViewportTransform viewport() {
  softraster::Viewport vp;
  vp.width = 64;
  vp.height = 64;
  return makeViewportTransform(vp);
}

}  // namespace

TEST(ClipMask, PlanesAndNaN) {
  EXPECT_EQ(computeClipMask({0, 0, 0.5f, 1}), 0u);
  EXPECT_EQ(computeClipMask({2, 0, 0.5f, 1}), kOutsideRight);
  EXPECT_EQ(computeClipMask({-2, 0, 0.5f, 1}), kOutsideLeft);
  EXPECT_EQ(computeClipMask({0, 2, 0.5f, 1}), kOutsideBottom);
  EXPECT_EQ(computeClipMask({0, -2, 0.5f, 1}), kOutsideTop);
  EXPECT_EQ(computeClipMask({0, 0, -0.5f, 1}), kOutsideNear);
  EXPECT_EQ(computeClipMask({0, 0, 1.5f, 1}), kOutsideFar);
  // Unordered comparisons: a NaN fails every test it takes part in. NaN x: both x planes;
  // NaN w: every plane but the near one (z >= 0 does not read w).
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(computeClipMask({nan, 0, 0.5f, 1}), kOutsideLeft | kOutsideRight);
  EXPECT_EQ(computeClipMask({0, 0, 0.5f, nan}), 0x3fu & ~kOutsideNear);
  // Behind the camera (w < 0) a vertex is outside both x planes, whatever its x.
  EXPECT_EQ(computeClipMask({0, 0, 0.5f, -1}) & (kOutsideLeft | kOutsideRight), kOutsideLeft | kOutsideRight);
}

TEST(Clipping, TriangleCrossingTheNearPlaneBecomesAQuad) {
  const auto vp = viewport();
  // v0 behind the near plane (z < 0), v1 and v2 in front.
  const auto v0 = vertex({0, 0, -1, 1}, 10, vp);
  const auto v1 = vertex({-0.5f, 0.5f, 0.5f, 1}, 20, vp);
  const auto v2 = vertex({0.5f, 0.5f, 0.5f, 1}, 30, vp);
  ASSERT_EQ(v0.clipMask, kOutsideNear);
  ClippedPolygon<1> polygon;
  ASSERT_TRUE(clipTriangle(v0, v1, v2, v0.clipMask | v1.clipMask | v2.clipMask, vp, kSmooth, polygon));
  ASSERT_EQ(polygon.count, 4);
  // The polygon starts where v0's edge to v1 comes back in, then v1, v2, and v2's edge to v0.
  EXPECT_EQ(polygon.vertices[1].clip.x, v1.clip.x);
  EXPECT_EQ(polygon.vertices[2].clip.x, v2.clip.x);
  for (int i : {0, 3}) {
    const auto& v = polygon.vertices[i];
    EXPECT_NEAR(v.clip.z, 0.0f, 1e-7f) << i;
    EXPECT_EQ(v.clipMask, 0u);
    // Interpolated from the endpoint nearer the plane (v0, distance 1, versus 0.5): t = 2/3 from v1/v2.
    EXPECT_NEAR(v.varyings[0], i == 0 ? 20 + (10 - 20) * (0.5f / 1.5f) : 30 + (10 - 30) * (0.5f / 1.5f), 1e-5f);
    // Window position recomputed as pos * (1/w) * scale + trans.
    EXPECT_EQ(v.window.x, v.clip.x * (1.0f / v.clip.w) * vp.scale[0] + vp.translate[0]);
  }
}

TEST(Clipping, NaNDistanceDropsTheTriangle) {
  const auto vp = viewport();
  const auto v0 = vertex({std::numeric_limits<float>::quiet_NaN(), 0, 0.5f, 1}, 0, vp);
  const auto v1 = vertex({-0.5f, 0.5f, 0.5f, 1}, 0, vp);
  const auto v2 = vertex({0.5f, 0.5f, 0.5f, 1}, 0, vp);
  ClippedPolygon<1> polygon;
  EXPECT_FALSE(clipTriangle(v0, v1, v2, v0.clipMask | v1.clipMask | v2.clipMask, vp, kSmooth, polygon));
}

TEST(Clipping, TriangleCrossingAllFourSidesKeepsAllNewVerticesInside) {
  const auto vp = viewport();
  const auto v0 = vertex({-3, -3, 0.5f, 1}, 0, vp);
  const auto v1 = vertex({-3, 4, 0.5f, 1}, 1, vp);
  const auto v2 = vertex({4, -3, 0.5f, 1}, 2, vp);
  ClippedPolygon<1> polygon;
  ASSERT_TRUE(clipTriangle(v0, v1, v2, v0.clipMask | v1.clipMask | v2.clipMask, vp, kSmooth, polygon));
  EXPECT_GE(polygon.count, 4);
  for (int i = 0; i < polygon.count; ++i) {
    const Vec4 c = polygon.vertices[i].clip;
    EXPECT_LE(std::fabs(c.x), c.w * (1 + 1e-6f)) << i;
    EXPECT_LE(std::fabs(c.y), c.w * (1 + 1e-6f)) << i;
  }
}
