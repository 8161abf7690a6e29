// What every mesher shares, and the one entry that runs any of them: the field types, the
// settings, the counters, and mesh(), which picks the mesher named in the settings (as
// libfive's BRepSettings::alg). A mesher is a file in marching/ plus one Mesher value and
// one line in mesher.cpp's table; callers choose one by value or by name, never by switch.
#pragma once

#include <cstddef>
#include <functional>
#include <glm/vec3.hpp>
#include <optional>
#include <span>
#include <string_view>

#include "core/box.h"
#include "core/cancel.h"
#include "core/mesh.h"

namespace sylva {

// A field evaluated one point at a time (convenient for tests and simple shapes). Always
// called from the calling thread, so it need not be thread-safe.
using ScalarField = std::function<float(const glm::vec3&)>;

// A field evaluated in batches: values[i] = f(points[i]); both spans have the same size.
// Called concurrently from several threads: it must be thread-safe. It must also be a pure
// function of the point: the meshers may evaluate a point twice in different batches (a
// node the sparse mesher also used as a block centre, say) and rely on getting the same
// value, so that neighbouring blocks agree on a shared node.
using BatchField = std::function<void(std::span<const glm::vec3> points, std::span<float> values)>;

enum class Mesher {
    Dense,   // every grid node evaluated, in parallel slabs (marching/marching_cubes.h)
    Sparse,  // blocks that provably hold no surface are skipped (needs a distance bound)
    Vdb,     // OpenVDB narrow-band level set + tools::volumeToMesh (marching/vdb_mesher.h)
};

// Counters a benchmark or a status bar can show. Every mesher cuts the grid into blocks of
// 8 x 8 x 8 (smaller at the far ends of the axes): cells for Dense and Sparse, nodes (one
// OpenVDB leaf) for Vdb.
struct MeshingStats {
    std::size_t evaluations = 0;    // field samples taken, points in all batches
    std::size_t blocks_total = 0;   // blocks in the grid
    std::size_t blocks_meshed = 0;  // blocks whose cells were meshed (Dense: all of them)
};

// What only the OpenVDB mesher reads.
struct VdbSettings {
    // openvdb::tools::volumeToMesh adaptivity, 0 (uniform) to 1 (most merging).
    double adaptivity = 0.0;
    // Half-width of the narrow band, in voxels (at least 1): nodes nearer the surface than
    // this hold their field value, the others +-band. 1 gives the same uniform mesh for
    // about 35% fewer evaluations; adaptive merging judges flatness on the wider band.
    float band_voxels = 3.0f;
};

struct MeshSettings {
    // Which mesher mesh() runs; the functions of each mesher ignore it.
    Mesher mesher = Mesher::Sparse;
    // Cells along the longest side of the box (Heuer 2022: P_Tres / P_Cres, 10-200).
    int resolution = 64;
    // Extra empty cells added on every side so the surface is never clipped by the box.
    int padding_cells = 2;
    // Worker threads; 0 = all cores (oneTBB's default arena).
    int threads = 0;
    // Called now and then with the finished fraction in [0, 1], from any thread but never
    // concurrently; the fractions never decrease, and a run that completes ends with
    // exactly one call with 1. The callback may set *cancel.
    std::function<void(float)> progress;
    // Polled between small pieces of work (a batch of a few thousand nodes, or a few
    // blocks); once it is true the mesher lets the running pieces finish, drops its work
    // and throws Cancelled.
    CancelFlag cancel = nullptr;
    // Overwritten when not null (and the run completes).
    MeshingStats* stats = nullptr;
    // Read by Mesher::Vdb only.
    VdbSettings vdb;
};

// Meshes the zero level set of `field` inside `box` with settings.mesher: the same as
// calling marching_cubes(), sparse_marching_cubes() or vdb_mesh() directly, whose headers
// state the guarantees and what each throws. Throws InputError as they do, and for a
// Mesher value that names no mesher.
Mesh mesh(const BatchField& field, const Box& box, const MeshSettings& settings);

// One mesher of the registry: its value, the name --mesher takes and one line of help.
struct MesherInfo {
    Mesher mesher;
    std::string_view name;
    std::string_view help;
    Mesh (*run)(const BatchField&, const Box&, const MeshSettings&);
};

// Every mesher, the default (MeshSettings{}.mesher) first, and their names in that order.
std::span<const MesherInfo> meshers();
std::span<const std::string_view> mesher_names();

// "sparse", "dense" or "vdb"; nullopt for any other name.
std::optional<Mesher> mesher_from_name(std::string_view name);

// The name mesher_from_name() takes; empty for a value that names no mesher.
std::string_view mesher_name(Mesher mesher);

}  // namespace sylva
