// vkref's per-sample read-back (vkref/src/samples.hpp): one invocation per pixel copies every
// sample of the multisampled colour, depth and (with STENCIL=1) stencil images into one storage
// buffer, in softraster's order (pixel (x, y)'s samples at (y * width + x) * samples + s):
//   words[0, c)            colour as the image stores it, colourWords words per sample (1, 2 or
//                          4), read through an R32_UINT, R32G32_UINT or R32G32B32A32_UINT view
//   words[c, c + n)        depth as the float the sampled view returns (bits; samples.cpp turns
//                          a UNORM depth back into its stored integer)
//   words[c + n, c + n + pixels) stencil, the samples of a pixel one byte each (sample s in byte s)
// with n = width * height * samples and c = n * colourWords.
// With COLOUR_ONLY=1 (a colour attachment after the first, dispatched once per attachment into a
// buffer of its own) only the colour is read and written, at the same place: no depth or
// stencil binding, and the buffer holds words[0, c) alone.
// Deliberately no conversion: colour is copied as bits, whatever its format; depth is left for
// the host, where the inverse of the driver's UNORM conversion is checked against sample 0 of
// the depth resolve.
#version 450
#extension GL_EXT_samplerless_texture_functions : require

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform utexture2DMS colourSamples;
#if !COLOUR_ONLY
layout(set = 0, binding = 1) uniform texture2DMS depthSamples;
#endif
#if STENCIL
layout(set = 0, binding = 2) uniform utexture2DMS stencilSamples;
#endif
layout(std430, set = 0, binding = 3) writeonly buffer Samples { uint words[]; };

layout(push_constant) uniform Frame {
  uint width;
  uint height;
  uint samples;
  uint colourWords;
};

void main() {
  const uvec2 p = gl_GlobalInvocationID.xy;
  if (p.x >= width || p.y >= height) return;
  const uint pixel = p.y * width + p.x;
  const uint n = width * height * samples;
  const uint c = n * colourWords;
  uint stencilWord = 0u;
  for (uint s = 0u; s < samples; ++s) {
    const uint i = pixel * samples + s;
    const uvec4 colour = texelFetch(colourSamples, ivec2(p), int(s));
    for (uint k = 0u; k < colourWords; ++k) words[i * colourWords + k] = colour[k];
#if !COLOUR_ONLY
    words[c + i] = floatBitsToUint(texelFetch(depthSamples, ivec2(p), int(s)).r);
#endif
#if STENCIL
    stencilWord |= (texelFetch(stencilSamples, ivec2(p), int(s)).r & 255u) << (8u * s);
#endif
  }
#if !COLOUR_ONLY
  words[c + n + pixel] = stencilWord;
#endif
}
