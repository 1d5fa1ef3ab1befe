// vkref's per-sample read-back (vkref/src/samples.hpp): one invocation per pixel copies every
// sample of the multisampled colour, depth and (with STENCIL=1) stencil images into one storage
// buffer, in softraster's order (pixel (x, y)'s samples at (y * width + x) * samples + s):
//   words[0, n)           colour, RGBA8 packed as the image stores it (R in the low byte)
//   words[n, 2n)          depth as the float the sampled view returns (bits; samples.cpp turns
//                         a UNORM depth back into its stored integer)
//   words[2n, 2n + pixels) stencil, the samples of a pixel one byte each (sample s in byte s)
// with n = width * height * samples.
// Deliberately no conversion beyond RGBA8 packing: colour reads c * (1/255) and packs back to c
// exactly; depth is left for the host, where the inverse of the driver's UNORM conversion is
// checked against sample 0 of the depth resolve.
#version 450
#extension GL_EXT_samplerless_texture_functions : require

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2DMS colourSamples;
layout(set = 0, binding = 1) uniform texture2DMS depthSamples;
#if STENCIL
layout(set = 0, binding = 2) uniform utexture2DMS stencilSamples;
#endif
layout(std430, set = 0, binding = 3) writeonly buffer Samples { uint words[]; };

layout(push_constant) uniform Frame {
  uint width;
  uint height;
  uint samples;
};

void main() {
  const uvec2 p = gl_GlobalInvocationID.xy;
  if (p.x >= width || p.y >= height) return;
  const uint pixel = p.y * width + p.x;
  const uint n = width * height * samples;
  uint stencilWord = 0u;
  for (uint s = 0u; s < samples; ++s) {
    const uint i = pixel * samples + s;
    words[i] = packUnorm4x8(texelFetch(colourSamples, ivec2(p), int(s)));
    words[n + i] = floatBitsToUint(texelFetch(depthSamples, ivec2(p), int(s)).r);
#if STENCIL
    stencilWord |= (texelFetch(stencilSamples, ivec2(p), int(s)).r & 255u) << (8u * s);
#endif
  }
  words[2u * n + pixel] = stencilWord;
}
