// The course's rasterization methods (Method::Scanline, Trapezoid, Barycentric; detail/course/):
// coverage of a known triangle against Method::Exact's away from its edges, interpolated values
// against the exact method's plane interpolation (perspective-correct and affine), the depth test,
// culling, lines through the exact code, the options' errors, and no fault on hostile vertices.
// Not bit-identity: these are other algorithms; the tolerances below are stated per test.
#include <softraster/detail/course/barycentric.hpp>
#include <softraster/detail/course/scanline.hpp>
#include <softraster/detail/course/trapezoid.hpp>
#include <softraster/detail/exact/interpolation.hpp>
#include <softraster/pipeline.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace {

using softraster::Method;

constexpr Method kCourseMethods[] = {Method::Scanline, Method::Trapezoid, Method::Barycentric};

// Clip-space positions straight through, one perspective varying shown as red.
struct Ramp {
  struct Vertex {
    softraster::Vec4 position;
    float value = 0;
  };
  struct Uniforms {
    softraster::Vec4 colour{1, 1, 1, 1};  // multiplied by the varying in red, as is in g, b, a
  };
  static constexpr int kVaryings = 1;
  static softraster::Vec4 vertex(const Uniforms&, const Vertex& v, float* varyings) {
    varyings[0] = v.value;
    return v.position;
  }
  static softraster::Vec4 fragment(const Uniforms& u, const float* varyings) {
    return {u.colour.x * varyings[0], u.colour.y, u.colour.z, u.colour.w};
  }
};

struct Target {
  softraster::Framebuffer framebuffer;
  explicit Target(std::uint32_t size, softraster::DepthFormat format = softraster::DepthFormat::D32Sfloat,
                  std::uint32_t samples = 1)
      : framebuffer(softraster::Framebuffer::create(size, size, format, samples).value()) {}
  bool covered(std::uint32_t x, std::uint32_t y) const { return framebuffer.colourAt(x, y)[3] == 255; }
};

softraster::Status draw(Method method, Target& target, const std::vector<Ramp::Vertex>& vertices,
                        softraster::PipelineState state = {}, Ramp::Uniforms uniforms = {}, bool affine = false,
                        softraster::DepthMode depthMode = softraster::DepthMode::Vulkan) {
  softraster::ContextOptions options;
  options.method = method;
  options.threads = 1;
  options.affineVaryings = affine;
  options.depthMode = depthMode;
  const softraster::Context context(options);
  return context.draw<Ramp>(state, uniforms, std::span<const Ramp::Vertex>(vertices), target.framebuffer);
}

softraster::PipelineState noCulling() {
  softraster::PipelineState state;
  state.rasterization.cullMode = softraster::CullMode::None;
  return state;
}

// A right triangle with its right angle at the top left of a 64x64 framebuffer: (4, 4), (60, 4),
// (4, 60) in pixels.
std::vector<Ramp::Vertex> rightTriangle() {
  const auto ndc = [](float px) { return px / 32.0f - 1.0f; };
  return {{{ndc(4), ndc(4), 0.5f, 1}, 0}, {{ndc(60), ndc(4), 0.5f, 1}, 1}, {{ndc(4), ndc(60), 0.5f, 1}, 0}};
}

// Distance in pixels from pixel (x, y)'s centre to the right triangle's nearest edge, signed
// (positive inside).
float insideBy(int x, int y) {
  const float cx = static_cast<float>(x) + 0.5f, cy = static_cast<float>(y) + 0.5f;
  const float hypotenuse = (64.0f - cx - cy) / std::sqrt(2.0f);
  return std::fmin(std::fmin(cx - 4.0f, cy - 4.0f), hypotenuse);
}

TEST(CourseMethods, NamesAndOrder) {
  EXPECT_EQ(softraster::methodName(Method::Scanline), "scanline");
  EXPECT_EQ(softraster::methodName(Method::Trapezoid), "trapezoid");
  EXPECT_EQ(softraster::methodName(Method::Barycentric), "barycentric");
  for (Method m : softraster::kMethods) EXPECT_EQ(softraster::methodFromName(softraster::methodName(m)), m);
  EXPECT_EQ(softraster::kMethods.size(), 5u);
  EXPECT_FALSE(softraster::isCourseMethod(Method::Exact));
  EXPECT_FALSE(softraster::isCourseMethod(Method::ExactScalar));
  for (Method m : kCourseMethods) EXPECT_TRUE(softraster::isCourseMethod(m));
}

