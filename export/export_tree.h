// Finishing a tree and writing it: the one path from a generated tree to files, used by
// the CLI's `export` and the studio's Export button alike. Trunk and crown are reduced to
// the budget (or to a LOD chain of budgets), the parts named and coloured, and the result
// written in the format the path's extension (or the caller) names.
#pragma once

#include <deque>
#include <filesystem>
#include <optional>
#include <vector>

#include "export/export.h"
#include "impostor/impostor_bake.h"
#include "tree/lowpoly_tree.h"

namespace sylva {

// The parts as the exporters want them: trunk, crown and leaves with the template's
// colours, leaves marked open; empty parts left out; materials `<material_prefix>_<part>`
// (the part names when the prefix is empty). The meshes must outlive the result.
std::vector<NamedMesh> tree_parts(const Mesh& trunk, const Mesh& crown, const Mesh& leaves,
                                  const PartColors& colors, std::string_view material_prefix = {});

// The material prefix of one tree: its template's name (made a safe file name) and its
// seed, `oak_s7`: the same tree always gets the same names, two templates or two seeds
// never share one.
std::string material_prefix(std::string_view template_name, std::uint64_t seed);

struct FinishSettings {
    // Trunk + crown triangles and the leaves' own share (TreeBudget); total 0 with no part
    // or leaf budget keeps every triangle and every leaf.
    TreeBudget budget;
    // LOD0..LOD<lod_levels-1> with budgets total, total/2, ... and leaf budgets halving
    // alike (lod_budgets()); with a total of 0 the chain starts at kDefaultTriangleBudget.
    bool lod = false;
    std::size_t lod_levels = 4;
    // Progress and cancel of the reductions (its max_triangles is ignored).
    DecimateSettings decimate;
};

// What a tree becomes for export: one reduced tree per level (none: the marching-cubes
// meshes as they are), with the budget each level was reduced to.
struct FinishedTree {
    std::vector<ReducedTree> levels;
    std::vector<std::size_t> budgets;       // trunk + crown, per level
    std::vector<std::size_t> leaf_budgets;  // per level; SIZE_MAX: every leaf
    bool lod = false;  // levels are a LOD chain (the writers add the _LOD<i> suffixes)
    // Per level, the tree's organs thinned to the level's leaf budget (thin_organs(),
    // docs/lowpoly.md "Organs"); empty when the tree has none.
    std::vector<OrganMesh> organs;
};

// Trunk and crown of the finest level: reduced, or the tree's own when not reduced. What
// the studio shows, the status lines count and fidelity is measured on.
struct SolidParts {
    const Mesh& trunk;
    const Mesh& crown;
};
SolidParts finest_solids(const Tree& tree, const FinishedTree& finished);

// The trunk + crown triangles of the finest level `settings` make (0: not reduced): what
// generate_tree's MeshOptions::budget should be for this export.
std::size_t game_budget(const FinishSettings& settings);

// The tree's organs thinned to each of `leaf_budgets` (FinishedTree::organs); empty when
// the tree has none.
std::vector<OrganMesh> finished_organs(const Tree& tree,
                                       const std::vector<std::size_t>& leaf_budgets);

// Reduces the tree as `settings` say. Throws what reduce_tree() throws.
// With settings.lod, `level0` (if given) is the chain's level 0 as made before: what
// finish_tree() without lod returned as its only level (make_lod_chain()).
FinishedTree finish_tree(const Tree& tree, const FinishSettings& settings,
                         std::optional<ReducedTree> level0 = std::nullopt);

// The parts of each level as the writers want them: trunk, crown and leaves of that level
// (or the tree's own when not reduced), with the template's colours, named `trunk`,
// `crown` and `leaves` (a chain's writer adds `_LOD<i>` to node and group names, never to
// materials), materials as tree_parts() names them, and `organs` when the tree has any.
// The meshes stay owned by `tree` and `finished`.
std::vector<ModelParts> finished_parts(const Tree& tree, const FinishedTree& finished,
                                       const PartColors& colors,
                                       std::string_view material_prefix = {});

// The finished parts dressed for engines as options.engine and options.profile say: every
// part with its UVs, tint and wind (export/part_attributes.h), and with collision on, the
// collision hulls (export/collision.h) in level 0, named for the profile after the mesh
// they belong to (the model, or its `_LOD0` in a chain), materials named with
// options.material_prefix. Owns what the parts point to (besides the meshes owned by `tree`
// and `finished`); moving it keeps them. With options.impostor, the far levels
// (export/impostor_level.h) come last: a billboard level and/or an octahedral impostor
// level, baked from level 0's parts.
struct EngineModel {
    std::vector<ModelParts> levels;
    std::deque<PartAttributes> attributes;
    std::deque<Mesh> hulls;
    std::deque<Mesh> far_meshes;        // the impostor's and the billboard's quads
    std::deque<PartTextures> textures;  // their images
    // What the far levels were baked as (without pixels), for the layout JSON.
    std::optional<ImpostorAtlas> atlas;
    std::optional<BillboardTexture> billboard;
};
EngineModel engine_model(const Tree& tree, const FinishedTree& finished, const PartColors& colors,
                         const ExportOptions& options);

// What the impostor bakes of a level: its parts but collision, with their colours, tints
// (attributes) and sides.
std::vector<BakePart> bake_parts(const ModelParts& level);

// Writes engine_model() of the finished tree to `path` (format: given, or from the
// extension), and with options.engine_kit the profile's import kit there, with
// options.impostor the layout JSON `<stem>_impostor.json` beside it, all in one transaction.
// Returns every file written; `impostor_layout`, when given, gets the octahedral atlas's
// layout line (what an automatic layout chose and why; empty otherwise). Throws InputError for
// an unknown extension, IoError when a file cannot be written.
std::vector<std::filesystem::path> write_tree(const std::filesystem::path& path, const Tree& tree,
                                              const FinishedTree& finished,
                                              const PartColors& colors,
                                              const ExportOptions& options = {},
                                              const ExportFormat* format = nullptr,
                                              std::string* impostor_layout = nullptr);

}  // namespace sylva
