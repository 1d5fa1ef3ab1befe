// PNG output (through stb_image_write) and the depth view: depth remapped to grey.
// Deliberately write-only: the tool never needs to read images back.
#pragma once

#include <softraster/status.hpp>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace crosscheck {

// Writes RGBA8 pixels (creating the folder), as RGB when every alpha is 255, compressed with zlib
// at its best level; the error is "FILE: cannot write PNG".
softraster::Status writePng(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
                            const std::vector<std::uint8_t>& rgba);

// Depth in [lo, hi] to grey levels 0..255 as RGBA8 (near is dark); values outside saturate. With lo >= hi
// the range is taken from the depths that differ from clearDepth.
std::vector<std::uint8_t> depthToGrey(const std::vector<float>& depth, float clearDepth, float lo, float hi);

}  // namespace crosscheck
