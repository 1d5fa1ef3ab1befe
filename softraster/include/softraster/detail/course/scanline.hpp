// The course's scanline method (Method::Scanline): the vertices are projected (the shared front
// end's window positions), each of the three edges is walked row by row with linear
// interpolation, p = a + t (b - a) with t = (y_centre - a.y) / (b.y - a.y), and the course's
// Pixel it gives (x, y, z, 1/z and the varyings, pixel.hpp) is kept in per-row left and right
// arrays (the leftmost and rightmost edge crossing of each row); then each row is drawn from its
// left to its right Pixel, every pixel's values interpolated linearly between the two.
// A two-call object: setup(a, b, c, region) walks the edges into the arrays, then draw(shade)
// calls shade(px, py, values) for every pixel of every row.
// What it does: pixel centres at +0.5, a row covered where its centre's y is within the
// triangle's [min y, max y], a pixel where its centre's x is within [left x, right x] (both ends
// included); either winding (culling is done before, course/draw.hpp); rows and spans clamped to
// the draw region (scissor and viewport), so the arrays hold at most the region's rows; values
// computed afresh at each row and pixel by a division (no stepping: see trapezoid.hpp for that).
// What it does not do: no fill rule (a pixel centre exactly on a shared edge is drawn by both
// triangles; float rounding of the edge crossings can leave cracks or double hits), no sub-pixel
// snapping, no clipping of its own (the front end clips to the frustum and guard band), no MSAA
// coverage; horizontal edges are not walked (the other two give their row's ends), a zero-height
// or non-finite triangle draws nothing.
#pragma once

#include <softraster/detail/course/pixel.hpp>
#include <softraster/detail/geometry/viewport.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace softraster::detail::course {

template <int K>
class ScanlineTriangle {
 public:
  // rows: the per-row left/right arrays (two Pixels a row), scratch kept between triangles.
  explicit ScanlineTriangle(std::vector<Pixel<K>>& rows) : rows_(rows) {}

  // False when there is nothing to draw (a vertex not drawable(), no row centre inside).
  bool setup(const Pixel<K>& a, const Pixel<K>& b, const Pixel<K>& c, const PixelRect& region) {
    if (!drawable(a) || !drawable(b) || !drawable(c)) return false;
    const float minY = std::fmin(a.y, std::fmin(b.y, c.y)), maxY = std::fmax(a.y, std::fmax(b.y, c.y));
    first_ = firstCentreAtOrAfter(minY, region.y0, region.y1);
    last_ = lastCentreAtOrBefore(maxY, region.y0, region.y1);
    region_ = region;
    if (first_ > last_) return false;
    rows_.resize(2 * static_cast<std::size_t>(last_ - first_ + 1));
    for (std::size_t r = 0; r < rows_.size(); r += 2) {
      rows_[r].x = std::numeric_limits<float>::infinity();       // left: none yet
      rows_[r + 1].x = -std::numeric_limits<float>::infinity();  // right: none yet
    }
    walkEdge(a, b);
    walkEdge(b, c);
    walkEdge(c, a);
    return true;
  }

  template <class Shade>
  void draw(Shade&& shade) const {
    std::array<float, K> values;
    for (int py = first_; py <= last_; ++py) {
      const std::size_t r = 2 * static_cast<std::size_t>(py - first_);
      const Pixel<K>& left = rows_[r];
      const Pixel<K>& right = rows_[r + 1];
      if (!(left.x <= right.x)) continue;  // no edge crossed this row
      const int x0 = firstCentreAtOrAfter(left.x, region_.x0, region_.x1);
      const int x1 = lastCentreAtOrBefore(right.x, region_.x0, region_.x1);
      const float width = right.x - left.x;
      for (int px = x0; px <= x1; ++px) {
        const float t = width > 0.0f ? ((static_cast<float>(px) + 0.5f) - left.x) / width : 0.0f;
        for (int i = 0; i < K; ++i) values[i] = left.values[i] + t * (right.values[i] - left.values[i]);
        shade(px, py, values.data());
      }
    }
  }

 private:
  // The crossing of edge (p, q) with every row centre it spans, kept where it widens the row.
  void walkEdge(const Pixel<K>& p0, const Pixel<K>& q0) {
    if (p0.y == q0.y) return;  // horizontal: its ends are the other edges' ends
    const Pixel<K>& p = p0.y < q0.y ? p0 : q0;
    const Pixel<K>& q = p0.y < q0.y ? q0 : p0;
    const int y0 = firstCentreAtOrAfter(p.y, first_, last_);
    const int y1 = lastCentreAtOrBefore(q.y, first_, last_);
    const float height = q.y - p.y;
    for (int py = y0; py <= y1; ++py) {
      const float t = ((static_cast<float>(py) + 0.5f) - p.y) / height;
      const Pixel<K> crossing = lerp(p, q, t);
      const std::size_t r = 2 * static_cast<std::size_t>(py - first_);
      if (crossing.x < rows_[r].x) rows_[r] = crossing;
      if (crossing.x > rows_[r + 1].x) rows_[r + 1] = crossing;
    }
  }

  std::vector<Pixel<K>>& rows_;
  PixelRect region_{0, 0, -1, -1};
  int first_ = 0, last_ = -1;  // the rows drawn (region-clamped)
};

}  // namespace softraster::detail::course
