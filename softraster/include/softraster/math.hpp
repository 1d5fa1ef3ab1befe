// Small vector and matrix types for softraster and its shaders.
// Every operation spells out its order of evaluation, because the exact method must
// round exactly as lavapipe's JIT code does. Nothing here fuses a multiply and an add: these
// headers are compiled with the user's flags, so the softraster target passes -ffp-contract=off
// to everything that links it (CMake's INTERFACE option, pkg-config's cflags), and under Clang
// this file also turns contraction off itself (#pragma clang fp contract). FMA is only used
// where it is written (std::fma).
// Deliberately not a general linear-algebra library: no inverse, no quaternions.
#pragma once

#include <array>
#include <cmath>

#if defined(__clang__)
#pragma float_control(push)
#pragma clang fp contract(off)
#endif

namespace softraster {

struct Vec2 {
  float x = 0, y = 0;
};

struct Vec3 {
  float x = 0, y = 0, z = 0;
};

// A 4-vector over a float type F: float, or a FloatBatch (simd.hpp) holding one value per lane,
// so a shader twin written over F shades one pixel or a batch of pixels with the same source.
template <class F>
struct Vec4T {
  F x{}, y{}, z{}, w{};
  constexpr F& operator[](int i) { return i == 0 ? x : i == 1 ? y : i == 2 ? z : w; }
  constexpr const F& operator[](int i) const { return i == 0 ? x : i == 1 ? y : i == 2 ? z : w; }
};
using Vec4 = Vec4T<float>;

template <class F>
constexpr Vec4T<F> operator+(const Vec4T<F>& a, const Vec4T<F>& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w};
}
template <class F>
constexpr Vec4T<F> operator*(const Vec4T<F>& a, const F& s) {
  return {a.x * s, a.y * s, a.z * s, a.w * s};
}

// Column-major 4x4 matrix, the layout GLSL uses for a mat4 in a push constant block.
struct Mat4 {
  std::array<Vec4, 4> columns{};

  static constexpr Mat4 identity() {
    Mat4 m;
    m.columns[0].x = m.columns[1].y = m.columns[2].z = m.columns[3].w = 1.0f;
    return m;
  }
  constexpr float& at(int row, int column) { return columns[column][row]; }
  constexpr float at(int row, int column) const { return columns[column][row]; }
};

// m * v evaluated as ((c0*v.x + c1*v.y) + c2*v.z) + c3*v.w, every product rounded on its own.
// The GLSL twins write the same sum with `precise`, so both renderers round identically.
constexpr Vec4 transform(const Mat4& m, Vec4 v) {
  return m.columns[0] * v.x + m.columns[1] * v.y + m.columns[2] * v.z + m.columns[3] * v.w;
}

// Product of two matrices (a * b), used on the host to build model-view-projection matrices.
constexpr Mat4 multiply(const Mat4& a, const Mat4& b) {
  Mat4 r;
  for (int c = 0; c < 4; ++c) r.columns[c] = transform(a, b.columns[c]);
  return r;
}

}  // namespace softraster

#if defined(__clang__)
#pragma float_control(pop)
#endif
