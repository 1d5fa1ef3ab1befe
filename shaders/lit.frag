#version 450
#extension GL_GOOGLE_include_directive : require
// The lit shading models' fragment stage: MODEL, PER_PIXEL, INTERPOLATION and SURFACE as in
// lit.vert. C++ twins: lit.hpp (SURFACE 0), lit_surface.hpp (SURFACE 1 and 2), lit_shadowed.hpp
// (SURFACE 3 and 4).
#define BLINN (MODEL == 2)
#ifndef SURFACE
#define SURFACE 0
#endif
#include "lighting.glsl"

#if PER_PIXEL
layout(location = 0) INTERPOLATION in vec3 vPosition;
layout(location = 1) INTERPOLATION in vec3 vNormal;
layout(location = 2) INTERPOLATION in vec4 vColour;
#else
layout(location = 0) INTERPOLATION in vec4 vColour;
#endif
#if SURFACE == 3
layout(location = 3) INTERPOLATION in vec4 vShadow;
layout(set = 1, binding = 0) uniform sampler2DShadow uShadowMap;
#elif SURFACE == 4
layout(location = 3) INTERPOLATION in vec4 vShadow;
layout(set = 1, binding = 0) uniform sampler2D uShadowMap;
#elif SURFACE >= 1
layout(location = 3) INTERPOLATION in vec2 vTexcoord;
layout(set = 1, binding = 0) uniform sampler2D uTexture;
#endif
#if SURFACE == 2
layout(location = 4) INTERPOLATION in vec4 vTangent;
layout(set = 1, binding = 1) uniform sampler2D uNormalMap;
#endif
layout(location = 0) out vec4 outColour;

#if SURFACE >= 3
// How much of the light reaches this point: the shadow pass's clip position to the shadow map's
// texture coordinates (y down, as the pass's rows are) and reference depth, less the bias; 3
// compares in the sampler (filtered 0/1 results), 4 compares one texel's depth by hand.
float visibility() {
  precise vec3 p = vShadow.xyz / vShadow.w;
  precise vec2 uv = p.xy * 0.5 + 0.5;
  precise float reference = p.z - u.shadow.x;
#if SURFACE == 3
  return texture(uShadowMap, vec3(uv, reference));
#else
  return reference <= texture(uShadowMap, uv).r ? 1.0 : 0.0;
#endif
}
#endif

void main() {
#if SURFACE >= 3
  outColour = vec4(phongLightVisible(vPosition, vNormal, vColour.rgb, visibility()), vColour.a);
#elif SURFACE >= 1
  precise vec4 surface = vColour * texture(uTexture, vTexcoord);
#if SURFACE == 2
  // The normal map's (x, y, z) in [0, 1] to [-1, 1], in the frame of the interpolated normal,
  // tangent and their cross product (the bitangent, flipped by the tangent's w).
  precise vec3 n = normalize(vNormal);
  precise vec3 t = normalize(vTangent.xyz);
  precise vec3 b = cross(n, t) * vTangent.w;
  precise vec3 m = texture(uNormalMap, vTexcoord).xyz * 2.0 - 1.0;
  precise vec3 normal = t * m.x + b * m.y + n * m.z;
#else
  vec3 normal = vNormal;
#endif
  outColour = vec4(phongLight(vPosition, normal, surface.rgb), surface.a);
#elif !PER_PIXEL
  outColour = vColour;
#elif MODEL == 0
  outColour = vec4(courseLight(vPosition, vNormal, vColour.rgb), vColour.a);
#else
  outColour = vec4(phongLight(vPosition, vNormal, vColour.rgb), vColour.a);
#endif
}
