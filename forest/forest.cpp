#include "forest/forest.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/color_variation.h"
#include "core/errors.h"
#include "core/file_set.h"
#include "core/noise.h"
#include "core/output_folder.h"
#include "core/random.h"
#include "core/stopwatch.h"
#include "forest/poisson_disk.h"
#include "forest/variant_impostor.h"
#include "forest/variation.h"
#include "tree/parameters.h"

namespace sylva::forest {
namespace {

// Streams of the forest's seed, so each decision draws from its own numbers.
enum Stream : std::uint64_t {
    kPoints = 1,
    kThinning,
    kTrees,
    kMeadow,
    kStands = 100,
    kSpecies = 1000,
    kOrchards = 1u << 20,  // + polygon index
};

void validate(const ForestSettings& s) {
    if (s.species.empty()) throw InputError("a forest needs at least one species");
    std::map<std::pair<std::string, std::string>, int> names;
    for (const Species& sp : s.species) {
        if (!(sp.weight > 0.0) || !std::isfinite(sp.weight))
            throw InputError("species '" + sp.tree.name + "': the weight must be positive, not " +
                             std::to_string(sp.weight));
        if (sp.cls != kForestClass && sp.cls != kOrchardClass)
            throw InputError("species '" + sp.tree.name +
                             "': class must be forest or orchard, not '" + sp.cls + "'");
        if (++names[{sp.cls, sp.tree.name}] > 1)
            throw InputError("species '" + sp.tree.name + "' is listed twice");
    }
    if (s.variants < 1 || s.variants > 1000)
        throw InputError("--variants must be 1 to 1000, not " + std::to_string(s.variants));
    if (!(s.spacing > 0.0) || !std::isfinite(s.spacing))
        throw InputError("--spacing must be a positive number of meters");
    if (s.density && s.trees) throw InputError("give either a density or a tree count, not both");
    if (s.density && !(*s.density > 0.0 && std::isfinite(*s.density)))
        throw InputError("--density must be a positive number of trees per hectare");
    if (!(s.stand_size > 0.0) || !std::isfinite(s.stand_size))
        throw InputError("--stand-size must be a positive number of meters");
    if (!(s.min_age >= 0.0 && s.min_age <= 1.0))
        throw InputError("--min-age must be from 0 to 1, not " + std::to_string(s.min_age));
    if (!(s.scale_jitter >= 0.0 && s.scale_jitter <= 0.9))
        throw InputError("--scale-jitter must be from 0 to 0.9, not " +
                         std::to_string(s.scale_jitter));
    if (s.layout &&
        (!(s.layout->meadow_density >= 0.0) || !std::isfinite(s.layout->meadow_density)))
        throw InputError("--meadow-density must be a number of trees per hectare, 0 or more");
}

bool has_class(const Ground& ground, std::string_view cls) {
    for (const GroundPolygon& polygon : ground.polygons)
        if (polygon.cls == cls && polygon.points.size() >= 3) return true;
    return false;
}

// Poisson disk points over the polygons of class `cls`, kept where `keep` says.
template <typename Keep>
std::vector<glm::dvec2> disk_points(const Ground& ground, std::string_view cls, double spacing,
                                    std::uint64_t seed, std::size_t* candidate_count, Keep keep) {
    std::vector<glm::dvec2> points;
    const GroundBounds bounds = forest_bounds(ground, cls);
    if (!(bounds.hi.x > bounds.lo.x && bounds.hi.y > bounds.lo.y)) return points;
    PoissonSettings poisson;
    poisson.min_distance = spacing;
    poisson.seed = seed;
    const std::vector<glm::dvec2> candidates = poisson_disk(bounds.lo, bounds.hi, poisson);
    for (glm::dvec2 p : candidates)
        if (keep(p)) points.push_back(p);
    if (candidate_count) *candidate_count = candidates.size();
    return points;
}

// A random subset of `target` points, in their order.
void thin(std::vector<glm::dvec2>& points, std::size_t target, std::uint64_t seed) {
    if (target >= points.size()) return;
    std::vector<std::size_t> order(points.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    Random random(seed);
    for (std::size_t i = order.size() - 1; i > 0; --i)
        std::swap(order[i], order[random.next() % (i + 1)]);
    order.resize(target);
    std::sort(order.begin(), order.end());
    std::vector<glm::dvec2> kept;
    for (std::size_t i : order) kept.push_back(points[i]);
    points = std::move(kept);
}

// Each point's species: the highest of the species' noise fields plus a bias, the biases
// tuned until every species has about its weight's share.
// `pool`: the indices of the species to pick from; returns indices into s.species.
std::vector<std::size_t> pick_species(const std::vector<glm::dvec2>& points,
                                      const ForestSettings& s,
                                      const std::vector<std::size_t>& pool) {
    const std::size_t n = points.size(), m = pool.size();
    std::vector<std::size_t> pick(n, m ? pool[0] : 0);
    if (m <= 1 || n == 0) return pick;
    std::vector<double> field(n * m);
    // Half a period of the first octave is a stand; a weak second octave frays its edges.
    const FbmSettings fbm_settings{2, 0.5 / s.stand_size, 0.35, 2.0};
    for (std::size_t k = 0; k < m; ++k) {
        const GradientNoise noise(variant_seed(s.seed, kStands + pool[k]));
        for (std::size_t i = 0; i < n; ++i)
            field[i * m + k] = fbm(noise, points[i].x, points[i].y, fbm_settings);
    }
    double total_weight = 0.0;
    for (std::size_t k : pool) total_weight += s.species[k].weight;
    // The fields' spread over a small area may be tiny, so the step shrinks geometrically
    // (from 0.5 to about 1e-4) rather than oscillating around the shares.
    std::vector<double> bias(m, 0.0);
    double step = 0.5;
    for (int round = 0; round < 120; ++round, step *= 0.93) {
        std::vector<std::size_t> count(m, 0);
        for (std::size_t i = 0; i < n; ++i) {
            std::size_t best = 0;
            for (std::size_t k = 1; k < m; ++k)
                if (field[i * m + k] + bias[k] > field[i * m + best] + bias[best]) best = k;
            pick[i] = best;
            ++count[best];
        }
        for (std::size_t k = 0; k < m; ++k)
            bias[k] += step * (s.species[pool[k]].weight / total_weight -
                               static_cast<double>(count[k]) / static_cast<double>(n));
    }
    for (std::size_t& p : pick) p = pool[p];
    return pick;
}

std::string format_row(std::size_t row, const std::string& species, const std::string& variant,
                       const Placement& p) {
    char line[256];
    std::snprintf(line, sizeof line, "%zu,%s,%s,%.4f,%.4f,%.4f,%.3f,%.5f,%.4f,%s\n", row,
                  species.c_str(), variant.c_str(), p.position.x, p.position.y, p.position.z,
                  p.yaw_degrees, p.scale, p.age, p.cls.c_str());
    return line;
}

}  // namespace

std::filesystem::path placements_csv_path(const std::filesystem::path& glb) {
    return glb.parent_path() / (glb.stem().string() + ".placements.csv");
}

std::filesystem::path placements_json_path(const std::filesystem::path& glb) {
    return glb.parent_path() / (glb.stem().string() + ".placements.json");
}

namespace {

// The densest disk packing of `spacing` over the box of the polygons of class `cls`.
double packed_trees(const Ground& ground, std::string_view cls, double spacing) {
    const GroundBounds box = forest_bounds(ground, cls);
    const glm::dvec2 size = box.hi - box.lo;
    if (!(size.x > 0.0 && size.y > 0.0)) return 0.0;
    return 1.2 * ((size.x + spacing) / spacing) * ((size.y + spacing) / spacing);
}

// Placements, their scene nodes and both lists, per tree.
constexpr double kBytesPerTree = 2000.0;
constexpr double kSecondsPerTree = 2.0e-5;

}  // namespace

double estimated_trees(const ForestSettings& s) {
    bool forest_species = false, orchard_species = false;
    for (const Species& sp : s.species)
        (sp.cls == kOrchardClass ? orchard_species : forest_species) = true;
    double trees = 0.0;
    if (forest_species) {
        double forest = packed_trees(s.ground, kForestClass, s.spacing);
        if (s.trees) forest = std::min(forest, static_cast<double>(*s.trees));
        if (s.density) {
            const GroundBounds box = forest_bounds(s.ground);
            const glm::dvec2 size = box.hi - box.lo;
            forest = std::min(forest, *s.density * size.x * size.y / 1e4);
        }
        trees += forest;
        if (s.layout && s.layout->meadow_density > 0.0)
            trees += packed_trees(s.ground, kMeadowClass, 3.0 * s.spacing);
    }
    if (s.layout && orchard_species)
        for (const GroundPolygon& polygon : s.ground.polygons)
            if (polygon.cls == kOrchardClass)
                trees += orchard_lattice_points(polygon, s.layout->orchard);
    return std::isnan(trees) ? std::numeric_limits<double>::infinity() : trees;
}

Cost estimate_forest_cost(const ForestSettings& s) {
    const std::size_t budget = game_budget(s.finish);
    Cost total;
    double peak = 0.0, kept = 0.0;  // one variant is made at a time; every one is kept
    for (const Species& sp : s.species) {
        const Cost each = estimate_cost(sp.tree, budget);
        const Cost variants = many_trees_cost(each, static_cast<double>(s.variants), budget);
        total.modules += variants.modules;
        total.segments += variants.segments;
        total.cells += variants.cells;
        total.seconds += variants.seconds;
        peak = std::max(peak, each.bytes);
        kept += variants.bytes - each.bytes;
    }
    const double trees = estimated_trees(s);
    total.bytes = peak + kept + kBytesPerTree * trees;
    total.seconds += kSecondsPerTree * trees;
    return total;
}

ForestPlan plan_forest(const ForestSettings& s) {
    validate(s);
    // Every class together, before any tree is placed: an orchard lattice of 1e-9 m spacing
    // would otherwise be walked point by point.
    const double trees = estimated_trees(s);
    if (!(trees <= kMaxForestTrees)) {
        char figure[160];
        std::snprintf(figure, sizeof figure,
                      "this ground and spacing would plant up to %.3g trees; the limit is %.0f",
                      trees, kMaxForestTrees);
        throw InputError(figure);
    }
    ForestPlan plan;
    const std::size_t k_count = s.variants;
    const bool layout = s.layout.has_value();
    const bool forest_area = has_class(s.ground, kForestClass);
    const bool meadow_trees =
        layout && s.layout->meadow_density > 0.0 && has_class(s.ground, kMeadowClass);
    const bool orchard_area = layout && has_class(s.ground, kOrchardClass);
    std::vector<std::size_t> forest_pool, orchard_pool;
    for (std::size_t sp = 0; sp < s.species.size(); ++sp)
        (s.species[sp].cls == kOrchardClass ? orchard_pool : forest_pool).push_back(sp);

    // The variants: K per species that plants something, ages spread over [min_age, 1].
    std::vector<std::size_t> first_variant(s.species.size(), 0);
    for (std::size_t sp = 0; sp < s.species.size(); ++sp) {
        const TreeTemplate& tree = s.species[sp].tree;
        first_variant[sp] = plan.variants.size();
        const bool orchard = s.species[sp].cls == kOrchardClass;
        if (orchard ? !orchard_area : layout && !(forest_area || meadow_trees)) continue;
        const std::uint64_t base = variant_seed(s.seed, kSpecies + sp);
        // The template's own age (--set age=0.5: a young forest) is the oldest variant's.
        const std::optional<double> template_age = get_param(tree.params, "age");
        for (std::size_t k = 0; k < k_count; ++k) {
            Variant v;
            v.species = sp;
            v.index = k;
            v.name = tree.name + (orchard ? "_orchard_v" : "_v") + std::to_string(k);
            v.seed = variant_seed(base, k);
            v.params = varied_params(tree.params, v.seed, s.jitter);
            if (template_age) {
                const double t =
                    k_count == 1 ? 1.0 : static_cast<double>(k) / static_cast<double>(k_count - 1);
                v.age = *template_age * (s.min_age + (1.0 - s.min_age) * t);
                set_param(v.params, "age", v.age);
            }
            plan.variants.push_back(std::move(v));
        }
    }

    // Where: Poisson disk over the forest's box, kept where trees may stand.
    const GroundBounds bounds = forest_bounds(s.ground);
    const bool forest_box = bounds.hi.x > bounds.lo.x && bounds.hi.y > bounds.lo.y;
    if (!forest_box && !layout) throw InputError("the ground has no forest polygon with an area");
    if (!forest_box && !orchard_area && !meadow_trees)
        throw InputError(
            "the layout has nothing to plant: no forest or orchard polygon (and no meadow "
            "with --meadow-density)");
    std::size_t candidates = 0;
    std::vector<glm::dvec2> points =
        forest_pool.empty()
            ? std::vector<glm::dvec2>{}
            : disk_points(s.ground, kForestClass, s.spacing, variant_seed(s.seed, kPoints),
                          &candidates, [&](glm::dvec2 p) { return plantable(s.ground, p); });

    // How many: a density over the plantable area (the box's share the candidates found), or
    // a count; a random subset keeps the spacing.
    std::size_t target = points.size();
    if (s.trees) target = std::min(target, *s.trees);
    if (s.density && candidates) {
        const glm::dvec2 size = bounds.hi - bounds.lo;
        const double area =
            size.x * size.y * static_cast<double>(points.size()) / static_cast<double>(candidates);
        const double wanted = *s.density * area / 1e4;  // compared before any cast
        if (wanted < static_cast<double>(target))
            target = static_cast<std::size_t>(std::llround(std::max(wanted, 0.0)));
    }
    thin(points, target, variant_seed(s.seed, kThinning));
    std::vector<std::size_t> species = pick_species(points, s, forest_pool);
    std::vector<std::string_view> classes(points.size(), kForestClass);

    // Orchards: rows, one species per polygon drawn by weight.
    if (orchard_area && !orchard_pool.empty()) {
        double total = 0.0;
        for (std::size_t sp : orchard_pool) total += s.species[sp].weight;
        for (std::size_t i = 0; i < s.ground.polygons.size(); ++i) {
            const GroundPolygon& polygon = s.ground.polygons[i];
            if (polygon.cls != kOrchardClass) continue;
            Random random(variant_seed(s.seed, kOrchards + i));
            double draw = random.uniform() * total;
            std::size_t pick = orchard_pool.back();
            for (std::size_t sp : orchard_pool) {
                if (draw < s.species[sp].weight) {
                    pick = sp;
                    break;
                }
                draw -= s.species[sp].weight;
            }
            for (glm::dvec2 p : orchard_rows(polygon, s.ground, s.layout->orchard)) {
                points.push_back(p);
                species.push_back(pick);
                classes.push_back(kOrchardClass);
            }
        }
    }

    // Meadows: a few solitary trees, far apart.
    if (meadow_trees && !forest_pool.empty()) {
        auto in_meadow = [&](glm::dvec2 p) {
            bool meadow = false;
            for (const GroundPolygon& polygon : s.ground.polygons) {
                if (polygon.points.size() < 3 || !contains(polygon, p)) continue;
                if (polygon.cls != kMeadowClass) return false;
                meadow = true;
            }
            return meadow;
        };
        std::size_t meadow_candidates = 0;
        std::vector<glm::dvec2> meadow =
            disk_points(s.ground, kMeadowClass, 3.0 * s.spacing, variant_seed(s.seed, kMeadow),
                        &meadow_candidates, in_meadow);
        const GroundBounds box = forest_bounds(s.ground, kMeadowClass);
        if (meadow_candidates) {
            const glm::dvec2 size = box.hi - box.lo;
            const double area = size.x * size.y * static_cast<double>(meadow.size()) /
                                static_cast<double>(meadow_candidates);
            const double wanted = std::clamp(s.layout->meadow_density * area / 1e4, 0.0,
                                             static_cast<double>(meadow.size()));
            thin(meadow, static_cast<std::size_t>(std::llround(wanted)),
                 variant_seed(s.seed, kMeadow + 1));
        }
        const std::vector<std::size_t> meadow_species = pick_species(meadow, s, forest_pool);
        for (std::size_t i = 0; i < meadow.size(); ++i) {
            points.push_back(meadow[i]);
            species.push_back(meadow_species[i]);
            classes.push_back(kMeadowClass);
        }
    }

    // Which variant, how turned and scaled.
    Random random(variant_seed(s.seed, kTrees));
    const double radius = 2.0 * s.spacing;  // neighbours whose variant a tree avoids
    std::map<std::pair<long, long>, std::vector<std::size_t>> grid;  // cell -> placements
    // Clamped before the cast: a ground far from the origin (1e300 m) would overflow a long.
    auto index = [&](double x) {
        return static_cast<long>(std::clamp(std::floor(x / radius), -1e15, 1e15));
    };
    auto cell = [&](glm::dvec2 p) { return std::pair<long, long>(index(p.x), index(p.y)); };
    for (std::size_t i = 0; i < points.size(); ++i) {
        const glm::dvec2 p = points[i];
        std::vector<bool> taken(k_count, false);
        const auto [cx, cy] = cell(p);
        for (long y = cy - 1; y <= cy + 1; ++y)
            for (long x = cx - 1; x <= cx + 1; ++x) {
                auto found = grid.find({x, y});
                if (found == grid.end()) continue;
                for (std::size_t q : found->second) {
                    const Placement& other = plan.placements[q];
                    const glm::dvec2 o(other.position.x, -other.position.z);
                    if (other.species == species[i] && glm::length(o - p) < radius)
                        taken[plan.variants[other.variant].index] = true;
                }
            }
        std::vector<std::size_t> free;
        for (std::size_t k = 0; k < k_count; ++k)
            if (!taken[k]) free.push_back(k);
        const std::uint64_t draw = random.next();
        const std::size_t k = free.empty() ? draw % k_count : free[draw % free.size()];
        Placement placement;
        placement.species = species[i];
        placement.variant = first_variant[species[i]] + k;
        placement.cls = std::string(classes[i]);
        placement.position = {p.x, 0.0, -p.y};
        placement.yaw_degrees = 360.0 * random.uniform();
        placement.scale = 1.0 + s.scale_jitter * (2.0 * random.uniform() - 1.0);
        placement.age = plan.variants[placement.variant].age;
        grid[cell(p)].push_back(plan.placements.size());
        plan.placements.push_back(placement);
    }
    return plan;
}

ForestResult plant_forest(const ForestSettings& s, const std::filesystem::path& glb) {
    // Where the files go, made or refused before any tree is.
    OutputFolder folder(glb.parent_path());
    for (const std::filesystem::path& file :
         {glb, placements_csv_path(glb), placements_json_path(glb)})
        output_target(file);
    ForestResult result;
    Stopwatch clock;
    result.plan = plan_forest(s);
    result.times.plan_ms = clock.lap_ms();
    const ForestPlan& plan = result.plan;

    // The unique variants: independent trees, generated in parallel.
    MeshOptions mesh = s.mesh;
    mesh.budget = game_budget(s.finish);
    mesh.cancel = s.cancel;
    mesh.progress = nullptr;
    FinishSettings finish = s.finish;
    finish.decimate.cancel = s.cancel;
    struct Generated {
        Tree tree;
        FinishedTree finished;
    };
    std::vector<std::unique_ptr<Generated>> generated(plan.variants.size());
    std::atomic<std::size_t> done{0};
    std::mutex progress_mutex;
    tbb::parallel_for(std::size_t{0}, plan.variants.size(), [&](std::size_t v) {
        TreeTemplate tree = s.species[plan.variants[v].species].tree;
        tree.params = plan.variants[v].params;
        auto g = std::make_unique<Generated>();
        g->tree = generate_tree(tree, mesh);
        g->finished = finish_tree(g->tree, finish);
        generated[v] = std::move(g);
        const std::size_t n = ++done;
        if (s.progress) {
            std::lock_guard lock(progress_mutex);
            s.progress(n, plan.variants.size());
        }
    });
    throw_if_cancelled(s.cancel);
    result.times.variants_ms = clock.lap_ms();

    std::vector<SceneVariant> scene_variants;
    // Own the far levels' quads and textures (one impostor bake per variant) until written.
    std::vector<EngineModel> variant_models(plan.variants.size());
    tbb::parallel_for(std::size_t{0}, plan.variants.size(), [&](std::size_t v) {
        TreeTemplate tree = s.species[plan.variants[v].species].tree;
        tree.params = plan.variants[v].params;
        variant_models[v] =
            variant_model_levels(generated[v]->tree, generated[v]->finished, tree_colors(tree),
                                 s.export_options, plan.variants[v].name);
    });
    for (std::size_t v = 0; v < plan.variants.size(); ++v) {
        TreeTemplate tree = s.species[plan.variants[v].species].tree;
        tree.params = plan.variants[v].params;
        SceneVariant sv;
        sv.name = plan.variants[v].name;
        // One material set per species, or per variant when its colours vary by seed.
        sv.material_prefix = tree.params.color_variation > 0.0 ? sv.name : tree.name;
        sv.levels = variant_models[v].levels;
        std::size_t triangles = 0;
        for (const NamedMesh& part : sv.levels[0]) triangles += part.mesh->triangles.size();
        result.variant_triangles.push_back(triangles);
        scene_variants.push_back(std::move(sv));
    }
    std::vector<SceneInstance> instances;
    for (std::size_t i = 0; i < plan.placements.size(); ++i) {
        const Placement& p = plan.placements[i];
        char name[32];
        std::snprintf(name, sizeof name, "tree_%05zu", i);
        instances.push_back({p.variant, glm::vec3(p.position), static_cast<float>(p.yaw_degrees),
                             static_cast<float>(p.scale), name});
    }

    FileSet files;
    files.add(glb, [&](std::ostream& out) {
        write_forest_glb(out, scene_variants, instances, s.instancing, s.export_options);
    });
    files.add(placements_csv_path(glb), [&](std::ostream& out) {
        out << "index,species,variant,x,y,z,yaw_degrees,scale,age,class\n";
        for (std::size_t i = 0; i < plan.placements.size(); ++i) {
            const Placement& p = plan.placements[i];
            out << format_row(i, s.species[p.species].tree.name, plan.variants[p.variant].name, p);
        }
    });
    files.add(placements_json_path(glb), [&](std::ostream& out) {
        nlohmann::ordered_json species = nlohmann::ordered_json::array();
        for (const Species& sp : s.species)
            species.push_back({{"name", sp.tree.name}, {"weight", sp.weight}, {"class", sp.cls}});
        nlohmann::ordered_json variants = nlohmann::ordered_json::array();
        for (std::size_t v = 0; v < plan.variants.size(); ++v) {
            const Variant& var = plan.variants[v];
            variants.push_back({{"name", var.name},
                                {"species", s.species[var.species].tree.name},
                                {"seed", var.seed},
                                {"age", var.age},
                                {"triangles", result.variant_triangles[v]}});
        }
        nlohmann::ordered_json placements = nlohmann::ordered_json::array();
        for (const Placement& p : plan.placements)
            placements.push_back({{"species", s.species[p.species].tree.name},
                                  {"variant", plan.variants[p.variant].name},
                                  {"position", {p.position.x, p.position.y, p.position.z}},
                                  {"yaw_degrees", p.yaw_degrees},
                                  {"scale", p.scale},
                                  {"age", p.age},
                                  {"class", p.cls}});
        const nlohmann::ordered_json doc = {{"seed", s.seed},
                                            {"species", species},
                                            {"variants", variants},
                                            {"placements", placements}};
        out << doc.dump(1) << '\n';
    });
    result.files = files.commit();
    folder.keep();
    result.times.write_ms = clock.lap_ms();
    return result;
}

}  // namespace sylva::forest
