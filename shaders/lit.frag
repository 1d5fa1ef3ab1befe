#version 450
#extension GL_GOOGLE_include_directive : require
// The lit shading models' fragment stage: MODEL, PER_PIXEL and INTERPOLATION as in lit.vert.
// C++ twin: lit.hpp.
#define BLINN (MODEL == 2)
#include "lighting.glsl"

#if PER_PIXEL
layout(location = 0) INTERPOLATION in vec3 vPosition;
layout(location = 1) INTERPOLATION in vec3 vNormal;
layout(location = 2) INTERPOLATION in vec4 vColour;
#else
layout(location = 0) INTERPOLATION in vec4 vColour;
#endif
layout(location = 0) out vec4 outColour;

void main() {
#if !PER_PIXEL
  outColour = vColour;
#elif MODEL == 0
  outColour = vec4(courseLight(vPosition, vNormal, vColour.rgb), vColour.a);
#else
  outColour = vec4(phongLight(vPosition, vNormal, vColour.rgb), vColour.a);
#endif
}
