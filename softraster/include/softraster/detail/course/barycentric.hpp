// The course's barycentric method (Method::Barycentric, the Givry & Shin project's): loop over
// the triangle's bounding box, compute the barycentric coordinates (u, v) of each pixel centre in
// float, p = a + u (b - a) + v (c - a), and draw the pixel when u >= 0, v >= 0 and u + v <= 1;
// its values are a + u (Pb - Pa) + v (Pc - Pa), computed afresh at every pixel (no stepping).
// A two-call object: setup(a, b, c, region) finds the box and the coordinates' gradients, then
// draw(shade) calls shade(px, py, values) for every pixel inside.
// What it does: pixel centres at +0.5; either winding (u and v do not depend on it; culling is
// done before, course/draw.hpp); the box clamped to the draw region (scissor and viewport), so a
// huge triangle costs at most the region; depth as the values carry it (Vulkan z or the
// course's 1/z, pixel.hpp); perspective-correct or affine varyings (pixel.hpp).
// What it does not do: no fill rule (a pixel centre exactly on an edge shared by two triangles is
// drawn by both: a double hit, and float rounding of u, v can leave a crack), no snapping to a
// sub-pixel grid, no clipping of its own (the shared front end clips to the frustum and guard
// band first), no MSAA coverage; a zero-area or non-finite triangle draws nothing.
#pragma once

#include <softraster/detail/course/pixel.hpp>
#include <softraster/detail/geometry/viewport.hpp>

#include <array>

namespace softraster::detail::course {

template <int K>
class BarycentricTriangle {
 public:
  // False when there is nothing to draw (zero area, a vertex not drawable(), a box outside region).
  bool setup(const Pixel<K>& a, const Pixel<K>& b, const Pixel<K>& c, const PixelRect& region) {
    if (!drawable(a) || !drawable(b) || !drawable(c)) return false;
    const float e1x = b.x - a.x, e1y = b.y - a.y;
    const float e2x = c.x - a.x, e2y = c.y - a.y;
    const float det = e1x * e2y - e2x * e1y;
    if (!(det != 0.0f) || !std::isfinite(det)) return false;
    // u = ((p - a) x e2) / det, v = (e1 x (p - a)) / det.
    invDet_ = 1.0f / det;
    a_ = a;
    e1x_ = e1x, e1y_ = e1y, e2x_ = e2x, e2y_ = e2y;
    for (int i = 0; i < K; ++i) {
      d1_[i] = b.values[i] - a.values[i];
      d2_[i] = c.values[i] - a.values[i];
    }
    const float minX = std::fmin(a.x, std::fmin(b.x, c.x)), maxX = std::fmax(a.x, std::fmax(b.x, c.x));
    const float minY = std::fmin(a.y, std::fmin(b.y, c.y)), maxY = std::fmax(a.y, std::fmax(b.y, c.y));
    box_ = {firstCentreAtOrAfter(minX, region.x0, region.x1), firstCentreAtOrAfter(minY, region.y0, region.y1),
            lastCentreAtOrBefore(maxX, region.x0, region.x1), lastCentreAtOrBefore(maxY, region.y0, region.y1)};
    return !box_.empty();
  }

  template <class Shade>
  void draw(Shade&& shade) const {
    std::array<float, K> values;
    for (int py = box_.y0; py <= box_.y1; ++py) {
      const float dy = (static_cast<float>(py) + 0.5f) - a_.y;
      for (int px = box_.x0; px <= box_.x1; ++px) {
        const float dx = (static_cast<float>(px) + 0.5f) - a_.x;
        const float u = (dx * e2y_ - e2x_ * dy) * invDet_;
        const float v = (e1x_ * dy - dx * e1y_) * invDet_;
        if (!(u >= 0.0f && v >= 0.0f && u + v <= 1.0f)) continue;
        for (int i = 0; i < K; ++i) values[i] = a_.values[i] + u * d1_[i] + v * d2_[i];
        shade(px, py, values.data());
      }
    }
  }

 private:
  Pixel<K> a_;
  float e1x_ = 0, e1y_ = 0, e2x_ = 0, e2y_ = 0, invDet_ = 0;
  std::array<float, K> d1_{}, d2_{};
  PixelRect box_{0, 0, -1, -1};
};

}  // namespace softraster::detail::course
