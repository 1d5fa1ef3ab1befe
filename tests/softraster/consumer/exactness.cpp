// The outside side of the exactness test: built against the installed package with whatever
// flags and compiler the consumer project was configured with, draws exactness_scene.hpp's
// frames and compares every colour and depth byte with the reference file the project's own
// build wrote (argv[1]). Prints the bytes compared and exits 0 only when all are identical.
// Deliberately no tolerance: the library promises lavapipe's bits, so any difference is a failure.
#include "exactness_scene.hpp"

#include <cstdio>
#include <cstring>

namespace {

// Bytes of `a` and `b` (of equal size) that differ.
std::size_t differingBytes(const void* a, const void* b, std::size_t size) {
  const auto* x = static_cast<const unsigned char*>(a);
  const auto* y = static_cast<const unsigned char*>(b);
  std::size_t n = 0;
  for (std::size_t i = 0; i < size; ++i) n += x[i] != y[i];
  return n;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: exactness REFERENCE\n");
    return 2;
  }
  const softraster::Result<std::vector<exactness::Frame>> reference = exactness::read(argv[1]);
  if (!reference) {
    std::fprintf(stderr, "exactness: %s\n", reference.error().c_str());
    return 2;
  }
  const softraster::Result<std::vector<exactness::Frame>> frames = exactness::render();
  if (!frames) {
    std::fprintf(stderr, "exactness: %s\n", frames.error().c_str());
    return 2;
  }
  if (frames->size() != reference->size()) {
    std::fprintf(stderr, "exactness: %zu frames, the reference has %zu\n", frames->size(), reference->size());
    return 1;
  }
  std::size_t colourBytes = 0, depthBytes = 0, colourDiffs = 0, depthDiffs = 0, covered = 0;
  for (std::size_t i = 0; i < frames->size(); ++i) {
    const exactness::Frame& got = (*frames)[i];
    const exactness::Frame& want = (*reference)[i];
    if (got.name != want.name || got.colour.size() != want.colour.size() || got.depth.size() != want.depth.size()) {
      std::fprintf(stderr, "exactness: frame %zu is '%s', the reference's is '%s' (or sizes differ)\n", i,
                   got.name.c_str(), want.name.c_str());
      return 1;
    }
    const std::size_t c = differingBytes(got.colour.data(), want.colour.data(), got.colour.size());
    const std::size_t d = differingBytes(got.depth.data(), want.depth.data(), got.depth.size() * sizeof(std::uint32_t));
    for (std::size_t s = 0; s < want.depth.size(); ++s) covered += want.depth[s] != want.depth[0];
    std::printf("%-28s %zu of %zu colour bytes and %zu of %zu depth bytes differ\n", got.name.c_str(), c,
                got.colour.size(), d, got.depth.size() * sizeof(std::uint32_t));
    colourBytes += got.colour.size();
    depthBytes += got.depth.size() * sizeof(std::uint32_t);
    colourDiffs += c;
    depthDiffs += d;
  }
  // The corner sample is background in every frame; a reference with nearly nothing drawn would
  // compare nothing worth comparing.
  if (covered < 1000) {
    std::fprintf(stderr, "exactness: only %zu samples drawn in the reference; the scene is broken\n", covered);
    return 1;
  }
  if (colourDiffs != 0 || depthDiffs != 0) {
    std::printf("DIFFERENT: %zu colour and %zu depth bytes differ from the project's build\n", colourDiffs, depthDiffs);
    return 1;
  }
  std::printf("identical: %zu colour bytes and %zu depth bytes (%zu drawn samples) match the project's build\n",
              colourBytes, depthBytes, covered);
  return 0;
}
