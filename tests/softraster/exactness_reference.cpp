// The reference side of the outside-consumer exactness test: draws consumer/exactness_scene.hpp's
// frames with the project's own build (its flags, its compiler) and writes them to argv[1].
// Deliberately compares nothing: consumer/exactness.cpp, built outside, does.
#include "consumer/exactness_scene.hpp"

#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: exactness_reference OUT\n");
    return 2;
  }
  softraster::Result<std::vector<exactness::Frame>> frames = exactness::render();
  if (!frames) {
    std::fprintf(stderr, "exactness_reference: %s\n", frames.error().c_str());
    return 1;
  }
  if (!exactness::write(argv[1], *frames)) {
    std::fprintf(stderr, "exactness_reference: %s: cannot write\n", argv[1]);
    return 1;
  }
  return 0;
}
