// The mesher registry: the only place that maps a Mesher to its name and its function.
#include "marching/mesher.h"

#include <array>
#include <string>

#include "core/errors.h"
#include "marching/marching_cubes.h"
#include "marching/vdb_mesher.h"

namespace sylva {
namespace {

struct MesherEntry {
    Mesher mesher;
    std::string_view name;
    Mesh (*run)(const BatchField&, const Box&, const MeshSettings&);
};

// One line per mesher. The names are what the CLI's --mesher takes.
constexpr std::array kMeshers{
    MesherEntry{Mesher::Dense, "dense", marching_cubes},
    MesherEntry{Mesher::Sparse, "sparse", sparse_marching_cubes},
    MesherEntry{Mesher::Vdb, "vdb", vdb_mesh},
};

const MesherEntry* find(Mesher mesher) {
    for (const MesherEntry& entry : kMeshers) {
        if (entry.mesher == mesher) return &entry;
    }
    return nullptr;
}

}  // namespace

Mesh mesh(const BatchField& field, const Box& box, const MeshSettings& settings) {
    const MesherEntry* entry = find(settings.mesher);
    if (!entry) {
        throw InputError("mesh: no mesher has the value " +
                         std::to_string(static_cast<int>(settings.mesher)));
    }
    return entry->run(field, box, settings);
}

std::optional<Mesher> mesher_from_name(std::string_view name) {
    for (const MesherEntry& entry : kMeshers) {
        if (entry.name == name) return entry.mesher;
    }
    return std::nullopt;
}

std::string_view mesher_name(Mesher mesher) {
    const MesherEntry* entry = find(mesher);
    return entry ? entry->name : std::string_view();
}

}  // namespace sylva
