#include "export/engine_kit.h"

#include <system_error>

#include "core/errors.h"
#include "core/file_set.h"

namespace sylva {

std::vector<std::pair<std::string_view, std::string_view>> engine_kit(EngineProfile profile) {
    std::vector<std::pair<std::string_view, std::string_view>> out;
    for (const auto& file : engine_kit_files()) {
        const std::string_view kit = file.first.substr(0, file.first.find('/'));
        for (std::string_view wanted : profile_info(profile).kits)
            if (kit == wanted) out.push_back(file);
    }
    return out;
}

void add_engine_kit(FileSet& files, const std::filesystem::path& dir, EngineProfile profile) {
    for (const auto& [name, text] : engine_kit(profile)) {
        const std::filesystem::path target = dir / std::filesystem::path(name);
        std::error_code error;
        std::filesystem::create_directories(target.parent_path(), error);
        if (error)
            throw IoError("cannot make the folder '" + target.parent_path().string() +
                              "' for the engine kit: " + error.message(),
                          target.parent_path());
        files.add(target, [text = text](std::ostream& out) {
            out.write(text.data(), static_cast<std::streamsize>(text.size()));
        });
    }
}

}  // namespace sylva
