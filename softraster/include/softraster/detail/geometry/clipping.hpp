// Clipping: Sutherland–Hodgman against the six frustum planes in clip space, exactly as Mesa's
// draw module (draw_pipe_clip.c) does it for lavapipe:
//   - planes visited in clip-mask bit order (x<=w, x>=-w, y<=w, y>=-w, z>=0, z<=w), only those
//     some vertex of the triangle is outside of;
//   - plane distance dp = dot4(position, plane), summed left to right;
//   - a new vertex is interpolated from the endpoint nearer the plane: base + t*(other - base);
//   - its window position is pos * (1/w) * scale + trans with no FMA (this is C code in Mesa);
//   - a NaN or infinite distance drops the whole triangle;
//   - the resulting polygon is emitted as a fan from its vertex 0.
//   - noperspective varyings use a t recomputed in screen space (from x, or y when x is equal);
//     flat varyings of the polygon's vertex 0 are the provoking vertex's (the triangle's first,
//     or its third with provoking vertex last; the fan is then emitted as (i-1, i, 0)).
// With depth clamp the z planes are simply absent from the clip masks.
// Lines and points follow do_clip_line and clip_point_guard_xy (below).
// Deliberately absent: user clip planes, clip distances.
#pragma once

#include <softraster/detail/geometry/vertex_processing.hpp>
#include <softraster/shader.hpp>

#include <array>
#include <cmath>
#include <cstdint>