// Every pixel whose centre is more than a pixel inside the edges is covered, as with Exact; every
// one more than a pixel outside is not; both windings (culling off).
TEST(CourseMethods, CoverAKnownTriangleAsExactDoesAwayFromItsEdges) {
  Target exact(64);
  exact.framebuffer.clear({0, 0, 0, 0}, 1.0f);
  ASSERT_TRUE(draw(Method::ExactScalar, exact, rightTriangle(), noCulling()).ok());
  for (Method method : kCourseMethods) {
    for (bool reversed : {false, true}) {
      SCOPED_TRACE(std::string(softraster::methodName(method)) + (reversed ? " clockwise" : ""));
      std::vector<Ramp::Vertex> vertices = rightTriangle();
      if (reversed) std::swap(vertices[1], vertices[2]);
      Target course(64);
      course.framebuffer.clear({0, 0, 0, 0}, 1.0f);
      ASSERT_TRUE(draw(method, course, vertices, noCulling()).ok());
      int interior = 0, edgeDifferences = 0;
      for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x) {
          const float d = insideBy(x, y);
          const bool c = course.covered(x, y), e = exact.covered(x, y);
          if (d > 1.0f) {
            ++interior;
            EXPECT_TRUE(c && e) << "interior pixel " << x << "," << y;
          } else if (d < -1.0f) {
            EXPECT_FALSE(c || e) << "exterior pixel " << x << "," << y;
          } else {
            edgeDifferences += c != e;
          }
        }
      }
      EXPECT_GT(interior, 1200);
      // Near the edges the methods may disagree with Exact (no fill rule), but only there: at most
      // the pixels along the three edges.
      EXPECT_LE(edgeDifferences, 3 * 56);
    }
  }
}

// With the default culling (back faces), a clockwise triangle is culled by every method alike.
TEST(CourseMethods, CullAsTheStateSays) {
  for (Method method : kCourseMethods) {
    SCOPED_TRACE(softraster::methodName(method));
    std::vector<Ramp::Vertex> vertices = rightTriangle();
    for (bool reversed : {false, true}) {
      if (reversed) std::swap(vertices[1], vertices[2]);
      softraster::PipelineState state;
      state.rasterization.cullMode = softraster::CullMode::Back;
      Target exact(64), course(64);
      exact.framebuffer.clear({0, 0, 0, 0}, 1.0f);
      course.framebuffer.clear({0, 0, 0, 0}, 1.0f);
      ASSERT_TRUE(draw(Method::ExactScalar, exact, vertices, state).ok());
      ASSERT_TRUE(draw(method, course, vertices, state).ok());
      EXPECT_EQ(exact.covered(10, 10), course.covered(10, 10)) << (reversed ? "reversed" : "as given");
    }
  }
}

// A triangle's Pixels with a perspective varying: w = 1, 4 and 2 at the vertices.
struct PerspectiveCase {
  softraster::detail::ShadedVertex<1> v[3];
  PerspectiveCase() {
    const float xs[3] = {3.25f, 120.5f, 10.75f}, ys[3] = {2.5f, 20.25f, 110.5f}, ws[3] = {1.0f, 4.0f, 2.0f};
    const float values[3] = {0.0f, 1.0f, 0.25f};
    for (int i = 0; i < 3; ++i) {
      v[i].window = {xs[i], ys[i], 0.5f, 1.0f / ws[i]};
      v[i].varyings[0] = values[i];
    }
  }
};

// Every pixel a method draws, with the varying as the per-pixel end computes it.
template <class Triangle>
std::vector<std::array<float, 3>> drawnValues(Triangle& triangle, const PerspectiveCase& c, bool affine) {
  using namespace softraster::detail::course;
  const softraster::InterpolationSet<1> smooth{softraster::Interpolation::Perspective};
  const Pixel<3> a = pixelOf<3>(c.v[0], c.v[0], smooth, affine), b = pixelOf<3>(c.v[1], c.v[0], smooth, affine),
                 p = pixelOf<3>(c.v[2], c.v[0], smooth, affine);
  std::vector<std::array<float, 3>> out;
  if (!triangle.setup(a, b, p, softraster::detail::PixelRect{0, 0, 127, 127})) return out;
  triangle.draw([&](int px, int py, const float* values) {
    const float varying = affine ? values[2] : values[2] * (1.0f / values[1]);
    out.push_back({static_cast<float>(px), static_cast<float>(py), varying});
  });
  return out;
}

