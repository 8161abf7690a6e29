// Writes a file all at once or not at all: the content goes to a staging folder beside the
// target, and the file is renamed over the target only when everything was written. A
// failed write never leaves a partial file, and the previous file stays intact. A set of
// one file of file_set.h: a symlink at `path` is followed, a directory or device refused.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>

namespace sylva {

// Throws IoError naming the path and the reason when the file cannot be written.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write);

}  // namespace sylva
