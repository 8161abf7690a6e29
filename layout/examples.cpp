#include "layout/examples.h"

#include <filesystem>

#include "core/errors.h"

namespace sylva::layout {

PolygonMesh load_example(const std::string& name_or_path) {
    for (const auto& [name, text] : builtin_examples())
        if (name == name_or_path) return read_mesh_text(text, name + ".mesh");
    std::error_code ec;
    if (!std::filesystem::exists(name_or_path, ec))
        throw InputError("'" + name_or_path +
                         "' is neither a shipped example (see 'sylva layout examples') nor a file");
    return read_mesh_file(name_or_path);
}

}  // namespace sylva::layout
