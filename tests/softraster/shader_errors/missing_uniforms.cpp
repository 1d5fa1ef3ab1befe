// expect: the shader has no `Uniforms` type
// A shader with one mistake, drawn the way a user draws (shader_errors_test.sh compiles it).
#include <softraster/pipeline.hpp>

#include <vector>

struct Broken {
  using Vertex = int;
  static constexpr int kVaryings = 0;
  static softraster::Vec4 vertex(const int&, const Vertex&, float*) { return {0, 0, 0, 1}; }
};

int main() {
  auto framebuffer = softraster::Framebuffer::create(8, 8);
  std::vector<int> vertices(3);
  const softraster::Context context;
  return context.draw<Broken>(softraster::PipelineState{}, 0, vertices, *framebuffer).ok() ? 0 : 1;
}
