#version 450
// builtins_sample_mask: gl_SampleMask and gl_SampleMaskIn. Keeps the samples of a pattern of
// gl_FragCoord: mask (column + 3 * row) & 15, column and row the integer parts of
// gl_FragCoord.xy (with one sample bit 0 keeps every other pixel of a row; with sample shading
// each invocation's own bit decides). Red is gl_SampleMaskIn / 16 (the samples the fragment
// covers), green, blue and alpha the vertex colour's. Every operation is exact, so the twin gets
// the same bits.
// C++ twin: builtins_sample_mask.hpp.

layout(location = 0) in vec4 vColour;
layout(location = 0) out vec4 outColour;

void main() {
  int column = int(gl_FragCoord.x);
  int row = int(gl_FragCoord.y);
  gl_SampleMask[0] = (column + 3 * row) & 15;
  outColour = vec4(float(gl_SampleMaskIn[0]) * 0.0625, vColour.g, vColour.b, vColour.a);
}
