// Texture files: a PNG (or any image stb_image reads) as a softraster::Texture, RGBA8, with its
// mip chain when asked (softraster::Texture::create makes it, the chain both renderers upload).
// Errors are one line, "FILE: what is wrong": a missing or unreadable file (input_file.hpp),
// a corrupt image (stb_image's reason), a size outside 1..16384.
// Deliberately no other formats than 8-bit RGBA (grey, grey-alpha and RGB images are expanded to it).
#pragma once

#include <softraster/status.hpp>
#include <softraster/texture.hpp>

#include <filesystem>

namespace crosscheck {

softraster::Result<softraster::Texture> loadTexture(const std::filesystem::path& path, softraster::TextureFormat format,
                                                    bool mipmaps);

}  // namespace crosscheck
