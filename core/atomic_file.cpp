#include "core/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>

#include "core/errors.h"

namespace sylva {

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::is_directory(path, ec))
        throw IoError("cannot write '" + path.string() + "': it is a directory", path);
    // The temporary sits in the target's folder so the rename never crosses file systems.
    fs::path temp = path;
    temp += ".tmp-" + std::to_string(::getpid());
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        if (!out)
            throw IoError("cannot write '" + path.string() + "': " + std::strerror(errno), path);
        try {
            write(out);
        } catch (...) {
            out.close();
            fs::remove(temp, ec);
            throw;
        }
        out.flush();
        if (!out) {
            int error = errno;
            out.close();
            fs::remove(temp, ec);
            throw IoError("writing '" + path.string() + "' failed: " + std::strerror(error), path);
        }
    }
    fs::rename(temp, path, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(temp, ignored);
        throw IoError("cannot write '" + path.string() + "': " + ec.message(), path);
    }
}

}  // namespace sylva
