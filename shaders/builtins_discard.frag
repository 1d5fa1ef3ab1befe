#version 450
// builtins_discard: discards the pixels whose column and row both fall in the first half of a
// 4-pixel period (a pattern of gl_FragCoord.xy); front faces are coloured by gl_FragCoord
// (x / 128, y / 128, z, w * 2), back faces by the vertex colour and 1 - gl_FragCoord.z.
// Every operation is exact or one IEEE rounding, so the twin gets the same bits.
// C++ twin: builtins_discard.hpp.

layout(location = 0) in vec4 vColour;
layout(location = 0) out vec4 outColour;

void main() {
  float cx = gl_FragCoord.x * 0.25;
  float cy = gl_FragCoord.y * 0.25;
  if (cx - floor(cx) < 0.5 && cy - floor(cy) < 0.5) discard;
  if (gl_FrontFacing) {
    outColour = vec4(gl_FragCoord.x / 128.0, gl_FragCoord.y / 128.0, gl_FragCoord.z, gl_FragCoord.w * 2.0);
  } else {
    outColour = vec4(vColour.rgb, 1.0 - gl_FragCoord.z);
  }
}
