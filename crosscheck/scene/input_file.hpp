// Input files (scenes, OBJ meshes, expectations): whether a path names a regular file that can be
// read, and if not, one error that says why ("file not found", "is a directory", "is not a
// regular file", "cannot be read: Too many levels of symbolic links", ...). Checked before the
// file is opened, so a FIFO never blocks and /dev/zero is never read without end.
// Deliberately no reading or parsing here: each loader reads its own format.
#pragma once

#include <softraster/status.hpp>

#include <filesystem>

namespace crosscheck {

// OK when `path` is a regular file (after following symlinks) that this process can open for
// reading; otherwise why not, without the path ("file not found", "is a directory, not a file",
// ...), for the caller to put after the path. Never throws.
softraster::Status checkInputFile(const std::filesystem::path& path);

}  // namespace crosscheck
