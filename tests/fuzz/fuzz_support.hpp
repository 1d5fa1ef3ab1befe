// What the fuzz targets share: a scratch folder for the loaders (which read files, not bytes), a
// reader that turns fuzz bytes into bounded numbers and floats (special values included), and
// failing loudly when a property does not hold (abort: libFuzzer keeps the input).
// Deliberately no libFuzzer header: the same sources also build with GCC as replay programs
// (replay_main.cpp) that ctest runs over the corpus and the saved regressions.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <string_view>

namespace fuzz {

// A folder of its own for this process, removed at exit.
inline const std::filesystem::path& scratchDir() {
  static const std::filesystem::path dir = [] {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/crosscheck-fuzz-XXXXXX";
    if (!mkdtemp(pattern.data())) {
      std::perror("mkdtemp");
      std::abort();
    }
    static const std::filesystem::path made = pattern;
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(made, ec);
    });
    return made;
  }();
  return dir;
}

inline void writeFile(const std::filesystem::path& path, std::string_view bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) {
    std::fprintf(stderr, "fuzz: cannot write %s\n", path.c_str());
    std::abort();
  }
}

// Ends the run when a property fails, naming it (libFuzzer saves the input as a crash).
inline void require(bool holds, const char* property, const std::string& detail = "") {
  if (holds) return;
  std::fprintf(stderr, "fuzz: property failed: %s%s%s\n", property, detail.empty() ? "" : ": ", detail.c_str());
  std::abort();
}

// Splits `text` at the first `separator`: (before, after); after is empty when it is absent.
inline std::pair<std::string_view, std::string_view> splitAt(std::string_view text, std::string_view separator) {
  const auto at = text.find(separator);
  if (at == std::string_view::npos) return {text, {}};
  return {text.substr(0, at), text.substr(at + separator.size())};
}

// Fuzz bytes read front to back; past the end every read is 0.
class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  std::uint8_t byte() { return position_ < size_ ? data_[position_++] : 0; }
  bool flag() { return byte() & 1; }
  std::uint32_t word() {
    std::uint32_t w = 0;
    for (int i = 0; i < 4; ++i) w |= std::uint32_t{byte()} << (8 * i);
    return w;
  }
  // 0..count-1.
  unsigned below(unsigned count) { return count ? byte() % count : 0; }

  // A float: often a small multiple of 1/64, sometimes a special value, sometimes any bits.
  float number() {
    static constexpr float kSpecial[] = {0.0f, -0.0f, 1.0f, -1.0f, 0.5f, 2.0f, 1e-3f, 1e-30f, 1e30f, -1e30f,
                                         std::numeric_limits<float>::max(), std::numeric_limits<float>::lowest(),
                                         std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::infinity(),
                                         -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN(),
                                         8388608.0f, 16777217.0f, 0.99999994f, 1.00000012f};
    const std::uint8_t kind = byte();
    if (kind < 160) {
      const auto small = static_cast<std::int16_t>(byte() | (byte() << 8));
      return static_cast<float>(small) / 64.0f;
    }
    if (kind < 224) return kSpecial[kind % (sizeof kSpecial / sizeof kSpecial[0])];
    return std::bit_cast<float>(word());
  }

  bool atEnd() const { return position_ >= size_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t position_ = 0;
};

}  // namespace fuzz
