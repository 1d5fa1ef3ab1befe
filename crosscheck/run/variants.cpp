// The chart's variants and their runs (see variants.hpp).
#include "run/variants.hpp"

#include "compare/compare.hpp"
#include "run/timing.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <exception>
#include <memory>

namespace crosscheck {
namespace {

using timing::Clock;
using timing::millisecondsSince;
using timing::median;

// A 1/z frame's depth cleared to 0 (infinitely far) where it was not drawn: stored as the scene's
// clear depth instead, so compareFrames sees the same coverage as in a z/w frame (its depth
// values stay 1/z: they are not comparable with Vulkan's and are not charted).
void clearDepthAsVulkan(Frame& frame, const Scene& scene, softraster::DepthMode mode) {
  if (mode != softraster::DepthMode::InverseZ) return;
  const std::uint32_t far = std::bit_cast<std::uint32_t>(0.0f);
  const std::uint32_t clear = softraster::depthClearValue(scene.depthFormat, scene.clearDepth);
  for (std::uint32_t& d : frame.depthStorage) {
    if (d == far) d = clear;
  }
}

// lavapipe's frames of a scene: median submit time and the last frame.
struct Reference {
  double milliseconds = 0;
  std::optional<Frame> frame;
  std::string error;
};

Reference drawReference(const Scene& scene, vkref::Renderer& renderer, unsigned frames) {
  Reference out;
  auto prepared = prepareVulkan(scene, renderer);
  if (!prepared) {
    out.error = prepared.error();
    return out;
  }
  std::vector<double> times;
  for (unsigned i = 0; i < frames + 1; ++i) {  // the first submit is untimed
    const auto start = Clock::now();
    const softraster::Status status = renderer.submit(*prepared);
    const double ms = millisecondsSince(start);
    if (!status) {
      out.error = status.prefixed("vulkan").message();
      return out;
    }
    if (i > 0) times.push_back(ms);
  }
  out.milliseconds = median(times);
  auto frame = readVulkan(scene, renderer, *prepared);
  if (!frame) {
    out.error = frame.error();
    return out;
  }
  out.frame = std::move(*frame);
  return out;
}

// One variant's frames: the timings into `run`, the last frame returned.
std::optional<Frame> drawVariant(const Scene& scene, const Variant& variant, unsigned frames, VariantRun& run) {
  SoftrasterScene prepared(scene, variant.options);
  for (unsigned i = 0; i < frames + 1; ++i) {  // the first frame is untimed
    const softraster::Status status = prepared.render();
    if (!status) {
      run.error = status.message();
      return std::nullopt;
    }
    if (i > 0) run.frameMilliseconds.push_back(prepared.milliseconds());
  }
  return prepared.takeFrame();
}

std::optional<Frame> drawOnce(const Scene& scene, const softraster::ContextOptions& options, std::string& error) {
  auto frame = renderSoftraster(scene, options);
  if (!frame) {
    error = frame.error();
    return std::nullopt;
  }
  return std::move(*frame);
}

}  // namespace

std::string variantLabel(softraster::Method method, softraster::DepthMode depth) {
  std::string label(softraster::methodName(method));
  if (depth == softraster::DepthMode::InverseZ) label += " 1/z";
  return label;
}

std::vector<Variant> chartVariants(const softraster::ContextOptions& base) {
  std::vector<Variant> variants;
  for (softraster::Method method : softraster::kMethods) {
    for (softraster::DepthMode depth : {softraster::DepthMode::Vulkan, softraster::DepthMode::InverseZ}) {
      Variant v{variantLabel(method, depth), base};
      v.options.method = method;
      v.options.depthMode = depth;
      variants.push_back(std::move(v));
    }
    if (softraster::isCourseMethod(method)) {  // the course's cheaper varyings: affine, not perspective-correct
      Variant v{std::string(softraster::methodName(method)) + " affine", base};
      v.options.method = method;
      v.options.affineVaryings = true;
      variants.push_back(std::move(v));
    }
  }
  return variants;
}

Scene hitCountScene(const Scene& scene) {
  Scene counting = scene;
  counting.clearColour = {0, 0, 0, 0};
  const shaders::ShadingModel* constant = shaders::findShadingModel(shaders::kDefaultShadingModel);
  constexpr float kStep = 1.0f / 255.0f;
  for (Draw& draw : counting.draws) {
    draw.shading = constant;
    draw.textures.clear();  // the constant model samples nothing
    draw.mesh.colours.assign(draw.mesh.positions.size(), softraster::Vec4{kStep, kStep, kStep, kStep});
    draw.state.depth.testEnable = false;
    draw.state.depth.writeEnable = false;
    draw.state.depth.stencilTestEnable = false;  // the stencil would mask what was covered
    softraster::BlendState& blend = draw.state.blend;
    blend.enable = true;
    blend.srcColorBlendFactor = blend.dstColorBlendFactor = softraster::BlendFactor::One;
    blend.srcAlphaBlendFactor = blend.dstAlphaBlendFactor = softraster::BlendFactor::One;
    blend.colorBlendOp = blend.alphaBlendOp = softraster::BlendOp::Add;
    blend.colorWriteMask = softraster::kColourRGBA;
  }
  return counting;
}

HitCounts compareHits(const Frame& frame, const Frame& reference) {
  HitCounts hits;
  const std::size_t n = std::min(frame.rgba.size(), reference.rgba.size());
  for (std::size_t i = 0; i < n; i += 4) {
    const unsigned mine = frame.rgba[i], theirs = reference.rgba[i];
    if (theirs > 0) ++hits.referenceCovered;
    if (theirs > 0 && mine == 0) ++hits.cracks;
    if (mine > theirs) ++hits.doubleHits;
  }
  return hits;
}

VariantResults runVariants(const Scene& scene, const std::vector<Variant>& variants, vkref::Renderer& renderer,
                           const VariantOptions& options) {
  VariantResults out;
  out.frames = std::max(1u, options.frames);
  Reference reference = drawReference(scene, renderer, out.frames);
  out.lavapipeMilliseconds = reference.milliseconds;
  out.lavapipeError = reference.error;

  const bool countHits = options.countHits && scene.samples == 1;
  std::optional<Scene> counting;
  std::optional<Frame> referenceHits;
  if (countHits && reference.frame) {
    counting = hitCountScene(scene);
    Reference r = drawReference(*counting, renderer, 0);
    if (r.frame) referenceHits = std::move(r.frame);
  }

  for (const Variant& variant : variants) {
    VariantRun run;
    run.label = variant.label;
    run.method = softraster::methodName(variant.options.method);
    run.depth = variant.options.depthMode == softraster::DepthMode::InverseZ ? "1/z" : "z";
    try {
      std::optional<Frame> frame = drawVariant(scene, variant, out.frames, run);
      if (frame) clearDepthAsVulkan(*frame, scene, variant.options.depthMode);
      run.medianMilliseconds = median(run.frameMilliseconds);
      if (frame && reference.frame) {
        const Comparison c = compareFrames(*frame, *reference.frame, scene);
        run.coverageMismatches = c.coverageMismatches;
        run.colourMaxDelta = *std::max_element(c.colourMaxDelta.begin(), c.colourMaxDelta.end());
        run.differingPixels = colourDifferingPixels(*frame, *reference.frame);
        run.withinTolerance = c.passed();
      }
      if (frame && counting && referenceHits) {
        std::string error;
        const std::optional<Frame> hits = drawOnce(*counting, variant.options, error);
        if (hits) {
          run.hits = compareHits(*hits, *referenceHits);
        } else if (run.ok()) {
          run.error = "hit count: " + error;
        }
      }
    } catch (const std::exception& e) {
      run.error = std::string("exception: ") + e.what();
    } catch (...) {
      run.error = "exception of unknown type";
    }
    out.runs.push_back(std::move(run));
  }
  return out;
}

}  // namespace crosscheck
