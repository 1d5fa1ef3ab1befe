// Stippled lines (VK_EXT_line_rasterization's stippledLineEnable), as lavapipe draws them: Mesa's
// draw-pipeline stipple stage (draw_pipe_stipple.c), after clipping, cuts each line into the
// segments its pattern keeps, and llvmpipe rasterizes those as ordinary lines.
//   - Length in window space: sqrt(dx*dx + dy*dy) for rectangular lines, max(|dx|, |dy|) for
//     Bresenham; a line covers ceil(length) stipple steps (none when the length is inf or NaN).
//   - Step i of a line is on iff bit ((counter + i) / factor) & 15 of the pattern is set; a run of
//     on-steps [s, e) becomes the segment from t = s/length to t = e/length (float divisions),
//     the last one ending at t = 1 exactly. The counter then grows by ceil(length).
//   - A segment's new ends are linear in window space: every value (x, y, z, 1/w and each
//     varying, perspective ones included) is v0 + t*(v1 - v0); an end at t = 0 or 1 is the
//     line's own vertex.
//   - Before it, Mesa's flatshade stage gives both ends the provoking vertex's flat varyings
//     (flatShadeLine), so the segments keep them.
//   - The counter restarts at 0 for every line of a line list (with or without adjacency) and at
//     the first line of each strip (a draw, or a run between primitive restarts); a line that
//     clipping drops entirely does not advance it (the stage never sees it).
//   - Polygon mode line: the unfilled stage's lines come in the triangle's edge order, the
//     counter restarting at each triangle and, of a triangle clipping cut into a fan, at the
//     fan's first triangle only (the caller, exact/draw.hpp drawCulled, resets it).
// Deliberately absent: the counter's storage (the caller's, one per run of lines drawn in order)
// and drawing the segments.
#pragma once

#include <softraster/detail/geometry/vertex_processing.hpp>
#include <softraster/shader.hpp>
#include <softraster/state.hpp>

#include <cmath>
#include <cstdint>

namespace softraster::detail {

// Whether stipple step `step` is on (draw_pipe_stipple.c stipple_test).
inline bool stippleStepOn(std::uint32_t step, const LineStipple& stipple) {
  const std::uint32_t bit = (step / stipple.factor) & 0xfu;
  return ((1u << bit) & stipple.pattern) != 0;
}

// The point at parameter t of the line (a, b), linear in window space (screen_interp).
template <int N>
inline ShadedVertex<N> stippleInterpolate(float t, const ShadedVertex<N>& a, const ShadedVertex<N>& b) {
  ShadedVertex<N> v = a;
  for (int i = 0; i < 4; ++i) v.window[i] = a.window[i] + t * (b.window[i] - a.window[i]);
  for (int i = 0; i < N; ++i) v.varyings[i] = a.varyings[i] + t * (b.varyings[i] - a.varyings[i]);
  v.pointSize = a.pointSize + t * (b.pointSize - a.pointSize);
  return v;
}

// Cuts the (clipped) line (a, b) by the stipple pattern and calls segment(p, q) for each piece
// it keeps, in order; `counter` is the stipple counter, advanced past this line.
template <int N, class Segment>
void stippleLine(const ShadedVertex<N>& a, const ShadedVertex<N>& b, const LineStipple& stipple, bool rectangular,
                 std::uint32_t& counter, Segment&& segment) {
  const float x0 = a.window.x, x1 = b.window.x, y0 = a.window.y, y1 = b.window.y;
  float length;
  if (rectangular) {
    const float dx = x1 - x0, dy = y1 - y0;
    length = std::sqrt(dx * dx + dy * dy);
  } else {
    const float dx = x0 > x1 ? x0 - x1 : x1 - x0;
    const float dy = y0 > y1 ? y0 - y1 : y1 - y0;
    length = dx > dy ? dx : dy;  // MAX2
  }
  const int steps = std::isfinite(length) ? static_cast<int>(std::ceil(length)) : 0;
  const auto emit = [&](float t0, float t1) {
    const ShadedVertex<N> p = t0 > 0.0f ? stippleInterpolate(t0, a, b) : a;
    const ShadedVertex<N> q = t1 < 1.0f ? stippleInterpolate(t1, a, b) : b;
    segment(p, q);
  };
  float start = 0.0f;
  bool on = false;
  for (int i = 0; i < steps; ++i) {
    const bool result = stippleStepOn(counter + static_cast<std::uint32_t>(i), stipple);
    if (result != on) {
      if (on) {
        emit(start / length, static_cast<float>(i) / length);
      } else {
        start = static_cast<float>(i);
      }
      on = result;
    }
  }
  if (on && start < length) emit(start / length, 1.0f);
  counter += static_cast<std::uint32_t>(steps);
}

// Mesa's flatshade stage for a line: both ends take the provoking vertex's flat varyings (the
// first end's, or the second's with provoking vertex last).
template <int N>
inline void flatShadeLine(ShadedVertex<N>& a, ShadedVertex<N>& b, const InterpolationSet<N>& interpolation,
                          bool provokingLast) {
  for (int i = 0; i < N; ++i) {
    if (interpolation[static_cast<std::size_t>(i)] != Interpolation::Flat) continue;
    if (provokingLast) {
      a.varyings[i] = b.varyings[i];
    } else {
      b.varyings[i] = a.varyings[i];
    }
  }
}

// Whether each line of `topology` starts the stipple afresh (lists), or only a strip's first.
inline bool stippleResetsEveryLine(Topology topology) {
  return topology == Topology::LineList || topology == Topology::LineListWithAdjacency;
}

}  // namespace softraster::detail
