#include "core/atomic_file.h"

#include "core/file_set.h"

namespace sylva {

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write) {
    FileSet files;
    files.add(path, write);
    files.commit();
}

}  // namespace sylva
