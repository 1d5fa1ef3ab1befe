// The course's trapezoid method (Method::Trapezoid): the vertices sorted by y are split at the
// middle one into two trapezoids (a flat-bottomed upper one and a flat-topped lower one) between
// the long edge (top to bottom) and the two short ones; each is drawn row by row with the
// course's two speed-ups:
//   - integer arithmetic for positions: an edge's x at the row centre is 16.16 fixed point in 64
//     bits, stepped by its fixed-point slope from row to row; a span's first and last pixels are
//     shifts of it (pixel centres at +0.5: first = ceil(x_left - 0.5), last = floor(x_right - 0.5));
//   - incremental values: the left edge's values (z, 1/z, varyings) start at the first row
//     computed directly and step by their per-row change down the edge; across a span they start
//     at the first pixel centre and step by the triangle's constant d/dx per pixel.
// Stepping accumulates float error along long edges and wide spans, which the chart shows.
// A two-call object: setup(a, b, c, region) sorts and measures, draw(shade) walks both
// trapezoids calling shade(px, py, values).
// What it does: rows and spans clamped to the draw region (scissor and viewport), the edges'
// start values computed at the first drawn row (so a clamped triangle does not step through the
// rows above it); either winding (culling is done before, course/draw.hpp); a row covered where
// its centre is within [top y, bottom y], the upper trapezoid taking rows above the middle
// vertex's y and the lower one the rest.
// What it does not do: no fill rule (both ends of a span are included: shared edges give double
// hits, the fixed-point rounding of x can give cracks), no sub-pixel snapping of vertices (only of
// the stepped edge positions, to 1/65536 px), no clipping of its own (the front end clips to the
// frustum and guard band), no MSAA coverage; slopes are clamped to 2^28 px per row (only an edge
// crossing at most one row centre is that steep, and its one x is computed directly); a
// zero-area or non-finite triangle draws nothing.
#pragma once

#include <softraster/detail/course/pixel.hpp>
#include <softraster/detail/geometry/viewport.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace softraster::detail::course {

template <int K>
class TrapezoidTriangle {
 public:
  static constexpr int kFractionBits = 16;
  static constexpr std::int64_t kOne = std::int64_t{1} << kFractionBits;

  // False when there is nothing to draw (zero area, a vertex not drawable(), no row inside).
  bool setup(const Pixel<K>& a, const Pixel<K>& b, const Pixel<K>& c, const PixelRect& region) {
    if (!drawable(a) || !drawable(b) || !drawable(c)) return false;
    v_ = {a, b, c};
    std::sort(v_.begin(), v_.end(), [](const Pixel<K>& p, const Pixel<K>& q) { return p.y < q.y; });
    const Pixel<K>& top = v_[0];
    const Pixel<K>& mid = v_[1];
    const Pixel<K>& bottom = v_[2];
    // Which side the long edge is on: the middle vertex right of it (y down) puts it on the left.
    const float side = (mid.x - top.x) * (bottom.y - top.y) - (mid.y - top.y) * (bottom.x - top.x);
    if (!(side != 0.0f) || !std::isfinite(side)) return false;
    longOnLeft_ = side > 0.0f;
    // The triangle's constant d/dx of every value (the plane's x gradient), for the spans.
    const float e1x = mid.x - top.x, e1y = mid.y - top.y, e2x = bottom.x - top.x, e2y = bottom.y - top.y;
    const float invDet = 1.0f / (e1x * e2y - e2x * e1y);
    for (int i = 0; i < K; ++i) {
      const float d1 = mid.values[i] - top.values[i], d2 = bottom.values[i] - top.values[i];
      dvdx_[i] = (d1 * e2y - d2 * e1y) * invDet;
    }
    first_ = firstCentreAtOrAfter(top.y, region.y0, region.y1);
    last_ = lastCentreAtOrBefore(bottom.y, region.y0, region.y1);
    region_ = region;
    return first_ <= last_;
  }

