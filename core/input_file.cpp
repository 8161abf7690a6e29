#include "core/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cstring>

#include "core/errors.h"

namespace sylva {
namespace {

// Closes the descriptor on every way out.
struct Descriptor {
    int fd = -1;
    ~Descriptor() {
        if (fd >= 0) ::close(fd);
    }
};

std::string file_kind(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISSOCK(mode)) return "a socket";
    if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
    return "not a regular file";
}

std::string mib(std::uintmax_t bytes) {
    return std::to_string((bytes + (std::uintmax_t{1} << 20) - 1) >> 20) + " MiB";
}

}  // namespace

std::uintmax_t input_size_limit() {
    const char* text = std::getenv("SYLVA_MAX_INPUT_MB");
    if (!text || !*text) return kDefaultInputLimit;
    std::uintmax_t megabytes = 0;
    const char* end = text + std::strlen(text);
    const auto [ptr, ec] = std::from_chars(text, end, megabytes);
    // Past 2^40 MiB a shift would overflow; such a limit means "none" anyway.
    if (ec != std::errc() || ptr != end || megabytes == 0 || megabytes > (std::uintmax_t{1} << 40))
        return kDefaultInputLimit;
    return megabytes << 20;
}

std::string read_input_file(const std::filesystem::path& path, std::string_view what,
                            std::uintmax_t max_bytes) {
    const std::string name = std::string(what) + " '" + path.string() + "'";
    Descriptor file;
    // O_NONBLOCK: opening a FIFO for reading returns at once instead of waiting for a writer.
    file.fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (file.fd < 0) {
        const int error = errno;
        if (error == ENOENT) throw IoError("cannot read " + name + ": no such file", path);
        throw IoError("cannot read " + name + ": " + std::strerror(error), path);
    }
    struct stat info {};
    if (::fstat(file.fd, &info) != 0)
        throw IoError("cannot read " + name + ": " + std::strerror(errno), path);
    if (!S_ISREG(info.st_mode))
        throw IoError(
            "cannot read " + name + ": it is " + file_kind(info.st_mode) + ", not a regular file",
            path);
    const auto size = static_cast<std::uintmax_t>(info.st_size);
    if (size > max_bytes)
        throw IoError("cannot read " + name + ": it has " + std::to_string(size) +
                          " bytes, over the limit of " + mib(max_bytes) +
                          " (raise it with SYLVA_MAX_INPUT_MB)",
                      path);
    std::string bytes;
    bytes.resize(static_cast<std::size_t>(size));
    std::size_t done = 0;
    // A file that grows while it is read is cut at the size it had: the limit holds.
    while (done < bytes.size()) {
        const ssize_t n = ::read(file.fd, bytes.data() + done, bytes.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            throw IoError("cannot read " + name + ": " + std::strerror(errno), path);
        }
        if (n == 0) break;
        done += static_cast<std::size_t>(n);
    }
    bytes.resize(done);
    return bytes;
}

}  // namespace sylva
