// The variants a scene is charted with: every softraster method (softraster::kMethods) with each
// depth option (Vulkan's z/w, the course's 1/z buffer), one label each ("exact", "exact 1/z"),
// in one list that the report's chart, `crosscheck stability` (and any caller that wants every
// point of the speed/accuracy chart) take from here. Per-vertex against per-pixel lighting is
// not a variant: they are different shading models (shaders/shading_models.cpp), so the lit
// scenes come in pairs (scenes/light_room_vertex.json, light_room_pixel.json) and each is its
// own scene on the chart.
// runVariants draws a scene with each variant a few timed frames (after one untimed frame), times
// lavapipe's submit over as many frames, and measures each variant's last frame against
// lavapipe's: coverage mismatches, colour max |Δ|, pixels that differ at all and, when asked,
// per-pixel hit counts (cracks and double hits, see HitCounts). A 1/z frame's depth is cleared to
// 0, not to the scene's clear depth: where it stayed 0 it counts as not drawn, so its coverage is
// compared as a z/w frame's (its depth values are not comparable with Vulkan's, and not charted).
// A variant that fails (a Status, an exception) is a row with its error, never a fault of the
// run; a crash inside softraster still ends the process (the report's worker processes turn it
// into the scene's Crash).
// Deliberately no printing and no statistics beyond the median.
#pragma once

#include "render/render.hpp"
#include "results/variant_results.hpp"
#include "scene/scene.hpp"

#include <softraster/options.hpp>
#include <vkref/renderer.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace crosscheck {

struct Variant {
  std::string label;                  // "exact", "exact 1/z", "exact-scalar", ...
  softraster::ContextOptions options;
};

// kMethods × {DepthMode::Vulkan, DepthMode::InverseZ}, in kMethods order, z/w first. `base`
// gives the threads and fmuladd rounding; its method and depth mode are replaced.
std::vector<Variant> chartVariants(const softraster::ContextOptions& base = {});

// The label of a method with a depth mode: "exact", "exact 1/z".
std::string variantLabel(softraster::Method method, softraster::DepthMode depth);

struct VariantOptions {
  unsigned frames = 3;                // timed frames per variant (at least 1)
  bool countHits = false;             // also count hits per pixel (HitCounts)
};

// Draws `scene` with each variant and lavapipe on `renderer` (see the top of this file).
VariantResults runVariants(const Scene& scene, const std::vector<Variant>& variants, vkref::Renderer& renderer,
                           const VariantOptions& options);

// The scene that counts hits (see HitCounts); exposed for tests.
Scene hitCountScene(const Scene& scene);

// Cracks and double hits of `frame` against `reference`, both drawn from hitCountScene.
HitCounts compareHits(const Frame& frame, const Frame& reference);

}  // namespace crosscheck
