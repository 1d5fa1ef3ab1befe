#version 450
// colour_outputs: the vertex colour written to four colour attachments at once (fragment outputs
// 0..3), each output a different function of it, so an attachment that got another's output, or
// none, shows: 0 the colour; 1 its complement with red and blue swapped; 2 values outside [0, 1]
// for float targets (and clamped by UNORM ones); 3 the colour rotated and scaled.
// Vertex stage: vertex_color.vert. C++ twin: colour_outputs.hpp.
// `precise` keeps every product rounded on its own (no FMA), as the twin computes it.

layout(location = 0) in vec4 vColour;
layout(location = 0) out vec4 outColour;
layout(location = 1) out vec4 outComplement;
layout(location = 2) out vec4 outWide;
layout(location = 3) out vec4 outRotated;

void main() {
  precise vec4 c = vColour;
  outColour = c;
  outComplement = vec4(1.0 - c.b, 1.0 - c.g, 1.0 - c.r, c.a);
  precise vec4 wide = vec4(c.r * 4.0 - 2.0, c.g * c.b, -c.a, c.a * 0.5 + 0.25);
  outWide = wide;
  precise vec4 rotated = c.gbra * 0.75;
  outRotated = rotated;
}
