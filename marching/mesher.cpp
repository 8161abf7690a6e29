// The mesher registry: the only place that maps a Mesher to its name and its function.
#include "marching/mesher.h"

#include <array>
#include <string>

#include "core/errors.h"
#include "marching/marching_cubes.h"
#include "marching/vdb_mesher.h"

namespace sylva {
namespace {

// One line per mesher, the default first. The names are what the CLI's --mesher takes.
constexpr std::array kMeshers{
    MesherInfo{Mesher::Sparse, "sparse", "skips the blocks that hold no surface (the default)",
               sparse_marching_cubes},
    MesherInfo{Mesher::Dense, "dense", "evaluates every grid node", marching_cubes},
    MesherInfo{Mesher::Vdb, "vdb", "OpenVDB narrow band + volumeToMesh", vdb_mesh},
};

constexpr auto kNames = [] {
    std::array<std::string_view, kMeshers.size()> names{};
    for (std::size_t i = 0; i < kMeshers.size(); ++i) names[i] = kMeshers[i].name;
    return names;
}();

const MesherInfo* find(Mesher mesher) {
    for (const MesherInfo& entry : kMeshers) {
        if (entry.mesher == mesher) return &entry;
    }
    return nullptr;
}

}  // namespace

Mesh mesh(const BatchField& field, const Box& box, const MeshSettings& settings) {
    const MesherInfo* entry = find(settings.mesher);
    if (!entry) {
        throw InputError("mesh: no mesher has the value " +
                         std::to_string(static_cast<int>(settings.mesher)));
    }
    return entry->run(field, box, settings);
}

std::span<const MesherInfo> meshers() {
    return kMeshers;
}

std::span<const std::string_view> mesher_names() {
    return kNames;
}

std::optional<Mesher> mesher_from_name(std::string_view name) {
    for (const MesherInfo& entry : kMeshers) {
        if (entry.name == name) return entry.mesher;
    }
    return std::nullopt;
}

std::string_view mesher_name(Mesher mesher) {
    const MesherInfo* entry = find(mesher);
    return entry ? entry->name : std::string_view();
}

}  // namespace sylva
