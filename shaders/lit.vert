#version 450
#extension GL_GOOGLE_include_directive : require
// The lit shading models' vertex stage (lighting.glsl has the light models).
// MODEL: 0 the course's omni light, 1 Phong, 2 Blinn-Phong. PER_PIXEL 0: lit here, per vertex
// (Gouraud), the colour interpolated; PER_PIXEL 1: the position, normal and colour in the
// lighting space go to the fragment stage, which lights each pixel. INTERPOLATION: the varyings'
// qualifier (empty: perspective-correct, or noperspective). SURFACE (per pixel only): 0 the
// vertex colour, 1 times a texture, 2 also a tangent-space normal map (texture coordinates and
// tangents pass through); 3 and 4 the vertex colour in the light of a shadow map (the position
// in the shadow pass's clip space passes through; 3 samples it with a comparison sampler, 4
// compares by hand). C++ twins: lit.hpp (SURFACE 0), lit_surface.hpp (SURFACE 1 and 2),
// lit_shadowed.hpp (SURFACE 3 and 4).
#define BLINN (MODEL == 2)
#ifndef SURFACE
#define SURFACE 0
#endif
#include "lighting.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inColour;
#if SURFACE >= 3
layout(location = 3) INTERPOLATION out vec4 vShadow;
#elif SURFACE >= 1
layout(location = 3) in vec2 inTexcoord;
layout(location = 3) INTERPOLATION out vec2 vTexcoord;
#endif
#if SURFACE == 2
layout(location = 4) in vec4 inTangent;  // xyz along +u, w the handedness of (tangent, bitangent, normal)
layout(location = 4) INTERPOLATION out vec4 vTangent;
#endif

#if PER_PIXEL
layout(location = 0) INTERPOLATION out vec3 vPosition;
layout(location = 1) INTERPOLATION out vec3 vNormal;
layout(location = 2) INTERPOLATION out vec4 vColour;
#else
layout(location = 0) INTERPOLATION out vec4 vColour;
#endif

void main() {
  gl_Position = toClip(inPosition);
  gl_PointSize = u.pointSize;
  vec3 position = toLighting(inPosition);
  vec3 normal = normalToLighting(inNormal);
#if PER_PIXEL
  vPosition = position;
  vNormal = normal;
  vColour = inColour;
#if SURFACE >= 3
  vShadow = toShadow(inPosition);
#elif SURFACE >= 1
  vTexcoord = inTexcoord;
#endif
#if SURFACE == 2
  vTangent = vec4(directionToLighting(inTangent.xyz), inTangent.w);
#endif
#elif MODEL == 0
  vColour = vec4(courseLight(position, normal, inColour.rgb), inColour.a);
#else
  vColour = vec4(phongLight(position, normal, inColour.rgb), inColour.a);
#endif
}
