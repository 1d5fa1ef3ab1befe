// Per-tile depth bounds (a hierarchical depth test) for the fast path's single-sample triangles,
// lines and points. A single-sample framebuffer keeps, per 32x32 tile, bounds [lo, hi] on the
// depth stored there (framebuffer.hpp: DepthTileRange, as keys that order like the depth test).
//   - Skipping: a primitive whose box covers at least a tile's worth of pixels bounds, per tile
//     it touches, the depth its fragments would test there, conservatively against the float
//     evaluation the fragment stage does (plane at the integer pixel coordinates with two
//     fmuladds, plus the bias, the clamp, the conversion to the format; the bound is widened by
//     2^-20 of the terms' magnitudes, several times their rounding). A tile where no fragment
//     could pass the compare op is not walked at all; the others are walked as before, in runs.
//   - Keeping the bounds true: at the start of a draw that writes depth, each tile's bound in the
//     direction the compare op can move stored depth is opened (Less: lo = -inf; Greater: hi =
//     +inf; NotEqual, Always: both), so a primitive that covers a tile in part changes nothing.
//     One that covers a whole tile, each of its fragments tested and written as the op says (no
//     stencil, nothing discarded, depth from the planes), narrows it: after Less every stored
//     value is min(old, new), so hi = min(hi, the primitive's hi), and the draw's later
//     primitives only lower values, which the open lo allows. Under NotEqual and Always a whole
//     tile would hold the primitive's range, but a later primitive of the same draw may write
//     anything in part of it, so those ops leave the tile open (closing it to the primitive's
//     range broke the bounds; tests/softraster/depth_tiles_test.cpp has the case).
//   - Draws that do not keep the bounds (the scalar method, the course's methods, the 1/z
//     buffer) forget them when they write depth; 4x MSAA framebuffers have none.
// It never changes a pixel: a skipped tile is one where every fragment fails the depth test, and
// the stencil (which a failing fragment would still update) is off
// (tests/softraster/depth_tiles_test.cpp checks the bounds and the bits).
// Tiles lie at multiples of 32 pixels, as the band queue's bands (fast/bands.hpp) do, so one
// thread at a time touches a tile.
// Deliberately absent: bounds for 4x MSAA, narrowing by a primitive that covers a tile only in
// part, accepting a whole tile without testing its fragments.
#pragma once

#include <softraster/detail/exact/triangle_setup.hpp>
#include <softraster/detail/fragment/depth.hpp>
#include <softraster/detail/fragment/shade.hpp>
#include <softraster/detail/geometry/viewport.hpp>
#include <softraster/framebuffer.hpp>
#include <softraster/state.hpp>

#include <algorithm>
#include <bitset>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>

