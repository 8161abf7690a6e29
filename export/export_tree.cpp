#include "export/export_tree.h"

#include <map>

#include "core/data_paths.h"
#include "core/file_set.h"
#include "export/collision.h"
#include "export/engine_kit.h"
#include "export/impostor_level.h"
#include "export/index_colors.h"
#include "export/leaf_atlas.h"
#include "export/organ_attributes.h"
#include "export/palette.h"
#include "export/part_attributes.h"

namespace sylva {

std::vector<NamedMesh> tree_parts(const Mesh& trunk, const Mesh& crown, const Mesh& leaves,
                                  const PartColors& colors, std::string_view material_prefix) {
    std::vector<NamedMesh> parts;
    if (!trunk.triangles.empty()) parts.push_back({"trunk", &trunk, colors.trunk, true});
    if (!crown.triangles.empty()) parts.push_back({"crown", &crown, colors.crown, true});
    if (!leaves.triangles.empty()) parts.push_back({"leaves", &leaves, colors.leaves, false});
    if (!material_prefix.empty())
        for (NamedMesh& part : parts)
            part.material = std::string(material_prefix) + "_" + part.name;
    return parts;
}

std::string material_prefix(std::string_view template_name, std::uint64_t seed) {
    return safe_file_name(template_name) + "_s" + std::to_string(seed);
}

SolidParts finest_solids(const Tree& tree, const FinishedTree& finished) {
    if (finished.levels.empty()) return {tree.trunk, tree.crown};
    return {finished.levels[0].trunk, finished.levels[0].crown};
}

std::size_t game_budget(const FinishSettings& settings) {
    const TreeBudget& b = settings.budget;
    if (settings.lod) return b.total > 0 ? b.total : kDefaultTriangleBudget;
    if (b.trunk && b.crown) return *b.trunk + *b.crown;
    return b.total;
}

FinishedTree finish_tree(const Tree& tree, const FinishSettings& settings,
                         std::optional<ReducedTree> level0) {
    FinishedTree out;
    const TreeBudget& budget = settings.budget;
    if (settings.lod) {
        const std::size_t finest = budget.total > 0 ? budget.total : kDefaultTriangleBudget;
        out.lod = true;
        TreeBudget first = budget;
        first.total = finest;
        const std::vector<TreeBudget> budgets = lod_budgets(first, settings.lod_levels);
        for (const TreeBudget& b : budgets) {
            out.budgets.push_back(b.total);
            out.leaf_budgets.push_back(leaf_budget(b));
        }
        out.levels = make_lod_chain(tree, budgets, settings.decimate, std::move(level0));
    } else if (budget.total > 0 || budget.trunk || budget.crown || budget.leaves) {
        out.budgets = {budget.total};
        out.leaf_budgets = {leaf_budget(budget)};
        out.levels.push_back(reduce_tree(tree, budget, settings.decimate));
    }
    out.organs = finished_organs(tree, out.leaf_budgets);
    return out;
}

std::vector<OrganMesh> finished_organs(const Tree& tree,
                                       const std::vector<std::size_t>& leaf_budgets) {
    // Organs are whole pieces with a budget of their own, the leaves' (docs/lowpoly.md).
    std::vector<OrganMesh> out;
    if (!tree.organs.empty())
        for (const std::size_t leaves : leaf_budgets)
            out.push_back(thin_organs(tree.organs, leaves));
    return out;
}

namespace {

// The organs part, when there are organs: open (double-sided), the leaves' colour.
void add_organs(ModelParts& parts, const OrganMesh& organs, const PartColors& colors,
                std::string_view material_prefix) {
    if (organs.empty()) return;
    parts.push_back({"organs", &organs.mesh, colors.leaves, false});
    if (!material_prefix.empty()) parts.back().material = std::string(material_prefix) + "_organs";
}

// The OrganMesh whose mesh `mesh` is: the tree's or a level's; null for another part.
const OrganMesh* organs_of(const Mesh* mesh, const Tree& tree, const FinishedTree& finished) {
    if (mesh == &tree.organs.mesh) return &tree.organs;
    for (const OrganMesh& level : finished.organs)
        if (mesh == &level.mesh) return &level;
    return nullptr;
}

}  // namespace

std::vector<ModelParts> finished_parts(const Tree& tree, const FinishedTree& finished,
                                       const PartColors& colors, std::string_view material_prefix) {
    if (finished.levels.empty()) {
        ModelParts parts = tree_parts(tree.trunk, tree.crown, tree.leaves, colors, material_prefix);
        add_organs(parts, tree.organs, colors, material_prefix);
        return {parts};
    }
    std::vector<ModelParts> levels;
    for (std::size_t i = 0; i < finished.levels.size(); ++i) {
        const ReducedTree& level = finished.levels[i];
        levels.push_back(
            tree_parts(level.trunk, level.crown, level.leaves, colors, material_prefix));
        if (i < finished.organs.size())
            add_organs(levels.back(), finished.organs[i], colors, material_prefix);
    }
    return levels;
}

EngineModel engine_model(const Tree& tree, const FinishedTree& finished, const PartColors& colors,
                         const ExportOptions& options) {
    EngineModel model;
    model.levels = finished_parts(tree, finished, colors, options.material_prefix);
    const EngineSettings& engine = options.engine;
    // One frame for all levels, so a level's wind and tint match the next one's.
    const TreeFrame frame = tree_frame(tree.trunk, tree.crown, tree.leaves);
    // A mesh in several levels (unthinned leaves) gets its attributes once.
    // With a palette a part may have become white (its tint then carries the colours).
    std::map<const Mesh*, std::pair<const PartAttributes*, glm::vec3>> done;
    for (ModelParts& level : model.levels)
        for (NamedMesh& part : level) {
            const Mesh& mesh = *part.mesh;
            if (auto found = done.find(&mesh); found != done.end()) {
                part.attributes = found->second.first;
                part.color = found->second.second;
                continue;
            }
            const OrganMesh* organs = organs_of(&mesh, tree, finished);
            if (part.name == "trunk")
                model.attributes.push_back(trunk_attributes(mesh, tree.skeleton, frame, engine));
            else if (part.name == "crown")
                model.attributes.push_back(crown_attributes(mesh, frame, engine));
            else if (organs)
                model.attributes.push_back(organ_attributes(*organs, frame, engine));
            else
                model.attributes.push_back(leaf_attributes(mesh, frame, engine));
            // The grammar's colour indices, with a palette (export/index_colors.h).
            PartAttributes& attributes = model.attributes.back();
            if (part.name == "trunk")
                color_trunk_by_index(part, attributes, tree.skeleton, colors.palette);
            else if (organs)
                color_organs_by_index(part, attributes, *organs, colors.palette);
            else if (part.name == "leaves")
                color_leaves_by_index(part, attributes, tree.skeleton, colors.palette);
            if (engine.palette) use_palette(model.attributes.back(), mesh, part.name);
            part.attributes = &model.attributes.back();
            done[&mesh] = {part.attributes, part.color};
        }
    // Textured leaf cards: one texture of leaves for every level's cards.
    if (tree.leaf_style == LeafStyle::Textured && !finished.levels.empty()) {
        model.textures.push_back(leaf_atlas(tree.leaf_shape, colors.leaves));
        for (ModelParts& level : model.levels)
            for (NamedMesh& part : level)
                if (part.name == "leaves") part.textures = &model.textures.back();
    }
    const bool collision =
        engine.collision.value_or(profile_info(options.profile).collision_by_default);
    if (collision && !model.levels.empty()) {
        // From the finest solids: the shapes a player bumps into.
        const SolidParts solids = finest_solids(tree, finished);
        for (Mesh& hull : collision_hulls(solids.trunk, solids.crown, tree.skeleton)) {
            model.hulls.push_back(std::move(hull));
            const std::string name =
                collision_name(options.profile, options.model_name, model.hulls.size() - 1,
                               model.levels.size() > 1);
            model.levels[0].push_back(
                {name, &model.hulls.back(), glm::vec3(1.0f), true, nullptr, true});
        }
    }
    if (options.impostor.kind != ImpostorKind::None && !model.levels.empty())
        add_far_levels(model, options);
    return model;
}

std::vector<BakePart> bake_parts(const ModelParts& level) {
    std::vector<BakePart> parts;
    for (const NamedMesh& part : level) {
        if (part.collision || !part.mesh || part.mesh->triangles.empty()) continue;
        const std::vector<glm::vec3>* tint =
            part.attributes && !part.attributes->tint.empty() ? &part.attributes->tint : nullptr;
        parts.push_back({part.mesh, part.color, tint, !part.closed});
    }
    return parts;
}

std::vector<std::filesystem::path> write_tree(const std::filesystem::path& path, const Tree& tree,
                                              const FinishedTree& finished,
                                              const PartColors& colors,
                                              const ExportOptions& options,
                                              const ExportFormat* format,
                                              std::string* impostor_layout) {
    ExportOptions with_palette = options;
    if (options.engine.palette) with_palette.palette_png = palette_png(colors);
    std::function<void(FileSet&)> kit;
    if (!options.engine_kit.empty())
        kit = [&](FileSet& files) { add_engine_kit(files, options.engine_kit, options.profile); };
    const EngineModel model = engine_model(tree, finished, colors, options);
    if (impostor_layout) *impostor_layout = model.atlas ? model.atlas->layout : std::string();
    if (model.atlas || model.billboard)
        with_palette.sidecars.push_back(
            {"_impostor.json", far_levels_layout(model, output_target(path),
                                                 format ? format : format_from_extension(path))});
    return write_lod_chain(path, model.levels, with_palette, format, kit);
}

}  // namespace sylva
