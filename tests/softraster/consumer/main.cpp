// Draws one triangle with its own shader through the installed softraster and checks the result,
// and that the version header says what the CMake package (or pkg-config) says.
#include <softraster/pipeline.hpp>
#include <softraster/version.hpp>

#include <cstdio>
#include <cstring>
#include <vector>

struct FlatRed {
  struct Vertex {
    softraster::Vec3 position;
  };
  struct Uniforms {};
  static constexpr int kVaryings = 0;
  static softraster::Vec4 vertex(const Uniforms&, const Vertex& v, float*) {
    return {v.position.x, v.position.y, v.position.z, 1.0f};
  }
  static softraster::Vec4 fragment(const Uniforms&, const float*) { return {1, 0, 0, 1}; }
};

static_assert(softraster::ShaderInterface<FlatRed>);

int main() {
#ifdef CONSUMER_PACKAGE_VERSION
  if (std::strcmp(SOFTRASTER_VERSION_STRING, CONSUMER_PACKAGE_VERSION) != 0) {
    std::fprintf(stderr, "version.hpp says %s, the package %s\n", SOFTRASTER_VERSION_STRING, CONSUMER_PACKAGE_VERSION);
    return 1;
  }
#endif
  std::printf("softraster %s\n", SOFTRASTER_VERSION_STRING);
  if (softraster::Framebuffer::create(32, 32, softraster::DepthFormat::D32Sfloat, 2)) {
    std::fprintf(stderr, "a 2-sample framebuffer was accepted\n");
    return 1;
  }
  softraster::Result<softraster::Framebuffer> created = softraster::Framebuffer::create(32, 32);
  if (!created) {
    std::fprintf(stderr, "%s\n", created.error().c_str());
    return 1;
  }
  softraster::Framebuffer& framebuffer = *created;
  framebuffer.clear({0, 0, 0, 1}, 1.0f);
  const std::vector<FlatRed::Vertex> vertices{{{-1, -1, 0.5f}}, {{-1, 1, 0.5f}}, {{1, -1, 0.5f}}};
  const std::vector<std::uint32_t> indices{0, 1, 2};
  const softraster::Context context;
  const softraster::Status status = context.drawIndexed<FlatRed>(softraster::PipelineState{}, FlatRed::Uniforms{},
                                                          vertices, indices, framebuffer);
  if (!status) {
    std::fprintf(stderr, "draw failed: %s\n", status.message().c_str());
    return 1;
  }
  int red = 0;
  for (std::size_t i = 0; i < framebuffer.colour().size(); i += 4) red += framebuffer.colour()[i] == 255;
  // Half of a 32x32 square: pixel centres strictly above the diagonal, 31*32/2. The 32 centres on
  // the diagonal belong to the bottom-right edge, which the top-left rule leaves out.
  std::printf("red pixels: %d\n", red);
  return red == 496 ? 0 : 1;
}