// The methods' varying at each pixel they draw against the exact method's plane interpolation at
// that pixel centre: perspective-correct (and affine against the plane of the plain values, which
// is what noperspective interpolation is). Tolerance: 1e-4 of the varying's range [0, 1] for the
// methods that compute values afresh (scanline, barycentric), 1e-3 for the stepping one
// (trapezoid: up to ~120 float additions per span and edge).
TEST(CourseMethods, InterpolateAVaryingAsExactDoesWithinAFloatTolerance) {
  using namespace softraster::detail;
  const PerspectiveCase c;
  for (bool affine : {false, true}) {
    const softraster::InterpolationSet<1> set{affine ? softraster::Interpolation::NoPerspective
                                                     : softraster::Interpolation::Perspective};
    const TriangleInterpolants<1> exact =
        setupInterpolants(c.v[0], c.v[1], c.v[2], set, softraster::DepthBias{}, softraster::DepthFormat::D32Sfloat);
    std::vector<course::Pixel<3>> rows;
    course::ScanlineTriangle<3> scanline(rows);
    course::TrapezoidTriangle<3> trapezoid;
    course::BarycentricTriangle<3> barycentric;
    const std::pair<const char*, std::vector<std::array<float, 3>>> results[] = {
        {"scanline", drawnValues(scanline, c, affine)},
        {"trapezoid", drawnValues(trapezoid, c, affine)},
        {"barycentric", drawnValues(barycentric, c, affine)}};
    for (const auto& [name, pixels] : results) {
      SCOPED_TRACE(std::string(name) + (affine ? " affine" : " perspective"));
      const float tolerance = std::string(name) == "trapezoid" ? 1e-3f : 1e-4f;
      EXPECT_GT(pixels.size(), 5000u);
      float worst = 0;
      for (const auto& [x, y, value] : pixels) {
        float expected;
        interpolateVaryings<false>(exact, set, x, y, &expected);
        worst = std::fmax(worst, std::fabs(value - expected));
      }
      EXPECT_LE(worst, tolerance);
    }
  }
}

// Affine and perspective-correct interpolation differ under perspective (the point of the option).
TEST(CourseMethods, AffineVaryingsDifferFromPerspectiveOnes) {
  const PerspectiveCase c;
  softraster::detail::course::BarycentricTriangle<3> barycentric;
  const auto perspective = drawnValues(barycentric, c, false);
  const auto affine = drawnValues(barycentric, c, true);
  ASSERT_EQ(perspective.size(), affine.size());
  float largest = 0;
  for (std::size_t i = 0; i < perspective.size(); ++i) largest = std::fmax(largest, std::fabs(perspective[i][2] - affine[i][2]));
  EXPECT_GT(largest, 0.1f);
}

// Through the Context: the colour of the varying at interior pixels is the exact method's within
// one 8-bit step, perspective-correct; with affine varyings it is not (vertices at w = 1 and 4).
TEST(CourseMethods, ShadeTheInterpolatedVaryingThroughTheContext) {
  std::vector<Ramp::Vertex> vertices = rightTriangle();
  for (Ramp::Vertex& v : vertices) {
    const float w = v.value == 1 ? 4.0f : 1.0f;  // the right-hand vertex further away
    v.position = {v.position.x * w, v.position.y * w, v.position.z * w, w};
  }
  Target exact(64);
  exact.framebuffer.clear({0, 0, 0, 0}, 1.0f);
  ASSERT_TRUE(draw(Method::ExactScalar, exact, vertices, noCulling()).ok());
  for (Method method : kCourseMethods) {
    SCOPED_TRACE(softraster::methodName(method));
    for (bool affine : {false, true}) {
      Target course(64);
      course.framebuffer.clear({0, 0, 0, 0}, 1.0f);
      ASSERT_TRUE(draw(method, course, vertices, noCulling(), {}, affine).ok());
      int worst = 0;
      for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x) {
          if (insideBy(x, y) <= 1.0f) continue;
          worst = std::max(worst, std::abs(int{course.framebuffer.colourAt(x, y)[0]} - int{exact.framebuffer.colourAt(x, y)[0]}));
        }
      }
      if (affine) {
        EXPECT_GT(worst, 20) << "affine varyings should be visibly off under perspective";
      } else {
        EXPECT_LE(worst, 1);
      }
    }
  }
}

