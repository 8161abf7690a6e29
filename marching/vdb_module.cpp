// vdb_mesh(): loads the OpenVDB mesher's module on first use (marching/vdb_mesher.h says why).
#include <dlfcn.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/errors.h"
#include "marching/vdb_mesher.h"

namespace sylva {
namespace {

constexpr const char* kModuleName = "libsylva_vdb.so";

std::vector<std::filesystem::path> module_candidates() {
    std::vector<std::filesystem::path> paths;
    if (const char* chosen = std::getenv("SYLVA_VDB_MODULE"); chosen && *chosen)
        paths.emplace_back(chosen);
    std::error_code error;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
    if (!error) paths.push_back(self.parent_path() / kModuleName);
    paths.emplace_back(SYLVA_VDB_MODULE_PATH);  // where the build put it
    return paths;
}

VdbMeshFunction load_module() {
    std::string tried;
    for (const std::filesystem::path& path : module_candidates()) {
        // RTLD_LOCAL: the module keeps its own copies of the few Sylva functions it uses.
        void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!module) {
            if (std::filesystem::exists(path))
                tried += std::string("\n  ") + dlerror();
            else
                tried += "\n  " + path.string() + ": not found";
            continue;
        }
        auto* entry =
            reinterpret_cast<VdbMeshFunction (*)()>(dlsym(module, "sylva_vdb_mesh_entry"));
        if (entry) return entry();
        tried += "\n  " + path.string() + ": no sylva_vdb_mesh_entry";
    }
    throw IoError(
        "the OpenVDB mesher is not available: its module " + std::string(kModuleName) +
        " did not load (set SYLVA_VDB_MODULE to its path, or use --mesher sparse):" + tried);
}

}  // namespace

Mesh vdb_mesh(const BatchField& field, const Box& box, const MeshSettings& settings) {
    static const VdbMeshFunction run = load_module();  // once, thread-safe
    return run(field, box, settings);
}

}  // namespace sylva
