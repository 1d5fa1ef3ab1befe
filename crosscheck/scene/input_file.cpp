// Input file checks (see input_file.hpp).
#include "scene/input_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

namespace crosscheck {

softraster::Status checkInputFile(const std::filesystem::path& path) {
  using softraster::Status;
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (status.type() == fs::file_type::not_found) return Status::error("file not found");
  if (ec) return Status::error("cannot be read: " + ec.message());
  if (status.type() == fs::file_type::directory) return Status::error("is a directory, not a file");
  if (status.type() != fs::file_type::regular) {
    return Status::error("is not a regular file (a device, FIFO or socket)");
  }
  // Permissions as the kernel decides them (root, ACLs), by opening it.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) return Status::error("cannot be read: " + std::system_category().message(errno));
  ::close(fd);
  return {};
}

}  // namespace crosscheck