// A nearer triangle drawn second wins with LESS, a farther one drawn second loses; in Vulkan depth
// and in the course's 1/z buffer; every compare op keeps its meaning against Exact.
TEST(CourseMethods, RespectTheDepthTest) {
  using softraster::CompareOp;
  const auto at = [](float z, float red) {
    std::vector<Ramp::Vertex> v = rightTriangle();
    for (Ramp::Vertex& p : v) {
      p.position.z = z;
      p.value = red;
    }
    return v;
  };
  for (Method method : kCourseMethods) {
    for (softraster::DepthMode mode : {softraster::DepthMode::Vulkan, softraster::DepthMode::InverseZ}) {
      for (CompareOp op : {CompareOp::Never, CompareOp::Less, CompareOp::Equal, CompareOp::LessOrEqual,
                           CompareOp::Greater, CompareOp::NotEqual, CompareOp::GreaterOrEqual, CompareOp::Always}) {
        for (bool nearerSecond : {true, false}) {
          SCOPED_TRACE(std::string(softraster::methodName(method)) + " op " + std::to_string(int(op)) +
                       (mode == softraster::DepthMode::InverseZ ? " 1/z" : " z") + (nearerSecond ? " nearer second" : ""));
          softraster::PipelineState state = noCulling();
          state.depth.testEnable = state.depth.writeEnable = true;
          state.depth.compareOp = op;
          // For 1/z the distance is w: put the nearer triangle at w = 1, the farther one at w = 2.
          const auto layer = [&](float depth, float red) {
            std::vector<Ramp::Vertex> v = at(depth, red);
            if (mode == softraster::DepthMode::InverseZ) {
              const float w = depth < 0.5f ? 1.0f : 2.0f;
              for (Ramp::Vertex& p : v) p.position = {p.position.x * w, p.position.y * w, 0.5f * w, w};
            }
            return v;
          };
          Target exact(64), course(64);
          const float clear = mode == softraster::DepthMode::InverseZ ? 0.0f : 1.0f;
          exact.framebuffer.clear({0, 0, 0, 1}, clear);
          course.framebuffer.clear({0, 0, 0, 1}, clear);
          const float first = nearerSecond ? 0.75f : 0.25f, second = nearerSecond ? 0.25f : 0.75f;
          for (Target* t : {&exact, &course}) {
            const Method m = t == &exact ? Method::ExactScalar : method;
            ASSERT_TRUE(draw(m, *t, layer(first, 0.2f), state, {}, false, mode).ok());
            ASSERT_TRUE(draw(m, *t, layer(second, 1.0f), state, {}, false, mode).ok());
          }
          // (Red is the varying, the same at every vertex: 51 for the first layer, 255 for the second.)
          EXPECT_EQ(course.framebuffer.colourAt(12, 12)[0], exact.framebuffer.colourAt(12, 12)[0]);
          if (op == CompareOp::Less) {
            EXPECT_EQ(course.framebuffer.colourAt(12, 12)[0], nearerSecond ? 255 : 51);
          }
        }
      }
    }
  }
}

// Lines and points are drawn by the exact method's code: the same pixels as ExactScalar.
TEST(CourseMethods, DrawLinesAndPointsWithTheExactCode) {
  for (auto topology : {softraster::Topology::LineList, softraster::Topology::PointList}) {
    softraster::PipelineState state;
    state.topology = topology;
    const std::vector<Ramp::Vertex> vertices{{{-0.9f, -0.8f, 0.5f, 1}, 1}, {{0.7f, 0.6f, 0.5f, 1}, 1}};
    Target exact(32);
    exact.framebuffer.clear({0, 0, 0, 0}, 1.0f);
    ASSERT_TRUE(draw(Method::ExactScalar, exact, vertices, state).ok());
    for (Method method : kCourseMethods) {
      Target course(32);
      course.framebuffer.clear({0, 0, 0, 0}, 1.0f);
      ASSERT_TRUE(draw(method, course, vertices, state).ok());
      EXPECT_EQ(course.framebuffer.colour(), exact.framebuffer.colour()) << softraster::methodName(method);
    }
  }
}