  template <class Shade>
  void draw(Shade&& shade) const {
    const Pixel<K>& top = v_[0];
    const Pixel<K>& mid = v_[1];
    const Pixel<K>& bottom = v_[2];
    // Rows of the upper trapezoid: centres in [top.y, mid.y); of the lower one: [mid.y, bottom.y].
    const int split = std::clamp(firstCentreAtOrAfter(mid.y, first_, last_), first_, last_ + 1);
    Edge longEdge = Edge::start(top, bottom, first_);
    if (first_ < split) {
      Edge shortEdge = Edge::start(top, mid, first_);
      drawRows(first_, split - 1, longEdge, shortEdge, shade);
    }
    if (split <= last_) {
      Edge shortEdge = Edge::start(mid, bottom, split);
      drawRows(split, last_, longEdge, shortEdge, shade);
    }
  }

 private:
  // An edge being walked: x in 16.16 fixed point at the current row's centre and its values.
  struct Edge {
    std::int64_t x = 0, dxdy = 0;
    std::array<float, K> values{}, dvdy{};

    // The edge p -> q (p above) at row `row`'s centre, computed directly; the steps per row.
    static Edge start(const Pixel<K>& p, const Pixel<K>& q, int row) {
      Edge e;
      const float height = q.y - p.y;
      const float t = height > 0.0f ? ((static_cast<float>(row) + 0.5f) - p.y) / height : 0.0f;
      e.x = toFixed(p.x + t * (q.x - p.x));
      const float slope = height > 0.0f ? (q.x - p.x) / height : 0.0f;
      e.dxdy = toFixed(std::clamp(slope, -kMaxSlope, kMaxSlope));
      for (int i = 0; i < K; ++i) {
        e.values[i] = p.values[i] + t * (q.values[i] - p.values[i]);
        e.dvdy[i] = height > 0.0f ? (q.values[i] - p.values[i]) / height : 0.0f;
      }
      return e;
    }
    void step() {
      x += dxdy;
      for (int i = 0; i < K; ++i) values[i] += dvdy[i];
    }
  };

  static constexpr float kMaxSlope = 268435456.0f;  // 2^28 px per row: 2^44 in 16.16, 2^16 rows of it fit in 64 bits

  // v in 16.16 fixed point, clamped to +-2^28 (positions are within +-2^25: kMaxWindowCoordinate).
  static std::int64_t toFixed(float v) {
    const double clamped = std::clamp(static_cast<double>(v), -double{kMaxSlope}, double{kMaxSlope});
    return static_cast<std::int64_t>(std::llround(clamped * static_cast<double>(kOne)));
  }

  // Pixel index of fixed-point x, clamped to [lo - 1, hi + 1].
  static int clampedPixel(std::int64_t pixel, int lo, int hi) {
    return static_cast<int>(std::clamp<std::int64_t>(pixel, std::int64_t{lo} - 1, std::int64_t{hi} + 1));
  }

  template <class Shade>
  void drawRows(int y0, int y1, Edge& longEdge, Edge& shortEdge, Shade& shade) const {
    std::array<float, K> values;
    for (int py = y0; py <= y1; ++py) {
      const Edge& left = longOnLeft_ ? longEdge : shortEdge;
      const Edge& right = longOnLeft_ ? shortEdge : longEdge;
      // first = ceil(x_left - 0.5), last = floor(x_right - 0.5), as shifts (arithmetic: floor).
      const std::int64_t half = kOne / 2;
      const int x0 = std::max(clampedPixel((left.x - half + kOne - 1) >> kFractionBits, region_.x0, region_.x1), region_.x0);
      const int x1 = std::min(clampedPixel((right.x - half) >> kFractionBits, region_.x0, region_.x1), region_.x1);
      if (x0 <= x1) {
        const float startDx = (static_cast<float>(x0) + 0.5f) - static_cast<float>(left.x) / static_cast<float>(kOne);
        for (int i = 0; i < K; ++i) values[i] = left.values[i] + startDx * dvdx_[i];
        for (int px = x0; px <= x1; ++px) {
          shade(px, py, values.data());
          for (int i = 0; i < K; ++i) values[i] += dvdx_[i];
        }
      }
      longEdge.step();
      shortEdge.step();
    }
  }

  std::array<Pixel<K>, 3> v_;
  std::array<float, K> dvdx_{};
  bool longOnLeft_ = true;
  PixelRect region_{0, 0, -1, -1};
  int first_ = 0, last_ = -1;
};

}  // namespace softraster::detail::course
