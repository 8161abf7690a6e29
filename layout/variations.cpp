#include "layout/variations.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>

#include "core/errors.h"
#include "core/random.h"
#include "layout/geometry.h"

namespace sylva::layout {

namespace {

// A seed for (seed, a, b): splitmix64 of the three mixed (unsigned: wraps by definition).
std::uint64_t mix(std::uint64_t seed, std::uint64_t a, std::uint64_t b = 0) {
    Random r(seed ^ (a * 0x9e3779b97f4a7c15ULL) ^ (b * 0xc2b2ae3d27d4eb4fULL));
    r.next();
    return r.next();
}

// One variation: grown to `target` and drawn, the ranges widened step by step when its
// structure needs it; grown again from another seed when it cannot be drawn at all; a
// starter as the last resort.
std::optional<PolygonMesh> one(const GrowthTable& table, std::uint64_t seed, int target,
                               const VariationSettings& settings, VariationReport& rep) {
    const Directions& dirs = table.grammar().dirs;
    GrowSettings grow = settings.grow;
    grow.target = target;
    rep.target = target;
    for (int r = 0; r <= settings.retries; ++r) {
        throw_if_cancelled(settings.cancel);
        const AngleGraph g = grow_graph(table, mix(seed, r, 1), grow, &rep.grow);
        for (int relax = 0; relax <= 3; ++relax)
            if (auto mesh = realize(g, dirs, mix(seed, r, 2), settings.lengths, 12, relax)) {
                rep.regrown = r;
                rep.relax = relax;
                return mesh;
            }
    }
    rep.fallback = true;
    rep.relax = 3;
    for (std::size_t s = 0; s < table.grammar().starters.size(); ++s)
        if (auto mesh = realize(table.grammar().starters[s], dirs, mix(seed, s, 3),
                                settings.lengths, 64, 3))
            return mesh;
    return std::nullopt;
}

}  // namespace

double layout_area(const PolygonMesh& mesh) {
    double area = 0;
    for (const Polygon& p : mesh.polygons) {
        std::vector<glm::dvec2> pts;
        for (int i : p.vertices) pts.push_back(mesh.vertices[i]);
        area += std::abs(signed_area(pts));
    }
    return area;
}

std::string VariationsReport::limits() const {
    int stuck = 0, steps = 0, vertices = 0, regrown = 0, fallback = 0;
    int relaxed[4] = {0, 0, 0, 0};
    for (const VariationReport& r : items) {
        stuck += r.grow.stuck;
        steps += r.grow.step_limited;
        vertices += r.grow.vertex_limited;
        regrown += r.regrown > 0;
        if (!r.fallback) ++relaxed[std::clamp(r.relax, 0, 3)];
        fallback += r.fallback;
    }
    std::string out;
    auto add = [&](int n, const char* what) {
        if (n == 0) return;
        if (!out.empty()) out += ", ";
        out += std::to_string(n) + " " + what;
    };
    add(stuck, "stopped short: no rule grows them further");
    add(steps, "stopped by the step limit");
    add(vertices, "met the vertex limit");
    add(regrown, "grown again to be drawable");
    add(relaxed[1], "drawn longer than the length ranges");
    add(relaxed[2] + relaxed[3], "drawn shorter than the length ranges");
    add(fallback, "fell back to a starter");
    return out;
}

std::vector<PolygonMesh> generate_layouts(const GrowthTable& table, int count, std::uint64_t seed,
                                          const VariationSettings& settings,
                                          VariationsReport* report) {
    const int n = std::max(0, count);
    std::vector<std::optional<PolygonMesh>> out(static_cast<std::size_t>(n));
    std::vector<VariationReport> reports(static_cast<std::size_t>(n));
    const int base = table.example_size();
    const int lo = settings.spread_low > 0 ? settings.spread_low : base + 1;
    const int hi = std::max(lo, settings.spread_high > 0 ? settings.spread_high : 12 * base);
    // The example's area per unit of size, for an area target.
    const Grammar& grammar = table.grammar();
    double area_per_unit = 0;
    if (settings.area > 0) {
        for (const AngleGraph& s : grammar.starters) {
            if (auto m = realize(s, grammar.dirs, seed, settings.lengths, 64, 3)) {
                const Analysis a = analyze(s, grammar.dirs);
                area_per_unit =
                    std::max(area_per_unit, layout_area(*m) / std::max(1, table.size_of(s, a)));
            }
        }
        if (area_per_unit <= 0) area_per_unit = 1;
    }
    const double offset = Random(mix(seed, 0x6f6666)).uniform();
    std::atomic<int> done{0};
    std::mutex progress_mutex;
    auto work = [&](int i) {
        const std::uint64_t s = mix(seed, static_cast<std::uint64_t>(i) + 1);
        VariationReport& rep = reports[static_cast<std::size_t>(i)];
        int target = settings.size;
        if (target <= 0 && settings.area > 0) {
            target = std::max(1, static_cast<int>(std::lround(settings.area / area_per_unit)));
        } else if (target <= 0) {
            const double u = std::fmod(offset + 0.6180339887498949 * i, 1.0);
            target = lo + std::min(hi - lo, static_cast<int>(u * (hi - lo + 1)));
        }
        std::optional<PolygonMesh> mesh = one(table, s, target, settings, rep);
        // An area target: grown again to the size the last drawing suggests, keeping the
        // drawing nearest the area.
        for (int round = 0; round < 3 && mesh && settings.area > 0; ++round) {
            const double area = layout_area(*mesh);
            if (std::abs(std::log(area / settings.area)) < std::log(1.1)) break;
            const int next_target = std::max(
                1, static_cast<int>(std::lround(target * settings.area / std::max(area, 1e-9))));
            if (next_target == target) break;
            VariationReport again;
            std::optional<PolygonMesh> other =
                one(table, mix(s, round + 7), next_target, settings, again);
            if (!other) break;
            target = next_target;
            if (std::abs(std::log(layout_area(*other) / settings.area)) <
                std::abs(std::log(area / settings.area))) {
                mesh = std::move(other);
                rep = again;
            }
        }
        if (mesh) {
            rep.area = layout_area(*mesh);
            rep.size =
                static_cast<int>(table.measure() == SizeMeasure::Polygons ? mesh->polygons.size()
                                                                          : mesh->vertices.size());
        }
        out[static_cast<std::size_t>(i)] = std::move(mesh);
        const int finished = ++done;
        if (settings.progress) {
            std::lock_guard<std::mutex> lock(progress_mutex);
            settings.progress(finished, n);
        }
    };
    auto run = [&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, n, 1), [&](const tbb::blocked_range<int>& r) {
            for (int i = r.begin(); i != r.end(); ++i) work(i);
        });
    };
    if (settings.threads > 0) {
        tbb::task_arena arena(settings.threads);
        arena.execute(run);
    } else {
        run();
    }
    throw_if_cancelled(settings.cancel);
    std::vector<PolygonMesh> meshes;
    meshes.reserve(out.size());
    for (int i = 0; i < n; ++i) {
        if (!out[static_cast<std::size_t>(i)])
            throw InputError("no drawable layout found from this grammar (variation " +
                             std::to_string(i) + ")");
        meshes.push_back(std::move(*out[static_cast<std::size_t>(i)]));
    }
    if (report) {
        report->measure = table.measure();
        report->items = std::move(reports);
    }
    return meshes;
}

std::vector<PolygonMesh> generate_layouts(const Grammar& grammar, int count, std::uint64_t seed,
                                          const VariationSettings& settings,
                                          VariationsReport* report) {
    const GrowthTable table(grammar);
    return generate_layouts(table, count, seed, settings, report);
}

}  // namespace sylva::layout
