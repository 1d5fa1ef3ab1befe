// Coverage: the top-left rule makes triangles that share edges cover every pixel exactly once.
#include <softraster/detail/exact/rasterizer.hpp>
#include <softraster/detail/exact/triangle_setup.hpp>

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace {

using namespace softraster::detail;

struct Counter {
  int width, height;
  std::vector<int> hits;
  Counter(int w, int h) : width(w), height(h), hits(static_cast<std::size_t>(w * h), 0) {}
  void draw(FixedTriangle t) {
    const int sign = fixedAreaSign(t);
    if (sign == 0) return;
    if (sign < 0) {  // as the pipeline does: continue counter-clockwise as (v0, v2, v1)
      std::swap(t.x[1], t.x[2]);
      std::swap(t.y[1], t.y[2]);
    }
    rasterizeTriangle(setupEdges(t), PixelRect{0, 0, width - 1, height - 1},
                      [&](int px, int py) { ++hits[static_cast<std::size_t>(py * width + px)]; });
  }
};

FixedTriangle tri(int x0, int y0, int x1, int y1, int x2, int y2) { return {{x0, x1, x2}, {y0, y1, y2}}; }

// A jittered grid of triangles filling a rectangle whose sides lie between pixel centres:
// every pixel centre inside the rectangle must be hit exactly once, every other one never.
void checkJitteredGrid(unsigned seed, bool alternateWinding) {
  constexpr int kW = 64, kH = 48, kCells = 7;
  const int left = 3 * 256 + 77, right = 60 * 256 + 13, top = 2 * 256 + 200, bottom = 45 * 256 + 31;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> jitter(-300, 300);
  std::vector<int> gx((kCells + 1) * (kCells + 1)), gy(gx.size());
  for (int j = 0; j <= kCells; ++j) {
    for (int i = 0; i <= kCells; ++i) {
      int x = left + (right - left) * i / kCells, y = top + (bottom - top) * j / kCells;
      if (i > 0 && i < kCells) x += jitter(rng);
      if (j > 0 && j < kCells) y += jitter(rng);
      gx[static_cast<std::size_t>(j * (kCells + 1) + i)] = x;
      gy[static_cast<std::size_t>(j * (kCells + 1) + i)] = y;
    }
  }
  Counter counter(kW, kH);
  auto at = [&](int i, int j) { return static_cast<std::size_t>(j * (kCells + 1) + i); };
  for (int j = 0; j < kCells; ++j) {
    for (int i = 0; i < kCells; ++i) {
      const auto a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      FixedTriangle t1 = tri(gx[a], gy[a], gx[b], gy[b], gx[c], gy[c]);
      FixedTriangle t2 = tri(gx[a], gy[a], gx[c], gy[c], gx[d], gy[d]);
      if (alternateWinding && (i + j) % 2) std::swap(t1.x[1], t1.x[2]), std::swap(t1.y[1], t1.y[2]);
      counter.draw(t1);
      counter.draw(t2);
    }
  }
  int inside = 0;
  for (int py = 0; py < kH; ++py) {
    for (int px = 0; px < kW; ++px) {
      const bool expected = 256 * px > left && 256 * px < right && 256 * py > top && 256 * py < bottom;
      inside += expected;
      ASSERT_EQ(counter.hits[static_cast<std::size_t>(py * kW + px)], expected ? 1 : 0)
          << "pixel (" << px << ", " << py << ") seed " << seed;
    }
  }
  EXPECT_EQ(inside, 57 * 43);
}

}  // namespace

TEST(TopLeftRule, TwoTrianglesSharingADiagonalCoverEachPixelOnce) {
  // A square from pixel centre (2,2) to (12,12): its edges pass through pixel centres, so the
  // top-left rule decides: left and top edges are in, right and bottom edges are out.
  Counter counter(16, 16);
  counter.draw(tri(512, 512, 512, 3072, 3072, 3072));  // lower-left half, shares the diagonal
  counter.draw(tri(512, 512, 3072, 3072, 3072, 512));  // upper-right half
  for (int py = 0; py < 16; ++py) {
    for (int px = 0; px < 16; ++px) {
      const bool inside = px >= 2 && px < 12 && py >= 2 && py < 12;
      EXPECT_EQ(counter.hits[static_cast<std::size_t>(py * 16 + px)], inside ? 1 : 0) << px << "," << py;
    }
  }
}

TEST(TopLeftRule, JitteredMeshCoversEachPixelExactlyOnce) {
  for (unsigned seed = 1; seed <= 50; ++seed) checkJitteredGrid(seed, false);
}

TEST(TopLeftRule, MixedWindingMeshCoversEachPixelExactlyOnce) {
  for (unsigned seed = 100; seed <= 120; ++seed) checkJitteredGrid(seed, true);
}

TEST(TopLeftRule, HorizontalEdgeBelongsToTheTriangleBelowIt) {
  // Edge along y = pixel-centre row 4, shared by a triangle above and one below.
  Counter counter(16, 16);
  counter.draw(tri(256, 1024, 3000, 1024, 1600, 200));   // above the edge
  counter.draw(tri(256, 1024, 1600, 2400, 3000, 1024));  // below the edge
  int row4 = 0;
  for (int px = 0; px < 16; ++px) {
    ASSERT_LE(counter.hits[static_cast<std::size_t>(4 * 16 + px)], 1);
    row4 += counter.hits[static_cast<std::size_t>(4 * 16 + px)];
  }
  EXPECT_GT(row4, 0);
  // Drawing only the upper triangle: its bottom edge is not a top edge, so row 4 stays empty.
  Counter upper(16, 16);
  upper.draw(tri(256, 1024, 3000, 1024, 1600, 200));
  for (int px = 0; px < 16; ++px) EXPECT_EQ(upper.hits[static_cast<std::size_t>(4 * 16 + px)], 0);
}

TEST(FixedArea, SignFollowsVulkanWinding) {
  // Counter-clockwise on a y-down screen: top-left, bottom-left, top-right.
  EXPECT_EQ(fixedAreaSign(tri(0, 0, 0, 2560, 2560, 0)), 1);
  EXPECT_EQ(fixedAreaSign(tri(0, 0, 2560, 0, 0, 2560)), -1);
  EXPECT_EQ(fixedAreaSign(tri(0, 0, 256, 256, 512, 512)), 0);
}