namespace softraster::detail::fast {

inline constexpr float kNoDepthBound = std::numeric_limits<float>::infinity();

// Which way a depth write under `op` can move a stored value: down (Less), up (Greater), both.
struct DepthWriteDirection {
  bool down = false, up = false;
};
inline DepthWriteDirection depthWriteDirection(CompareOp op) {
  switch (op) {
    case CompareOp::Less:
    case CompareOp::LessOrEqual: return {true, false};
    case CompareOp::Greater:
    case CompareOp::GreaterOrEqual: return {false, true};
    case CompareOp::NotEqual:
    case CompareOp::Always: return {true, true};
    case CompareOp::Equal:  // a written value equals the stored one (as the test compares them)
    case CompareOp::Never: return {};
  }
  return {true, true};
}

// A draw that keeps the bounds opens those of the tiles of rows [y0, y1] its compare op may
// move (prepareDepthTiles, below: all of them). A pass's deferred draw (fast/deferred_draws.hpp)
// opens a band's tiles just before it draws there, after the draws before it have drawn there.
inline void prepareDepthTileRows(Framebuffer& framebuffer, const DepthState& depth, int y0, int y1) {
  if (!depth.testEnable || !depth.writeEnable) return;
  const DepthWriteDirection direction = depthWriteDirection(depth.compareOp);
  if (!direction.down && !direction.up) return;
  const std::span<DepthTileRange> tiles = FramebufferAccess::depthTiles(framebuffer);
  const std::size_t perRow = FramebufferAccess::depthTilesPerRow(framebuffer);
  const auto first = static_cast<std::size_t>(y0 / kDepthTileSize) * perRow;
  const std::size_t last = std::min(tiles.size(), static_cast<std::size_t>(y1 / kDepthTileSize + 1) * perRow);
  for (std::size_t i = first; i < last; ++i) {
    if (direction.down) tiles[i].lo = -kNoDepthBound;
    if (direction.up) tiles[i].hi = kNoDepthBound;
  }
}

// Once per draw, on the calling thread, before any fragment: a draw that writes depth opens the
// bounds its compare op may move (keeps: its fragment stage keeps them, top of this file), or
// forgets them all.
inline void prepareDepthTiles(Framebuffer& framebuffer, const DepthState& depth, bool keeps) {
  if (!depth.testEnable || !depth.writeEnable) return;  // nothing is written
  if (!keeps) {
    FramebufferAccess::forgetDepthTiles(framebuffer);
    return;
  }
  prepareDepthTileRows(framebuffer, depth, 0, static_cast<int>(framebuffer.height()) - 1);
}

// Whether every fragment with a key in [lo, hi] fails `op` against every stored key in `tile`.
inline bool everyFragmentFails(CompareOp op, float lo, float hi, const DepthTileRange& tile) {
  switch (op) {
    case CompareOp::Never: return true;
    case CompareOp::Less: return lo >= tile.hi;
    case CompareOp::LessOrEqual: return lo > tile.hi;
    case CompareOp::Greater: return hi <= tile.lo;
    case CompareOp::GreaterOrEqual: return hi < tile.lo;
    case CompareOp::Equal: return hi < tile.lo || lo > tile.hi;
    case CompareOp::NotEqual:
    case CompareOp::Always: return false;
  }
  return false;
}

// A tile's bounds after a primitive with fragment keys in [lo, hi] has tested and written every
// one of its pixels under `op`, the draw having opened them (prepareDepthTiles).
inline DepthTileRange narrowedByWholeTile(CompareOp op, float lo, float hi, DepthTileRange tile) {
  switch (op) {
    case CompareOp::Less:
    case CompareOp::LessOrEqual: tile.hi = std::min(tile.hi, hi); break;  // each value min(old, new)
    case CompareOp::Greater:
    case CompareOp::GreaterOrEqual: tile.lo = std::max(tile.lo, lo); break;  // max(old, new)
    case CompareOp::NotEqual:  // open in both directions for the rest of the draw (top comment)
    case CompareOp::Always:
    case CompareOp::Equal:
    case CompareOp::Never: break;
  }
  return tile;
}

// Keys bounding the depth a fragment stage tests at every pixel of `rect` (single sample:
// evaluatePlane at the integer pixel coordinates, plus the bias, clamped, converted), or false
// when the plane's magnitudes leave no useful bound.
template <DepthFormat Format>
inline bool depthKeyBounds(const PlaneEquation& depth, float depthOffset, DepthRange range, const PixelRect& rect,
                           float& lo, float& hi) {
  const double a0 = depth.a0, dx = depth.dadx, dy = depth.dady, offset = depthOffset;
  const double x0 = dx * rect.x0, x1 = dx * rect.x1, y0 = dy * rect.y0, y1 = dy * rect.y1;
  const double magnitude = std::fabs(a0) + std::max(std::fabs(x0), std::fabs(x1)) +
                           std::max(std::fabs(y0), std::fabs(y1)) + std::fabs(offset);
  if (!(magnitude < 0x1p100)) return false;  // NaN or huge: a float evaluation may overflow
  // The float evaluation rounds at most five times (two fmuladds, or their products and sums
  // apart, and the bias's add), each time by at most 2^-24 of a value below the magnitude, and
  // this bound's own rounding to float adds 2^-25 of it: 0.35 * 2^-20 of the magnitude in all,
  // which the slack covers three times over; flushed denormals are within 2^-126.
  const double slack = magnitude * 0x1p-20 + 0x1p-120;
  const double zLo = a0 + std::min(x0, x1) + std::min(y0, y1) + offset - slack;
  const double zHi = a0 + std::max(x0, x1) + std::max(y0, y1) + offset + slack;
  // Clamping and conversion keep the order (never reversing two depths), so they map the bounds.
  lo = depthTileKey(Format, detail::depthToStorage<Format>(detail::clampDepth(static_cast<float>(zLo), range)));
  hi = depthTileKey(Format, detail::depthToStorage<Format>(detail::clampDepth(static_cast<float>(zHi), range)));
  return true;
}

// Whether no edge value c + dcdy * y - dcdx * x over the pixels [0, x1] x [0, y1] can leave 64 bits.
template <int E>
inline bool edgeValuesFit(const EdgeFunction (&edges)[E], int x1, int y1) {
  for (int i = 0; i < E; ++i) {
    const double reach = std::fabs(static_cast<double>(edges[i].c)) + std::fabs(static_cast<double>(edges[i].dcdy)) * y1 +
                         std::fabs(static_cast<double>(edges[i].dcdx)) * x1;
    if (!(reach < 0x1p62)) return false;
  }
  return true;
}

// Whether the pixel centre (x, y) is inside every edge, as the fragment stage's lane test decides
// (value > 0); the values fit 64 bits (edgeValuesFit).
template <int E>
inline bool insideEveryEdge(const EdgeFunction (&edges)[E], int x, int y) {
  for (int i = 0; i < E; ++i) {
    if (edges[i].c + edges[i].dcdy * y - edges[i].dcdx * x <= 0) return false;
  }
  return true;
}

// Whether a fragment could fail `op` against every stored key in `tile`: with an open bound on
// the side the op compares against, none can.
inline bool tileCanRejectAll(CompareOp op, const DepthTileRange& tile) {
  switch (op) {
    case CompareOp::Never: return true;
    case CompareOp::Less:
    case CompareOp::LessOrEqual: return tile.hi < kNoDepthBound;
    case CompareOp::Greater:
    case CompareOp::GreaterOrEqual: return tile.lo > -kNoDepthBound;
    case CompareOp::Equal: return tile.hi < kNoDepthBound || tile.lo > -kNoDepthBound;
    case CompareOp::NotEqual:
    case CompareOp::Always: return false;
  }
  return false;
}

// One fragment stage's view of the tiles (a band's, or the whole draw's with one thread).
template <DepthFormat Format>
class DepthTiles {
 public:
  DepthTiles() = default;  // keeps nothing: every primitive walked whole

