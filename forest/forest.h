// `sylva forest`: planting a ground area (ground.h) with a few species. Liebemann's (2017) outlook:
// generate a limited number of plants and spread them so nobody notices they repeat.
//
//  1. Where: Poisson disk points (poisson_disk.h) at least `spacing` apart over the forest
//     polygons, thinned at random to a density or a tree count. A layout plan
//     (LayoutPlanting) adds orchard rows (orchard.h) and solitary trees on meadows.
//  2. Which species: one 2D fbm noise field per species (core/noise.h) plus a bias from its
//     weight; each tree takes the species whose field is highest there, so like stands with
//     like in patches about `stand_size` meters across, and the biases are tuned so each
//     species gets its weight's share of the trees.
//  3. Which tree: K unique variants per species (variation.h seeds and jitter; ages spread
//     over [min_age, 1] times the template's `age` when it has one), each tree one of them
//     at random, avoiding the variant of its nearest same-species neighbour, turned about
//     its axis at random and scaled by 1 +- scale_jitter.
//  4. Output: the variants (generated in parallel with oneTBB) once in one glb scene
//     (forest_scene.h), and a placement list engines can import, CSV and JSON.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/cancel.h"
#include "core/tree_template.h"
#include "export/export_tree.h"
#include "forest/forest_scene.h"
#include "forest/ground.h"
#include "forest/orchard.h"
#include "tree/cost.h"
#include "tree/pipeline.h"

namespace sylva::forest {

struct Species {
    TreeTemplate tree;  // parameters as configured; its seed is ignored
    double weight = 1.0;
    // Which polygons it plants: "forest" (and a layout's meadows) or "orchard".
    std::string cls{kForestClass};
};

inline constexpr std::string_view kOrchardClass = "orchard";
inline constexpr std::string_view kMeadowClass = "meadow";

// What planting a layout plan (`sylva forest --layout`) adds to a ground: "orchard" polygons
// get rows of the orchard species (orchard.h), one species per polygon drawn by weight;
// "meadow" polygons get solitary trees of the forest species at `meadow_density` trees per
// hectare (0: none), at least 3 x spacing apart; "path" and other classes stay empty.
struct LayoutPlanting {
    OrchardSettings orchard;
    double meadow_density = 0.0;
};

struct ForestSettings {
    Ground ground = rectangle_ground(100.0, 100.0);
    std::vector<Species> species;
    std::optional<LayoutPlanting> layout;  // none: only "forest" polygons are planted
    std::size_t variants = 8;              // K unique variants per species
    std::uint64_t seed = 1;
    double spacing = 4.0;  // minimum distance between trunks, meters
    // At most one of these; neither: as dense as the spacing allows.
    std::optional<double> density;     // trees per hectare
    std::optional<std::size_t> trees;  // this many trees (fewer if the spacing cannot fit them)
    double stand_size = 40.0;          // meters across a patch of one species
    double jitter = 0.1;               // varied_params() of each variant
    double min_age = 0.6;              // variants' ages: [min_age, 1] x the template's age
    double scale_jitter = 0.15;        // tree scale in [1 - s, 1 + s]
    FinishSettings finish;             // budget and LOD per variant
    MeshOptions mesh;
    ExportOptions export_options;
    Instancing instancing = Instancing::Nodes;
    // Called after each variant is generated (from a worker thread, serialised): done, total.
    std::function<void(std::size_t, std::size_t)> progress;
    CancelFlag cancel = nullptr;
};

struct Variant {
    std::size_t species = 0;
    std::size_t index = 0;  // within its species
    std::string name;       // "<template>_v<index>"
    std::uint64_t seed = 0;
    double age = 1.0;
    TreeParams params;
};

// One tree: a row of the placement list. Position in glTF axes (Y up, ground at y = 0, map
// (x, y) at (x, 0, -y)).
struct Placement {
    std::size_t species = 0;
    std::size_t variant = 0;  // index into ForestPlan::variants
    glm::dvec3 position{0.0};
    double yaw_degrees = 0.0;
    double scale = 1.0;
    double age = 1.0;
    std::string cls{kForestClass};  // the class of the polygon it stands in
};

struct ForestPlan {
    // Species by species, K each; none for a species with nothing to plant (an orchard
    // species without orchard polygons, forest species on a plan without forest or meadows).
    std::vector<Variant> variants;
    std::vector<Placement> placements;
};

// Everything but the trees' geometry: fast and deterministic for the settings. Trees come
// in this order: forest, orchard rows (polygon by polygon), meadow. --density and --trees
// apply to the forest polygons only. Throws InputError for no species, a weight that is
// not positive, bad spacing, density, tree count or K, an age the template cannot take, a
// ground with nothing to plant, and more than kMaxForestTrees estimated (naming the figure,
// before any tree is placed).
ForestPlan plan_forest(const ForestSettings& settings);

// At most this many trees in a forest, every class together.
inline constexpr double kMaxForestTrees = 1e6;

// How many trees the settings may plant, every class together, before any is placed: the
// densest disk packing over the forest and meadow boxes, thinned to --trees or --density,
// plus every orchard lattice point. An upper bound, in doubles (never an overflowed count).
// Throws InputError for bad orchard spacings.
double estimated_trees(const ForestSettings& settings);

// The whole job before any of it is made: every variant of every species (tree/cost.h's
// many_trees_cost at the finish budget) and the placements of estimated_trees().
Cost estimate_forest_cost(const ForestSettings& settings);

struct ForestTimes {
    double plan_ms = 0, variants_ms = 0, write_ms = 0;
};

struct ForestResult {
    ForestPlan plan;
    std::vector<std::size_t> variant_triangles;  // finest level, every part
    std::vector<std::filesystem::path> files;
    ForestTimes times;
};

// `<stem>.placements.csv` and `<stem>.placements.json` beside the scene.
std::filesystem::path placements_csv_path(const std::filesystem::path& glb);
std::filesystem::path placements_json_path(const std::filesystem::path& glb);

// Plans, generates the variants and writes the scene `glb` and the placement lists, all or
// nothing (core/file_set.h). CSV columns:
// index,species,variant,x,y,z,yaw_degrees,scale,age,class (species: the template name,
// variant: its name, class: the polygon's). JSON: {"species": [{"name", "weight", "class"}],
// "variants": [{"name", "species", "seed", "age", "triangles"}], "placements": [{"species",
// "variant", "position": [x, y, z], "yaw_degrees", "scale", "age", "class"}]}. The folder
// of `glb` is made (and the three targets checked) before any work: a file, device or an
// unwritable folder on the way is an IoError naming it, and a folder made for a forest that
// then fails is removed again.
// Throws InputError, IoError, Cancelled.
ForestResult plant_forest(const ForestSettings& settings, const std::filesystem::path& glb);

}  // namespace sylva::forest
