// Culling in Mesa's draw pipeline (draw_pipe_cull.c): a float-determinant test that runs before
// setup on every triangle of a vertex batch that needed clipping (primitive_assembly.hpp says
// which batches). The fixed-point area cull that every triangle then meets is setup's
// (exact/triangle_setup.hpp, windingFilter).
// Deliberately absent: culling by clip distances (no user clip planes).
#pragma once

#include <softraster/math.hpp>
#include <softraster/state.hpp>

namespace softraster::detail {

// The float-determinant cull of Mesa's draw pipeline (draw_pipe_cull.c). It runs, before setup,
// on every triangle of a vertex batch that needed clipping. Zero determinant counts as back.
// Whether the triangle faces front by that determinant (zero: back). The polygon-mode stage uses
// it too, for the stencil face of an unfilled polygon's lines and points in Deviations::Spec.
inline bool facesFrontInPipeline(Vec4 w0, Vec4 w1, Vec4 w2, FrontFace frontFace) {
  const float ex = w0.x - w2.x, ey = w0.y - w2.y;
  const float fx = w1.x - w2.x, fy = w1.y - w2.y;
  const float det = ex * fy - ey * fx;
  if (det == 0.0f) return false;
  const bool ccw = det < 0.0f;
  return ccw == (frontFace == FrontFace::CounterClockwise);
}

inline bool survivesPipelineCull(Vec4 w0, Vec4 w1, Vec4 w2, const RasterizationState& rs) {
  if (rs.cullMode == CullMode::None) return true;
  const bool cullFront = rs.cullMode == CullMode::Front || rs.cullMode == CullMode::FrontAndBack;
  const bool cullBack = rs.cullMode == CullMode::Back || rs.cullMode == CullMode::FrontAndBack;
  return facesFrontInPipeline(w0, w1, w2, rs.frontFace) ? !cullFront : !cullBack;
}

}  // namespace softraster::detail