namespace softraster::detail {

// Upper bound on the vertices of a triangle clipped by six planes (Mesa's bound with no user planes).
inline constexpr int kMaxClippedVertices = 2 * 6 + 1;

// The clipped polygon; edges[i] says whether the edge from vertex i to vertex i+1 is one of the
// original triangle's (polygon modes draw those, never the ones along a frustum plane).
template <int N>
struct ClippedPolygon {
  std::array<ShadedVertex<N>, kMaxClippedVertices + 1> vertices;
  std::array<bool, kMaxClippedVertices + 1> edges{};
  int count = 0;
};

// The plane vectors of draw_context.c / draw_pt_post_vs.c for Vulkan's [0, w] depth range. With
// the guard band the x and y planes are |x|, |y| <= 2w (draw_pt_post_vs.c's -0.5/0.5 planes); the
// clip masks are still computed against w, as Mesa's vertex JIT code does.
inline float clipDistance(Vec4 p, int plane, bool guardBandXY = false) {
  static constexpr float kPlanes[6][4] = {{-1, 0, 0, 1}, {1, 0, 0, 1}, {0, -1, 0, 1},
                                          {0, 1, 0, 1},  {0, 0, 1, 0}, {0, 0, -1, 1}};
  static constexpr float kGuardBandPlanes[4][4] = {{-0.5f, 0, 0, 1}, {0.5f, 0, 0, 1}, {0, -0.5f, 0, 1}, {0, 0.5f, 0, 1}};
  const float* q = guardBandXY && plane < 4 ? kGuardBandPlanes[plane] : kPlanes[plane];
  return p.x * q[0] + p.y * q[1] + p.z * q[2] + p.w * q[3];
}

template <int N>
inline ShadedVertex<N> interpolateClipVertex(float t, const ShadedVertex<N>& base, const ShadedVertex<N>& other,
                                             const ViewportTransform& vp, const InterpolationSet<N>& interpolation) {
  ShadedVertex<N> v;
  for (int i = 0; i < 4; ++i) v.clip[i] = base.clip[i] + t * (other.clip[i] - base.clip[i]);
  const float oneOverW = 1.0f / v.clip.w;
  v.window = {v.clip.x * oneOverW * vp.scale[0] + vp.translate[0], v.clip.y * oneOverW * vp.scale[1] + vp.translate[1],
              v.clip.z * oneOverW * vp.scale[2] + vp.translate[2], oneOverW};
  // noperspective: the same point's parameter along the edge in screen space.
  float tScreen = t;
  for (int k = 0; k < 2; ++k) {
    if (other.clip[k] != base.clip[k]) {
      const float otherCoord = other.clip[k] / other.clip.w;
      const float baseCoord = base.clip[k] / base.clip.w;
      const float newCoord = v.clip[k] / v.clip.w;
      tScreen = (newCoord - baseCoord) / (otherCoord - baseCoord);
      break;
    }
  }
  for (int i = 0; i < N; ++i) {
    const float ti = interpolation[static_cast<std::size_t>(i)] == Interpolation::NoPerspective ? tScreen : t;
    v.varyings[i] = base.varyings[i] + ti * (other.varyings[i] - base.varyings[i]);
  }
  v.pointSize = base.pointSize + t * (other.pointSize - base.pointSize);
  v.clipMask = 0;
  return v;
}

// Clips the triangle (a, b, c) whose vertices are outside the planes in `clipMask` (the OR of
// their masks). Returns false when the triangle is dropped entirely (empty or NaN/Inf).
// `guardBandXY`: clip x and y at 2w. lavapipe does this for triangles drawn with polygon mode
// POINT (measured, scenes/polygon_mode_clipping.json: a vertex at 1.9w keeps its point, one at
// 2.5w is moved to 2w); filled triangles, polygon mode LINE and line topologies clip at w.
// `provokingLast`: c, not a, is the provoking vertex whose flat varyings vertex 0 gets.
template <int N>
bool clipTriangle(const ShadedVertex<N>& a, const ShadedVertex<N>& b, const ShadedVertex<N>& c, std::uint32_t clipMask,
                  const ViewportTransform& vp, const InterpolationSet<N>& interpolation, ClippedPolygon<N>& result,
                  bool guardBandXY = false, bool provokingLast = false) {
  // Two vertex lists that swap roles after each plane; indices point into `storage`.
  std::array<ShadedVertex<N>, 3 + kMaxClippedVertices + 1> storage;
  int stored = 0;
  std::array<int, kMaxClippedVertices + 1> listA, listB;
  std::array<bool, kMaxClippedVertices + 1> edgesA{true, true, true}, edgesB{};
  int* in = listA.data();
  int* out = listB.data();
  bool* inEdges = edgesA.data();
  bool* outEdges = edgesB.data();
  storage[stored] = a;
  in[0] = stored++;
  storage[stored] = b;
  in[1] = stored++;
  storage[stored] = c;
  in[2] = stored++;
  int n = 3;

  while (clipMask != 0 && n >= 3) {
    const int plane = __builtin_ctz(clipMask);
    clipMask &= clipMask - 1;

    int previous = in[0];
    float dpPrevious = clipDistance(storage[previous].clip, plane, guardBandXY);
    if (!std::isfinite(dpPrevious)) return false;
    if (n >= kMaxClippedVertices) return false;
    in[n] = in[0];
    inEdges[n] = inEdges[0];

    int outCount = 0;
    for (int i = 1; i <= n; ++i) {
      const int current = in[i];
      const float dp = clipDistance(storage[current].clip, plane, guardBandXY);
      if (!std::isfinite(dp)) return false;

      const bool previousEdge = inEdges[i - 1];
      bool crosses;
      if (dpPrevious >= 0.0f) {
        if (outCount >= kMaxClippedVertices) return false;
        outEdges[outCount] = previousEdge;
        out[outCount++] = previous;
        crosses = dp < 0.0f;
      } else {
        crosses = !(dp < 0.0f);
      }
      if (crosses) {
        if (outCount >= kMaxClippedVertices || stored >= static_cast<int>(storage.size())) return false;
        const float denominator = dp - dpPrevious;
        const ShadedVertex<N>& prev = storage[previous];
        const ShadedVertex<N>& cur = storage[current];
        ShadedVertex<N> made;
        if (dp < 0.0f) {  // leaving: interpolate from whichever endpoint is nearer the plane
          if (-dp < dpPrevious) {
            made = interpolateClipVertex(dp / denominator, cur, prev, vp, interpolation);
          } else {
            made = interpolateClipVertex(-dpPrevious / denominator, prev, cur, vp, interpolation);
          }
          made.edgeFlag = false;  // the edge along the frustum plane is not drawn
        } else {  // coming back in
          if (-dpPrevious < dp) {
            made = interpolateClipVertex(-dpPrevious / denominator, prev, cur, vp, interpolation);
          } else {
            made = interpolateClipVertex(dp / denominator, cur, prev, vp, interpolation);
          }
          made.edgeFlag = prev.edgeFlag;
        }
        storage[stored] = made;
        outEdges[outCount] = previousEdge;
        out[outCount++] = stored++;
      }
      previous = current;
      dpPrevious = dp;
    }
    std::swap(in, out);
    std::swap(inEdges, outEdges);
    n = outCount;
  }

  if (n < 3) return false;
  result.count = n;
  for (int i = 0; i < n; ++i) {
    result.vertices[i] = storage[in[i]];
    result.edges[i] = inEdges[i];
  }
  const ShadedVertex<N>& provoking = provokingLast ? c : a;
  for (int i = 0; i < N; ++i) {  // flat varyings come from the provoking vertex
    if (interpolation[static_cast<std::size_t>(i)] == Interpolation::Flat) {
      result.vertices[0].varyings[i] = provoking.varyings[i];
    }
  }
  return true;
}

// Clips the line (a, b) as Mesa's do_clip_line: per plane, the fraction to cut from each end;
// each end moves by its largest fraction, from its own end towards the other; a line losing
// all of its length is dropped. Flat varyings of both new ends are the provoking vertex's (a, or
// b with provokingLast).
template <int N>
bool clipLine(const ShadedVertex<N>& a, const ShadedVertex<N>& b, std::uint32_t clipMask, const ViewportTransform& vp,
              const InterpolationSet<N>& interpolation, ShadedVertex<N>& outA, ShadedVertex<N>& outB,
              bool provokingLast = false) {
  float t0 = 0.0f, t1 = 0.0f;
  while (clipMask != 0) {
    const int plane = __builtin_ctz(clipMask);
    clipMask &= clipMask - 1;
    const float dp0 = clipDistance(a.clip, plane);
    const float dp1 = clipDistance(b.clip, plane);
    if (!std::isfinite(dp0) || !std::isfinite(dp1)) return false;
    if (dp1 < 0.0f) {
      const float t = dp1 / (dp1 - dp0);
      t1 = t1 > t ? t1 : t;
    }
    if (dp0 < 0.0f) {
      const float t = dp0 / (dp0 - dp1);
      t0 = t0 > t ? t0 : t;
    }
    if (t0 + t1 >= 1.0f) return false;
  }
  outA = a.clipMask ? interpolateClipVertex(t0, a, b, vp, interpolation) : a;
  outB = b.clipMask ? interpolateClipVertex(t1, b, a, vp, interpolation) : b;
  const ShadedVertex<N>& provoking = provokingLast ? b : a;
  for (int i = 0; i < N; ++i) {
    if (interpolation[static_cast<std::size_t>(i)] == Interpolation::Flat) {
      outA.varyings[i] = provoking.varyings[i];
      outB.varyings[i] = provoking.varyings[i];
    }
  }
  return true;
}

// Points are not clipped against x and y (lavapipe's point_tri_clip guard band): a point is
// drawn whole unless it is outside a depth plane, or its w <= 0, or its x or y is not finite.
template <int N>
bool pointSurvivesClipping(const ShadedVertex<N>& v) {
  if (v.clipMask == 0) return true;
  if ((v.clipMask & ~0xfu) != 0) return false;
  return v.clip.w > 0.0f && std::isfinite(v.clip.x) && std::isfinite(v.clip.y);
}

}  // namespace softraster::detail
