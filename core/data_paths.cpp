#include "core/data_paths.h"

#include <system_error>

#include "core/errors.h"

namespace sylva {
namespace {

bool inside(const std::filesystem::path& path, const std::filesystem::path& folder) {
    auto p = path.begin();
    for (auto f = folder.begin(); f != folder.end(); ++f, ++p) {
        if (f->empty()) continue;  // a trailing separator
        if (p == path.end() || *p != *f) return false;
    }
    return true;
}

}  // namespace

std::filesystem::path resolve_data_reference(std::string_view name,
                                             const std::filesystem::path& folder,
                                             std::string_view where) {
    const std::string at(where);
    const std::string quoted = "'" + std::string(name) + "'";
    if (name.empty()) throw InputError(at + ": the file name is empty");
    if (name.find('\0') != std::string_view::npos)
        throw InputError(at + ": the file name holds a NUL byte");
    if (folder.empty())
        throw InputError(at + ": " + quoted +
                         " names a file, but this text came from no file to look beside");
    const std::filesystem::path relative{std::string(name)};
    if (relative.is_absolute() || relative.has_root_name() || relative.has_root_directory())
        throw InputError(at + ": " + quoted +
                         " is an absolute path; a data file names files relative to its own "
                         "folder");
    for (const auto& part : relative)
        if (part == "..")
            throw InputError(at + ": " + quoted +
                             " leads out of the data file's folder ('..' is not allowed)");
    const std::filesystem::path path = folder / relative;
    // Links inside the folder may lead anywhere: compare where both really are.
    std::error_code ec;
    const std::filesystem::path real_folder = std::filesystem::weakly_canonical(folder, ec);
    if (ec) return path;  // the folder cannot be resolved: reading will fail and say so
    const std::filesystem::path real = std::filesystem::weakly_canonical(path, ec);
    if (ec || !inside(real, real_folder))
        throw InputError(at + ": " + quoted +
                         " leads out of the data file's folder through a symbolic link");
    return path;
}

std::filesystem::path data_folder(const std::filesystem::path& file) {
    const std::filesystem::path folder = file.parent_path();
    return folder.empty() ? std::filesystem::path(".") : folder;
}

std::string safe_file_name(std::string_view name, std::string_view fallback) {
    constexpr std::size_t kMaxLength = 64;
    const auto alnum = [&](std::size_t i) {
        if (i >= name.size()) return false;
        const char c = name[i];
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    };
    std::string out;
    bool pending = false;  // an unsafe run since the last safe byte, inside the name
    for (std::size_t i = 0; i < name.size() && out.size() < kMaxLength; ++i) {
        const char c = name[i];
        // A dot only between letters or digits ("oak.v2"): never "..", never a leading one.
        const bool safe =
            alnum(i) || c == '-' || c == '_' || (c == '.' && i > 0 && alnum(i - 1) && alnum(i + 1));
        if (!safe) {
            pending = !out.empty();
            continue;
        }
        if (pending) out += '_';
        pending = false;
        out += c;
    }
    if (out.size() > kMaxLength) out.resize(kMaxLength);
    return out.empty() ? std::string(fallback) : out;
}

}  // namespace sylva