  // shadesFirst: fragments may be dropped before the depth test (discard, alpha to coverage);
  // writesFragDepth: the shader gives the depth, which the planes do not bound.
  DepthTiles(Framebuffer& framebuffer, const FragmentTarget& target, bool inverseZ, bool shadesFirst,
             bool writesFragDepth)
      : tiles_(FramebufferAccess::depthTiles(framebuffer)),
        perRow_(static_cast<int>(FramebufferAccess::depthTilesPerRow(framebuffer))),
        width_(static_cast<int>(framebuffer.width())),
        height_(static_cast<int>(framebuffer.height())),
        op_(target.depth.compareOp),
        range_(target.depthRange) {
    const bool tested = target.depth.testEnable && !inverseZ && !target.stencil.enable && !writesFragDepth &&
                        framebuffer.samples() == 1 && !tiles_.empty();
    skips_ = tested && op_ != CompareOp::NotEqual && op_ != CompareOp::Always;
    const DepthWriteDirection direction = depthWriteDirection(op_);
    narrows_ = tested && target.depth.writeEnable && !shadesFirst && direction.down != direction.up;
  }

  // The primitive (its edges, its box clipped to the stage's region, its depth plane and bias)
  // through walk(part) for each part of `box` not skipped; narrows the tiles it covers whole.
  template <int E, class Walk>
  void shade(const EdgeFunction (&edges)[E], const PixelRect& box, const PlaneEquation& depth, float depthOffset,
             Walk&& walk) const {
    const long area = static_cast<long>(box.x1 - box.x0 + 1) * (box.y1 - box.y0 + 1);
    if ((!skips_ && !narrows_) || area < kDepthTileSize * kDepthTileSize) {
      walk(box);
      return;
    }
    const bool fits = narrows_ && edgeValuesFit(edges, box.x1, box.y1);  // so a whole tile may be found
    const int tx0 = box.x0 / kDepthTileSize, tx1 = box.x1 / kDepthTileSize;
    const int ty0 = box.y0 / kDepthTileSize, ty1 = box.y1 / kDepthTileSize;
    int walkedFrom = box.y0;  // rows from here down to the current tile row not walked yet, none of them skipped
    for (int ty = ty0; ty <= ty1; ++ty) {
      const PixelRect rows{box.x0, std::max(box.y0, ty * kDepthTileSize), box.x1,
                           std::min(box.y1, ty * kDepthTileSize + kDepthTileSize - 1)};
      skipped_.reset();
      bool anySkipped = false;
      for (int tx = tx0; tx <= tx1; ++tx) {
        const PixelRect tile{tx * kDepthTileSize, ty * kDepthTileSize, std::min(width_, (tx + 1) * kDepthTileSize) - 1,
                             std::min(height_, (ty + 1) * kDepthTileSize) - 1};
        const PixelRect part = intersect(tile, box);
        DepthTileRange& range = tiles_[static_cast<std::size_t>(ty) * static_cast<std::size_t>(perRow_) +
                                       static_cast<std::size_t>(tx)];
        float lo = -kNoDepthBound, hi = kNoDepthBound;  // set by depthKeyBounds before any use
        bool bounded = false;
        if (skips_ && tileCanRejectAll(op_, range)) {
          bounded = depthKeyBounds<Format>(depth, depthOffset, range_, part, lo, hi);
          if (bounded && everyFragmentFails(op_, lo, hi, range)) {
            skipped_.set(static_cast<std::size_t>(tx - tx0));
            anySkipped = true;
            continue;
          }
        }
        // Convex: its four corners inside every edge, the whole tile is.
        const bool whole = fits && part.x0 == tile.x0 && part.y0 == tile.y0 && part.x1 == tile.x1 &&
                           part.y1 == tile.y1 && insideEveryEdge(edges, tile.x0, tile.y0) &&
                           insideEveryEdge(edges, tile.x1, tile.y0) && insideEveryEdge(edges, tile.x0, tile.y1) &&
                           insideEveryEdge(edges, tile.x1, tile.y1);
        if (whole && (bounded || depthKeyBounds<Format>(depth, depthOffset, range_, part, lo, hi))) {
          range = narrowedByWholeTile(op_, lo, hi, range);
        }
      }
      if (!anySkipped) continue;  // walked with the rows after it
      if (walkedFrom < rows.y0) walk(PixelRect{box.x0, walkedFrom, box.x1, rows.y0 - 1});
      walkedFrom = rows.y1 + 1;
      for (int tx = tx0; tx <= tx1;) {  // the runs of tiles not skipped
        if (skipped_.test(static_cast<std::size_t>(tx - tx0))) {
          ++tx;
          continue;
        }
        const int first = tx;
        while (tx <= tx1 && !skipped_.test(static_cast<std::size_t>(tx - tx0))) ++tx;
        walk(PixelRect{std::max(box.x0, first * kDepthTileSize), rows.y0, std::min(box.x1, tx * kDepthTileSize - 1), rows.y1});
      }
    }
    if (walkedFrom <= box.y1) walk(PixelRect{box.x0, walkedFrom, box.x1, box.y1});
  }

 private:
  static constexpr std::size_t kMaxTilesPerRow = (kMaxFramebufferSize + kDepthTileSize - 1) / kDepthTileSize;

  std::span<DepthTileRange> tiles_;
  int perRow_ = 0, width_ = 0, height_ = 0;
  CompareOp op_ = CompareOp::Always;
  DepthRange range_;
  bool skips_ = false;    // the depth test may fail every fragment of a tile, and nothing else happens then
  bool narrows_ = false;  // a primitive covering a tile tests and writes each of its pixels
  mutable std::bitset<kMaxTilesPerRow> skipped_;  // of the current tile row, from the box's first tile
};

}  // namespace softraster::detail::fast
