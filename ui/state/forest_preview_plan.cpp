#include "ui/state/forest_preview_plan.h"

#include <algorithm>
#include <glm/common.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/mat4x4.hpp>

#include "export/export_tree.h"
#include "tree/pipeline.h"

namespace sylva::studio {

forest::ForestSettings forest_preview_settings(const TreeTemplate& tree,
                                               const ForestPreviewOptions& options,
                                               const ForestPreviewPlan& plan) {
    const double size =
        std::clamp(static_cast<double>(options.size), static_cast<double>(kForestPreviewMinSize),
                   static_cast<double>(kForestPreviewMaxSize));
    forest::ForestSettings s;  // spacing, density and jitters: `sylva forest`'s defaults
    s.ground = forest::rectangle_ground(size, size);
    s.species.push_back({tree, 1.0, std::string(forest::kForestClass)});
    if (plan.ground && !plan.ground->polygons.empty()) {
        glm::dvec2 lo(1e300), hi(-1e300);
        for (const forest::GroundPolygon& p : plan.ground->polygons)
            for (const glm::dvec2& q : p.points) lo = glm::min(lo, q), hi = glm::max(hi, q);
        const double scale =
            std::min(kForestPreviewPlanScale,
                     kForestPreviewPlanMaxSide / std::max({hi.x - lo.x, hi.y - lo.y, 1e-9}));
        s.ground = *plan.ground;
        for (forest::GroundPolygon& p : s.ground.polygons)
            for (glm::dvec2& q : p.points) q = (q - 0.5 * (lo + hi)) * scale;
        s.layout = forest::LayoutPlanting{};
        s.species.push_back({tree, 1.0, std::string(forest::kOrchardClass)});
    }
    s.variants =
        static_cast<std::size_t>(std::clamp(options.variants, 1, kForestPreviewMaxVariants));
    s.seed = tree.params.seed;
    s.finish.budget.total = kForestPreviewBudget;
    return s;
}

forest::ForestPlan plan_forest_preview(const TreeTemplate& tree,
                                       const ForestPreviewOptions& options) {
    return forest::plan_forest(forest_preview_settings(tree, options));
}

void append_transformed(Mesh& into, const Mesh& part, const glm::mat4& model) {
    const auto base = static_cast<std::uint32_t>(into.positions.size());
    for (const glm::vec3& p : part.positions)
        into.positions.push_back(glm::vec3(model * glm::vec4(p, 1.0f)));
    for (const std::array<std::uint32_t, 3>& t : part.triangles)
        into.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

ForestPreviewMeshes make_forest_preview(const TreeTemplate& tree,
                                        const ForestPreviewOptions& options, CancelFlag cancel,
                                        const std::function<void(int, int)>& progress,
                                        const ForestPreviewPlan& ground_plan) {
    const forest::ForestSettings settings = forest_preview_settings(tree, options, ground_plan);
    const forest::ForestPlan plan = forest::plan_forest(settings);
    MeshOptions mesh;
    mesh.budget = game_budget(settings.finish);
    mesh.cancel = cancel;
    mesh.threads = 1;  // the UI thread and the tree's own generation keep the other cores
    FinishSettings finish = settings.finish;
    finish.decimate.cancel = cancel;

    struct Parts {
        Mesh trunk, crown, leaves;
    };
    std::vector<Parts> variants;
    const int total = static_cast<int>(plan.variants.size());
    for (const forest::Variant& v : plan.variants) {
        TreeTemplate t = tree;
        t.params = v.params;
        const Tree generated = generate_tree(t, mesh);
        const FinishedTree finished = finish_tree(generated, finish);
        variants.push_back(
            {finished.levels[0].trunk, finished.levels[0].crown, finished.levels[0].leaves});
        if (progress) progress(static_cast<int>(variants.size()), total);
    }
    throw_if_cancelled(cancel);

    ForestPreviewMeshes out;
    out.variants = variants.size();
    for (const forest::Placement& p : plan.placements) {
        const Parts& parts = variants[p.variant];
        glm::mat4 model = glm::translate(glm::mat4(1.0f), glm::vec3(p.position));
        model = glm::rotate(model, glm::radians(static_cast<float>(p.yaw_degrees)),
                            glm::vec3(0.0f, 1.0f, 0.0f));
        model = glm::scale(model, glm::vec3(static_cast<float>(p.scale)));
        append_transformed(out.trunk, parts.trunk, model);
        append_transformed(out.crown, parts.crown, model);
        append_transformed(out.leaves, parts.leaves, model);
        ++out.trees;
    }
    bool any = false;
    for (const Mesh* m : {&out.trunk, &out.crown, &out.leaves})
        for (const glm::vec3& p : m->positions) {
            out.low = any ? glm::min(out.low, p) : p;
            out.high = any ? glm::max(out.high, p) : p;
            any = true;
        }
    return out;
}

}  // namespace sylva::studio
