// The known lavapipe deviations and their measurement (see deviations.hpp).
#include "run/deviations.hpp"

namespace crosscheck {

const std::vector<KnownDeviation>& knownDeviations() {
  static const std::vector<KnownDeviation> kDeviations{
      {"msaa_scissor",
       "Vulkan, Fragment Operations, \"Scissor Test\": \"The scissor test determines if a fragment's framebuffer "
       "coordinates (xf,yf) lie within the scissor rectangle\" (one test per fragment, so no sample of a pixel "
       "outside the rectangle is written)",
       "with 4x MSAA its scissor planes carry +127/256 (lp_setup_add_scissor_planes): in the column left of "
       "scissor.x it writes samples 1 and 3, in the row above scissor.y samples 2 and 3, in their corner sample 3 "
       "(unless that edge is on a 64-pixel tile boundary)",
       "msaa_scissor_viewport"},
  };
  return kDeviations;
}

const KnownDeviation* deviationShownBy(std::string_view sceneName) {
  for (const KnownDeviation& d : knownDeviations()) {
    if (d.scene == sceneName) return &d;
  }
  return nullptr;
}

}  // namespace crosscheck
