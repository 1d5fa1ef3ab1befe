#version 450
// builtins_frag_depth: writes gl_FragDepth = (gl_FragCoord.z - 0.8) * 8 plus 0.25 on the left
// half of every 16-pixel period of gl_FragCoord.x, so the depth test and write take a value that
// is no plane, leaves [0, 1] at both ends (clamped as the format and depth clamp say) and has no
// depth bias; the colour is the vertex colour. C++ twin: builtins_frag_depth.hpp.

layout(location = 0) in vec4 vColour;
layout(location = 0) out vec4 outColour;

void main() {
  float cx = gl_FragCoord.x * 0.0625;
  float stripe = cx - floor(cx) < 0.5 ? 0.25 : 0.0;
  gl_FragDepth = (gl_FragCoord.z - 0.8) * 8.0 + stripe;
  outColour = vColour;
}
