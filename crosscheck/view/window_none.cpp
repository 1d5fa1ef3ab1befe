// crosscheck view's window in a crosscheck built without SDL2 (libsdl2-dev was not found when
// CMake ran): every other command works, and view says why it cannot open a window.
#include "view/window.hpp"

namespace crosscheck::view {

softraster::Result<std::unique_ptr<Display>> openWindow(std::uint32_t, std::uint32_t, const std::string&) {
  return softraster::Status::error(
      "view: this crosscheck was built without SDL2: install libsdl2-dev (scripts/setup.sh does) and build again");
}

}  // namespace crosscheck::view
