// expect: the shader needs `static constexpr int kVaryings` between 0 and softraster::kMaxVaryings
// A shader with one mistake, drawn the way a user draws (shader_errors_test.sh compiles it).
#include <softraster/pipeline.hpp>

#include <vector>

struct Broken {
  using Vertex = int;
  struct Uniforms {};
  static constexpr int kVaryings = 65;
  static softraster::Vec4 vertex(const Uniforms&, const Vertex&, float*) { return {0, 0, 0, 1}; }
  template <class F>
  static softraster::Vec4T<F> fragment(const Uniforms&, const F*) { return {F(1), F(0), F(0), F(1)}; }
};

int main() {
  auto framebuffer = softraster::Framebuffer::create(8, 8);
  std::vector<int> vertices(3);
  const softraster::Context context;
  return context.draw<Broken>(softraster::PipelineState{}, Broken::Uniforms{}, vertices, *framebuffer).ok() ? 0 : 1;
}
