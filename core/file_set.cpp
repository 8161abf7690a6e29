#include "core/file_set.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>
#include <thread>

#include "core/errors.h"
#include "platform/signal_cleanup.h"

namespace sylva {

namespace fs = std::filesystem;

struct FileSet::Folder {
    fs::path dir;      // the targets' folder, as given ("" for the working directory)
    fs::path staging;  // `dir/.sylva-<pid>-<n>.tmp`
    std::unique_ptr<TempRegistration> registration;
};

struct FileSet::Staged {
    fs::path target;
    fs::path temp;  // `staging/<target's file name>`
    Folder* folder = nullptr;
    std::unique_ptr<TempRegistration> registration;
};

namespace {

[[noreturn]] void refuse(const fs::path& path, const std::string& why) {
    throw IoError("cannot write '" + path.string() + "': " + why, path);
}

std::string not_a_file(fs::file_type type) {
    switch (type) {
        case fs::file_type::directory:
            return "it is a directory";
        case fs::file_type::block:
        case fs::file_type::character:
            return "it is a device, not a file (refusing to replace it)";
        case fs::file_type::fifo:
            return "it is a FIFO, not a file (refusing to replace it)";
        case fs::file_type::socket:
            return "it is a socket, not a file (refusing to replace it)";
        default:
            return "it is not a regular file (refusing to replace it)";
    }
}

// A test seam: SYLVA_TEST_STAGING_DELAY_MS pauses after each staged file, so a test can
// interrupt an export while its temporaries exist. Unset in any real run.
void staging_delay() {
    static const long ms = [] {
        const char* text = std::getenv("SYLVA_TEST_STAGING_DELAY_MS");
        return text ? std::strtol(text, nullptr, 10) : 0L;
    }();
    if (ms > 0) std::this_thread::sleep_for(std::chrono::milliseconds(ms));
}

std::atomic<unsigned> staging_counter{0};

}  // namespace

fs::path output_target(const fs::path& path) {
    fs::path target = path;
    for (int hops = 0;; ++hops) {
        std::error_code ec;
        const fs::file_status status = fs::symlink_status(target, ec);
        if (ec || status.type() == fs::file_type::not_found ||
            status.type() == fs::file_type::regular)
            return target;  // a missing parent folder is reported when writing
        if (status.type() != fs::file_type::symlink) {
            if (target == path) refuse(path, not_a_file(status.type()));
            refuse(path, "it links to '" + target.string() + "': " + not_a_file(status.type()));
        }
        if (hops == 40) refuse(path, "too many levels of symbolic links");
        const fs::path link = fs::read_symlink(target, ec);
        if (ec) refuse(path, ec.message());
        target = link.is_absolute() ? link : target.parent_path() / link;
    }
}

FileSet::FileSet() = default;

FileSet::~FileSet() {
    if (!committed_) roll_back();
}

FileSet::Folder& FileSet::folder_for(const fs::path& dir, const fs::path& requested) {
    for (auto& folder : folders_)
        if (folder->dir == dir) return *folder;
    auto folder = std::make_unique<Folder>();
    folder->dir = dir;
    for (int attempt = 0;; ++attempt) {
        const fs::path staging = dir / (".sylva-" + std::to_string(::getpid()) + "-" +
                                        std::to_string(staging_counter++) + ".tmp");
        // Registered first: a signal between mkdir() and the registration would leak it.
        auto registration =
            std::make_unique<TempRegistration>(staging, TempRegistration::Kind::Folder);
        if (::mkdir(staging.c_str(), 0700) == 0) {
            folder->staging = staging;
            folder->registration = std::move(registration);
            break;
        }
        if (errno != EEXIST || attempt == 100) refuse(requested, std::strerror(errno));
    }
    folders_.push_back(std::move(folder));
    return *folders_.back();
}

fs::path FileSet::add(const fs::path& requested, const std::function<void(std::ostream&)>& write) {
    assert(!committed_);
    const fs::path target = output_target(requested);
    assert(std::none_of(files_.begin(), files_.end(),
                        [&](const auto& staged) { return staged->target == target; }) &&
           "each target is added once");
    Folder* folder = &folder_for(target.parent_path(), requested);
    auto staged = std::make_unique<Staged>();
    staged->target = target;
    staged->temp = folder->staging / target.filename();
    staged->folder = folder;
    staged->registration =
        std::make_unique<TempRegistration>(staged->temp, TempRegistration::Kind::File);
    const Staged& file = *staged;
    files_.push_back(std::move(staged));
    std::ofstream out(file.temp, std::ios::binary | std::ios::trunc);
    if (!out) refuse(requested, std::strerror(errno));
    write(out);
    out.flush();
    if (!out)
        throw IoError("writing '" + requested.string() + "' failed: " + std::strerror(errno),
                      requested);
    out.close();
    if (!out)
        throw IoError("writing '" + requested.string() + "' failed: " + std::strerror(errno),
                      requested);
    staging_delay();
    return target;
}

std::vector<fs::path> FileSet::commit() {
    assert(!committed_);
    const SignalDeferral hold;
    // Hard links keep the previous files, so a failed move can put them back; where the file
    // system has none, a failure past that point keeps the new file.
    std::vector<fs::path> backups(files_.size());
    std::vector<bool> existed(files_.size());
    for (std::size_t i = 0; i < files_.size(); ++i) {
        const Staged& file = *files_[i];
        std::error_code ec;
        existed[i] = fs::exists(file.target, ec);
        if (!existed[i]) continue;
        const fs::path backup =
            file.folder->staging / ("previous-" + file.target.filename().string());
        if (::link(file.target.c_str(), backup.c_str()) == 0) backups[i] = backup;
    }
    for (std::size_t i = 0; i < files_.size(); ++i) {
        const Staged& file = *files_[i];
        std::error_code ec;
        fs::rename(file.temp, file.target, ec);
        if (!ec) continue;
        for (std::size_t j = 0; j < i; ++j) {
            std::error_code ignored;
            if (!backups[j].empty())
                fs::rename(backups[j], files_[j]->target, ignored);
            else if (!existed[j])
                fs::remove(files_[j]->target, ignored);
        }
        const fs::path target = file.target;  // roll_back() drops `file`
        roll_back();
        std::error_code ignored;
        const fs::file_status status = fs::status(target, ignored);
        const std::string why =
            status.type() != fs::file_type::regular && status.type() != fs::file_type::not_found
                ? not_a_file(status.type())
                : ec.message();
        refuse(target, why);
    }
    std::vector<fs::path> landed;
    for (std::size_t i = 0; i < files_.size(); ++i) {
        std::error_code ignored;
        if (!backups[i].empty()) fs::remove(backups[i], ignored);
        landed.push_back(files_[i]->target);
    }
    for (const auto& folder : folders_) {
        std::error_code ignored;
        fs::remove(folder->staging, ignored);
    }
    committed_ = true;
    files_.clear();  // drops the registrations
    folders_.clear();
    return landed;
}

void FileSet::roll_back() noexcept {
    for (const auto& folder : folders_) {
        std::error_code ignored;
        fs::remove_all(folder->staging, ignored);
    }
    files_.clear();
    folders_.clear();
    committed_ = true;  // nothing left to commit or undo
}

}  // namespace sylva
