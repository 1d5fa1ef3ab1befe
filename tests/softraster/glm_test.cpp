// softraster/glm.hpp: GLM's vectors and matrices convert bit for bit both ways, and both routes
// from GLM's GL-style projection to Vulkan's clip space (flipClipY on a zero-to-one projection,
// vulkanFromGlClip times a GL one) put the near plane at z = 0, the far one at z = w and +y down.
// Deliberately not a test of GLM itself.
#include <softraster/glm.hpp>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <bit>

namespace {

TEST(Glm, MatricesAndVectorsConvertExactly) {
  glm::mat4 m(0.0f);
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) m[c][r] = 0.1f * static_cast<float>(c * 4 + r) + 1e-7f;
  }
  const softraster::Mat4 s = softraster::fromGlm(m);
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) EXPECT_EQ(std::bit_cast<std::uint32_t>(s.at(r, c)), std::bit_cast<std::uint32_t>(m[c][r]));
  }
  EXPECT_EQ(softraster::toGlm(s), m);
  const glm::vec3 v(0.3f, -1.7f, 2.9f);
  EXPECT_EQ(softraster::toGlm(softraster::fromGlm(v)), v);
  EXPECT_EQ(softraster::fromGlm(glm::vec4(v, 1.0f)).w, 1.0f);
}

// GL's perspective (z in [-w, w]) for a camera looking down -z, near 1, far 10.
glm::vec4 clipOf(const glm::mat4& projection, float x, float y, float z) { return projection * glm::vec4(x, y, z, 1.0f); }

TEST(Glm, GlClipSpaceBecomesVulkans) {
  const glm::mat4 gl = glm::perspectiveRH_NO(glm::radians(60.0f), 1.0f, 1.0f, 10.0f);
  const glm::mat4 zeroToOne = glm::perspectiveRH_ZO(glm::radians(60.0f), 1.0f, 1.0f, 10.0f);
  for (const glm::mat4& vulkan : {softraster::vulkanFromGlClip() * gl, softraster::flipClipY(zeroToOne)}) {
    const glm::vec4 nearPoint = clipOf(vulkan, 0, 0, -1), farPoint = clipOf(vulkan, 0, 0, -10);
    EXPECT_NEAR(nearPoint.z / nearPoint.w, 0.0f, 1e-6f);
    EXPECT_NEAR(farPoint.z / farPoint.w, 1.0f, 1e-6f);
    const glm::vec4 up = clipOf(vulkan, 0, 1, -5);  // above the axis in the world: the image's top, y < 0
    EXPECT_LT(up.y / up.w, 0.0f);
  }
  // flipClipY is exact: only the sign of row 1 changes.
  const glm::mat4 flipped = softraster::flipClipY(zeroToOne);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(flipped[c][1], -zeroToOne[c][1]);
}

}  // namespace
