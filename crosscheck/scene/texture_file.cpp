// Texture files (see texture_file.hpp), read with stb_image (libstb-dev: Debian's copy of the
// single-header decoder; PNG is all the scenes use, and it reads it robustly, with a reason when
// it cannot), compiled here, private to this file.
#include "scene/texture_file.hpp"

#include "scene/input_file.hpp"

#include <cstdio>
#include <memory>
#include <string>

#define STBI_NO_STDIO_FOR_DEFAULT 1
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#include <stb_image.h>
#pragma GCC diagnostic pop

namespace crosscheck {

softraster::Result<softraster::Texture> loadTexture(const std::filesystem::path& path, softraster::TextureFormat format,
                                                    bool mipmaps) {
  using softraster::Status;
  const std::string name = path.string();
  if (const Status readable = checkInputFile(path); !readable) {
    return Status::error(name + ": cannot open texture: " + readable.message());
  }
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(name.c_str(), "rb"), &std::fclose);
  if (!file) return Status::error(name + ": cannot open texture");
  int width = 0, height = 0, channels = 0;
  if (!stbi_info_from_file(file.get(), &width, &height, &channels)) {
    return Status::error(name + ": not a PNG image (" + std::string(stbi_failure_reason()) + ")");
  }
  if (width <= 0 || height <= 0 || width > static_cast<int>(softraster::Texture::kMaxDimension) ||
      height > static_cast<int>(softraster::Texture::kMaxDimension)) {
    return Status::error(name + ": texture size " + std::to_string(width) + "x" + std::to_string(height) +
                         " is outside 1.." + std::to_string(softraster::Texture::kMaxDimension));
  }
  std::unique_ptr<stbi_uc, void (*)(void*)> pixels(stbi_load_from_file(file.get(), &width, &height, &channels, 4),
                                                   &stbi_image_free);
  if (!pixels) return Status::error(name + ": corrupt PNG image (" + std::string(stbi_failure_reason()) + ")");
  const std::size_t bytes = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4;
  auto texture = softraster::Texture::create(format, static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height),
                                             std::span<const std::uint8_t>(pixels.get(), bytes), mipmaps);
  if (!texture) return texture.status().prefixed(name);
  return texture;
}

}  // namespace crosscheck
