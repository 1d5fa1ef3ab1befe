// Writes an RGBA8 image (row 0 at the top, as softraster stores it) to a PNG file.
// Deliberately only what the examples need: no other format, no reading.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

bool writePng(const std::string& path, std::uint32_t width, std::uint32_t height, const std::vector<std::uint8_t>& rgba);
