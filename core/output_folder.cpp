#include "core/output_folder.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include "core/errors.h"

namespace sylva {

std::filesystem::path missing_folder(const std::filesystem::path& dir) {
    namespace fs = std::filesystem;
    fs::path outermost;
    std::error_code ec;
    for (fs::path p = dir; !p.empty(); p = p.parent_path()) {
        if (fs::exists(fs::status(p, ec))) break;
        outermost = p;
        if (p == p.parent_path()) break;
    }
    return outermost;
}

OutputFolder::OutputFolder(const std::filesystem::path& dir) {
    namespace fs = std::filesystem;
    const fs::path folder = dir.empty() ? fs::path(".") : dir;
    auto refuse = [&](const std::string& why) -> void {
        throw IoError("cannot write into '" + dir.string() + "': " + why, dir);
    };
    // The missing folders, outermost first, each registered before it is made.
    std::vector<fs::path> missing;
    std::error_code ec;
    for (fs::path p = folder; !p.empty(); p = p.parent_path()) {
        const fs::file_status status = fs::status(p, ec);
        if (fs::is_directory(status)) break;
        if (fs::exists(status))
            refuse("'" + p.string() + "' is " +
                   (fs::is_regular_file(status) ? "a file" : "not a folder"));
        missing.insert(missing.begin(), p);
        if (p == p.parent_path()) break;
    }
    for (const fs::path& p : missing) {
        registrations_.push_back(
            std::make_unique<TempRegistration>(p, TempRegistration::Kind::Folder));
        if (!fs::create_directory(p, ec) && ec) {
            remove_made();
            refuse(ec.message());
        }
        made_.push_back(p);
    }
    if (::access(folder.c_str(), W_OK | X_OK) != 0) {
        const std::string why = std::strerror(errno);
        remove_made();
        refuse(why);
    }
}

OutputFolder::~OutputFolder() {
    remove_made();
}

void OutputFolder::remove_made() {
    std::error_code ec;
    for (auto p = made_.rbegin(); p != made_.rend(); ++p)
        if (std::filesystem::is_empty(*p, ec)) std::filesystem::remove(*p, ec);
    made_.clear();
}

}  // namespace sylva
