// The studio's forest preview, headless part: a small square of forest planted with the
// edited template as its only species (forest/forest.h: Poisson disk spacing, K variants
// from variation.h, yaw and scale per tree), each variant at a low triangle budget, and
// every planted tree merged into one mesh per part so the viewport draws it with three
// draw calls. ui/forest_preview.h runs it on a worker and draws it.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <memory>

#include "core/cancel.h"
#include "core/mesh.h"
#include "core/tree_template.h"
#include "forest/forest.h"

namespace sylva::studio {

struct ForestPreviewOptions {
    float size = 40.0f;  // meters, each side of the square (the slider's range: 20-100)
    int variants = 4;    // K unique variants of the template
};

// A ground plan planted instead of the square: a 2D layout's polygons with their planting
// classes (layout/), at kForestPreviewPlanScale meters per unit (the shipped examples' 10-unit
// plots become 30 m plots, as sylva forest --layout-scale 3 plants them), scaled down when its
// longer side would pass kForestPreviewPlanMaxSide. `id` tells plans apart without comparing
// them (0: none).
struct ForestPreviewPlan {
    std::shared_ptr<const forest::Ground> ground;
    std::uint64_t id = 0;
};

inline constexpr float kForestPreviewMinSize = 20.0f, kForestPreviewMaxSize = 100.0f;
inline constexpr double kForestPreviewPlanScale = 3.0, kForestPreviewPlanMaxSide = 240.0;
inline constexpr int kForestPreviewMaxVariants = 8;
// Trunk + crown triangles per variant: enough to read the shape from the distance a square
// of forest is framed at, cheap enough to make K of them in a few seconds.
inline constexpr std::size_t kForestPreviewBudget = 300;

// `sylva forest`'s settings for the preview: a size x size square centred on the origin (or
// the plan, centred and planted as `sylva forest --layout` plants one, with `tree` for its
// orchards too), `tree` as the only species, its seed as the forest's,
// spacing, density and jitters at `sylva forest`'s defaults, and the low budget. Size and K
// are clamped to the slider's ranges.
forest::ForestSettings forest_preview_settings(const TreeTemplate& tree,
                                               const ForestPreviewOptions& options,
                                               const ForestPreviewPlan& plan = {});

// Where the trees stand and which variant each is (forest::plan_forest: fast, deterministic
// for the template's seed). Throws InputError as plan_forest does.
forest::ForestPlan plan_forest_preview(const TreeTemplate& tree,
                                       const ForestPreviewOptions& options);

struct ForestPreviewMeshes {
    Mesh trunk, crown, leaves;  // every planted tree, placed, turned and scaled
    std::size_t trees = 0;
    std::size_t variants = 0;
    glm::vec3 low{0.0f}, high{0.0f};  // the bounds of all parts
};

// Plans, generates the variants one after another (progress(done, total) after each) and
// merges the placed instances. Throws InputError, Cancelled once `cancel` is set.
ForestPreviewMeshes make_forest_preview(const TreeTemplate& tree,
                                        const ForestPreviewOptions& options, CancelFlag cancel,
                                        const std::function<void(int, int)>& progress = {},
                                        const ForestPreviewPlan& ground_plan = {});

// Appends `part` to `into` moved by `model` (a rotation, uniform scale and translation, so
// windings stay counter-clockwise).
void append_transformed(Mesh& into, const Mesh& part, const glm::mat4& model);

}  // namespace sylva::studio