// Affine varyings with an exact method are an error of the draw, not a silent change of it.
TEST(CourseMethods, AffineVaryingsWithAnExactMethodAreAnError) {
  for (Method method : {Method::Exact, Method::ExactScalar}) {
    Target target(16);
    const softraster::Status status = draw(method, target, rightTriangle(), {}, {}, true);
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.message().find("affine varyings apply only to the course's methods"), std::string::npos)
        << status.message();
  }
}

// With 4x MSAA a course method decides each pixel at its centre and writes all four samples.
TEST(CourseMethods, FourSamplesGetThePixelsOneResult) {
  for (Method method : kCourseMethods) {
    Target target(64, softraster::DepthFormat::D32Sfloat, 4);
    target.framebuffer.clear({0, 0, 0, 0}, 1.0f);
    ASSERT_TRUE(draw(method, target, rightTriangle(), noCulling()).ok()) << softraster::methodName(method);
    for (std::uint32_t s = 0; s < 4; ++s) {
      EXPECT_EQ(target.framebuffer.colourAt(10, 10, s)[3], 255);
      EXPECT_EQ(target.framebuffer.colourAt(62, 62, s)[3], 0);
    }
  }
}

// Hostile vertices never fault, hang or write outside the framebuffer (the sanitizer build checks
// the writes): NaN, infinities, w = 0, huge and tiny coordinates, slivers; a scissor is honoured.
TEST(CourseMethods, NeverFaultOnHostileVertices) {
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN(), kInf = std::numeric_limits<float>::infinity();
  const std::vector<std::vector<Ramp::Vertex>> cases = {
      {{{kNaN, 0, 0.5f, 1}, 0}, {{1, 0, 0.5f, 1}, 0}, {{0, 1, 0.5f, 1}, 0}},
      {{{kInf, -kInf, 0.5f, 1}, 0}, {{1, 0, 0.5f, 1}, 0}, {{0, 1, 0.5f, 1}, 0}},
      {{{0, 0, 0, 0}, 0}, {{1, 0, 0.5f, 1}, 0}, {{0, 1, 0.5f, 1}, 0}},
      {{{0, 0, 0, 0}, 0}, {{0, 0, 0, 0}, 0}, {{0, 0, 0, 0}, 0}},
      {{{-1e30f, -1e30f, 0.5f, 1}, 0}, {{1e30f, -1e30f, 0.5f, 1}, 0}, {{0, 1e30f, 0.5f, 1}, 0}},
      {{{-3e4f, -3e4f, 0.5f, 1e-30f}, 0}, {{3e4f, -1, 0.5f, 1}, 0}, {{0, 3e4f, 0.5f, 1}, kNaN}},
      {{{-1, -1, 0.5f, 1}, 0}, {{1, 1, 0.5f, 1}, 0}, {{1, 1.000001f, 0.5f, 1}, 0}},
      {{{-1, 0.0f, 0.5f, 1}, 0}, {{1, 0.00001f, 0.5f, 1}, 0}, {{1, -0.00001f, 0.5f, 1}, 0}},
      {{{-2, -2, -1, 1}, 0}, {{2, -2, 2, 1}, 1}, {{0, 2, 0.5f, 1e-7f}, 1}},
  };
  for (Method method : kCourseMethods) {
    for (bool affine : {false, true}) {
      for (std::size_t i = 0; i < cases.size(); ++i) {
        SCOPED_TRACE(std::string(softraster::methodName(method)) + " case " + std::to_string(i));
        softraster::PipelineState state = noCulling();
        state.depth.testEnable = state.depth.writeEnable = true;
        state.depth.compareOp = softraster::CompareOp::Less;
        Target target(24);
        target.framebuffer.clear({0, 0, 0, 0}, 1.0f);
        EXPECT_TRUE(draw(method, target, cases[i], state, {}, affine).ok());
        state.scissor = {5, 6, 7, 3};
        Target scissored(24);
        scissored.framebuffer.clear({0, 0, 0, 0}, 1.0f);
        EXPECT_TRUE(draw(method, scissored, cases[i], state, {}, affine).ok());
        for (std::uint32_t y = 0; y < 24; ++y) {
          for (std::uint32_t x = 0; x < 24; ++x) {
            const bool inScissor = x >= 5 && x < 12 && y >= 6 && y < 9;
            if (!inScissor) {
              EXPECT_EQ(scissored.framebuffer.colourAt(x, y)[3], 0) << x << "," << y;
            }
          }
        }
      }
    }
  }
}

}  // namespace
