// Writes a file all at once or not at all: the content goes to a temporary file beside the
// target, which is renamed over it only when everything was written. A failed export never
// leaves a partial file, and the previous file stays intact.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>

namespace sylva {

// Throws IoError naming the path and the reason when the file cannot be written.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write);

}  // namespace sylva
