#version 450
// builtins_sample: the per-sample built-ins. Reading gl_SampleID makes the shader run once per
// covered sample (Vulkan: as if sample shading were on with minSampleShading 1). The colour is
// gl_SamplePosition (the sample's offset in the pixel: 0.5, 0.5 with one sample), gl_SampleID / 4
// and the vertex alpha; sample 3 is discarded in the top half of a 192-row frame. Every
// operation is exact, so the twin gets the same bits.
// C++ twin: builtins_sample.hpp.

layout(location = 0) in vec4 vColour;
layout(location = 0) out vec4 outColour;

void main() {
  if (gl_SampleID == 3 && gl_FragCoord.y < 96.0) discard;
  outColour = vec4(gl_SamplePosition.x, gl_SamplePosition.y, float(gl_SampleID) * 0.25, vColour.a);
}
