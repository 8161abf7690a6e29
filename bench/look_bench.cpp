// How the game meshes look (made by hand, not broken by the reduction): for every built-in
// template, the tree is meshed and finished as `sylva export` does it at each budget
// (generate_tree with the budget's resolutions, then finish_tree), and the reduced trunk
// and crown are measured for what a player sees as broken, the whole tree for what it kept
// of the full-detail tree's outline (quality/):
//
//   pairs  self-intersecting triangle pairs inside the trunk's and the crown's pieces
//          (self_intersections.h); pieces overlapping each other do not count
//   fold%  the edge-length share of the trunk's and the crown's interior edges folding
//          inwards by more than 90 degrees (folds.h)
//   iou    the silhouette of trunk + crown + leaves against the full-detail tree's (budget
//          0: the raw marching-cubes meshes, every leaf), intersection over union at
//          256 x 256, the mean of 9 views, and the worst view (silhouette.h)
//
// and what each measurement took (ms, one thread). Per budget a summary follows: the parts
// with pairs, the largest fold shares, the smallest and the median IoU. With --lod, every
// level of the LOD chain that starts at each budget is measured (LOD1.. beside LOD0). With
// --detail, a line under each row gives the trunk's and the crown's pieces, how many of
// them are no 2-manifold once welded (tested as soups), their degenerate triangles and
// the first intersecting pairs (triangle indices into the part).
//
// With --images DIR, each measured tree's nine views go to DIR/<template>_<budget>.png (and
// _LOD<i> for further levels), the views side by side: white where both trees cover a
// pixel, red where only the full-detail tree does (what the game mesh lost), blue where only
// the game mesh does. With --parts as well, the trunk's, the crown's and the leaves' views
// each alone go beside it (<template>_<budget>_trunk.png, _crown, _leaves): which part lost
// or added the outline.
//
// Usage: sylva-bench-look [--budgets 50,200,800,3000] [--lod] [--detail] [--images DIR]
//                         [--parts] [TEMPLATE...]
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench/common.h"
#include "core/stopwatch.h"
#include "export/export_tree.h"
#include "quality/folds.h"
#include "quality/self_intersections.h"
#include "quality/silhouette.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"

namespace {

using namespace sylva;

std::vector<std::size_t> parse_budgets(const std::string& list) {
    std::vector<std::size_t> out;
    std::size_t start = 0;
    while (start <= list.size()) {
        const std::size_t comma = std::min(list.find(',', start), list.size());
        if (comma > start) out.push_back(std::stoul(list.substr(start, comma - start)));
        start = comma + 1;
    }
    return out;
}

// "trunk: 3 pieces (1 soup), 2 degenerate, pairs 4-17 4-18 ..."
void print_detail(const char* part, const Mesh& mesh, const SelfIntersections& found) {
    std::printf("%s: %zu pieces (%zu soup), %zu degenerate", part, found.pieces, found.soup_pieces,
                found.degenerate.size());
    // How the pairs touch: sharing an edge, a corner, or apart (positions welded).
    std::size_t shared[3] = {0, 0, 0};
    for (const auto& [a, b] : found.pairs) {
        int common = 0;
        for (std::uint32_t i : mesh.triangles[a])
            for (std::uint32_t j : mesh.triangles[b])
                common += mesh.positions[i] == mesh.positions[j];
        ++shared[std::min(common, 2)];
    }
    // Pairs whose triangles are joined by shared vertex indices (not only by position).
    std::vector<std::uint32_t> root(mesh.positions.size());
    for (std::uint32_t v = 0; v < root.size(); ++v) root[v] = v;
    const auto find = [&](std::uint32_t v) {
        while (root[v] != v) v = root[v] = root[root[v]];
        return v;
    };
    for (const auto& t : mesh.triangles) {
        root[find(t[1])] = find(t[0]);
        root[find(t[2])] = find(t[0]);
    }
    std::size_t joined = 0;
    for (const auto& [a, b] : found.pairs)
        joined += find(mesh.triangles[a][0]) == find(mesh.triangles[b][0]);
    if (!found.pairs.empty())
        std::printf(" (%zu apart, %zu at a corner, %zu at an edge; %zu in one indexed piece)",
                    shared[0], shared[1], shared[2], joined);
    if (!found.pairs.empty()) std::printf(", pairs");
    for (std::size_t i = 0; i < std::min<std::size_t>(4, found.pairs.size()); ++i)
        std::printf(" %u-%u", found.pairs[i][0], found.pairs[i][1]);
    if (found.pairs.size() > 4) std::printf(" ...");
}

// The nine views side by side, the rows top first: white both, red reference only, blue
// candidate only.
void write_comparison(const std::string& path, const Silhouettes& reference,
                      const Silhouettes& candidate) {
    const int n = reference.resolution, width = n * kSilhouetteViews;
    std::vector<std::uint8_t> rgb(static_cast<std::size_t>(width) * n * 3, 0);
    for (int v = 0; v < kSilhouetteViews; ++v)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const std::size_t at = static_cast<std::size_t>(y) * n + x;
                const bool r = reference.views[v][at] != 0, c = candidate.views[v][at] != 0;
                std::uint8_t* px =
                    &rgb[(static_cast<std::size_t>(n - 1 - y) * width + v * n + x) * 3];
                px[0] = r ? 255 : 0;
                px[1] = r && c ? 255 : 0;
                px[2] = c ? 255 : 0;
            }
    stbi_write_png(path.c_str(), width, n, 3, rgb.data(), width * 3);
}

// One measured level of one template.
struct Row {
    std::string name;  // "oak trunk" style labels are made from it
    std::size_t level = 0;
    std::size_t trunk_pairs = 0, crown_pairs = 0;
    bool has_trunk = false, has_crown = false;
    double trunk_fold = 0.0, crown_fold = 0.0;  // percent
    double iou = 0.0, worst_view = 0.0;
};

// What the measurements cost, summed over the rows.
struct Costs {
    double pairs_ms = 0.0, folds_ms = 0.0, silhouette_ms = 0.0, reference_ms = 0.0;
    std::size_t triangles = 0, rows = 0;
};

}  // namespace

int main(int argc, char** argv) {
    bench::use_studio_heap();  // as the other benchmarks
    std::vector<std::size_t> budgets = {50, 200, 800, 3000};
    bool lod = false, detail = false, parts_too = false;
    std::string images;
    std::vector<std::string> names;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--budgets" && i + 1 < argc)
            budgets = parse_budgets(argv[++i]);
        else if (arg == "--lod")
            lod = true;
        else if (arg == "--detail")
            detail = true;
        else if (arg == "--parts")
            parts_too = true;
        else if (arg == "--images" && i + 1 < argc)
            images = argv[++i];
        else
            names.push_back(arg);
    }
    if (names.empty())
        for (const TreeTemplate* t : builtin_templates()) names.push_back(t->name);
    const int resolution = 256;

    std::printf(
        "look of the game meshes: pairs = self-intersecting pairs inside pieces, fold = share "
        "of\ninterior edge length folding inwards > 90 deg, iou = silhouette against the "
        "full-detail tree\n(mean of %d views at %d px, and the worst view)\n\n",
        kSilhouetteViews, resolution);
    std::printf("%-11s %8s %6s %6s | %6s %6s | %7s %7s | %6s %6s | %7s %7s %7s\n", "template",
                "budget", "tris", "leaves", "pairs", "", "fold%", "", "iou", "worst", "pairs",
                "folds", "iou");
    std::printf("%-11s %8s %6s %6s | %6s %6s | %7s %7s | %6s %6s | %7s %7s %7s\n", "", "", "", "",
                "trunk", "crown", "trunk", "crown", "mean", "view", "ms", "ms", "ms");

    // rows[k]: the rows of budget k, every level.
    std::vector<std::vector<Row>> rows(budgets.size());
    Costs costs;
    double generate_ms = 0.0, finish_ms = 0.0, full_ms = 0.0;
    for (const std::string& name : names) {
        const TreeTemplate tmpl = load_template(name);
        Stopwatch full_time;
        const Tree full = generate_tree(tmpl);
        full_ms += full_time.lap_ms();
        const Mesh* full_parts[] = {&full.trunk, &full.crown, &full.leaves};
        Stopwatch reference_time;
        const SilhouetteFrame frame = silhouette_frame(full_parts);
        const Silhouettes reference = rasterize_silhouettes(full_parts, frame, resolution);
        costs.reference_ms += reference_time.lap_ms();

        for (std::size_t k = 0; k < budgets.size(); ++k) {
            FinishSettings finish;
            finish.budget.total = budgets[k];
            finish.lod = lod;
            MeshOptions options;
            options.budget = game_budget(finish);
            Stopwatch stage;
            const Tree tree = generate_tree(tmpl, options);
            generate_ms += stage.lap_ms();
            const FinishedTree finished = finish_tree(tree, finish);
            finish_ms += stage.lap_ms();

            for (std::size_t level = 0; level < finished.levels.size(); ++level) {
                const ReducedTree& r = finished.levels[level];
                Row row;
                row.name = name;
                row.level = level;
                row.has_trunk = !r.trunk.triangles.empty();
                row.has_crown = !r.crown.triangles.empty();

                Stopwatch measure;
                const SelfIntersections trunk_found = find_self_intersections(r.trunk);
                const SelfIntersections crown_found = find_self_intersections(r.crown);
                row.trunk_pairs = trunk_found.pairs.size();
                row.crown_pairs = crown_found.pairs.size();
                const double pairs_ms = measure.lap_ms();
                row.trunk_fold = 100.0 * concave_fold_share(r.trunk);
                row.crown_fold = 100.0 * concave_fold_share(r.crown);
                const double folds_ms = measure.lap_ms();
                const Mesh* parts[] = {&r.trunk, &r.crown, &r.leaves};
                const Silhouettes seen = rasterize_silhouettes(parts, frame, resolution);
                const SilhouetteScore score = silhouette_iou(reference, seen);
                const double silhouette_ms = measure.lap_ms();
                row.iou = score.mean;
                if (!images.empty() && parts_too) {
                    const char* part_names[] = {"trunk", "crown", "leaves"};
                    for (int part = 0; part < 3; ++part) {
                        const Mesh* ref_part[] = {full_parts[part]};
                        const Mesh* seen_part[] = {parts[part]};
                        write_comparison(images + "/" + name + "_" + std::to_string(budgets[k]) +
                                             "_" + part_names[part] + ".png",
                                         rasterize_silhouettes(ref_part, frame, resolution),
                                         rasterize_silhouettes(seen_part, frame, resolution));
                    }
                }
                if (!images.empty())
                    write_comparison(images + "/" + name + "_" + std::to_string(budgets[k]) +
                                         (level ? "_LOD" + std::to_string(level) : "") + ".png",
                                     reference, seen);
                row.worst_view = *std::min_element(score.views.begin(), score.views.end());

                costs.pairs_ms += pairs_ms;
                costs.folds_ms += folds_ms;
                costs.silhouette_ms += silhouette_ms;
                costs.triangles += r.triangles;
                ++costs.rows;

                std::string label = std::to_string(finished.budgets[level]);
                if (lod) label = "LOD" + std::to_string(level) + " " + label;
                std::printf(
                    "%-11s %8s %6zu %6zu | %6zu %6zu | %7.2f %7.2f | %6.3f %6.3f | %7.2f %7.2f "
                    "%7.2f\n",
                    level == 0 ? name.c_str() : "", label.c_str(), r.triangles,
                    r.leaves.triangles.size(), row.trunk_pairs, row.crown_pairs, row.trunk_fold,
                    row.crown_fold, row.iou, row.worst_view, pairs_ms, folds_ms, silhouette_ms);
                if (detail) {
                    std::printf("%20s", "");
                    print_detail("trunk", r.trunk, trunk_found);
                    print_detail("; crown", r.crown, crown_found);
                    std::printf("\n");
                }
                rows[k].push_back(row);
            }
            std::fflush(stdout);
        }
    }

    std::printf("\n");
    for (std::size_t k = 0; k < budgets.size(); ++k) {
        const std::vector<Row>& rs = rows[k];
        std::size_t parts = 0, with_pairs = 0, pairs = 0;
        std::string which;
        // (share, label) of every part, for the largest fold shares.
        std::vector<std::pair<double, std::string>> folds;
        std::vector<double> ious;
        const Row* worst_iou = nullptr;
        for (const Row& r : rs) {
            const std::string at = lod ? " LOD" + std::to_string(r.level) : "";
            for (int part = 0; part < 2; ++part) {
                const bool has = part == 0 ? r.has_trunk : r.has_crown;
                if (!has) continue;
                const std::size_t p = part == 0 ? r.trunk_pairs : r.crown_pairs;
                const std::string label = r.name + (part == 0 ? " trunk" : " crown") + at;
                ++parts;
                pairs += p;
                if (p > 0) {
                    ++with_pairs;
                    which += (which.empty() ? "" : ", ") + label + " " + std::to_string(p);
                }
                folds.emplace_back(part == 0 ? r.trunk_fold : r.crown_fold, label);
            }
            ious.push_back(r.iou);
            if (!worst_iou || r.iou < worst_iou->iou) worst_iou = &r;
        }
        std::sort(folds.begin(), folds.end(),
                  [](const auto& a, const auto& b) { return a.first > b.first; });
        std::printf("budget %zu%s: %zu of %zu parts with pairs inside pieces (%zu pairs)%s%s\n",
                    budgets[k], lod ? " (every LOD level)" : "", with_pairs, parts, pairs,
                    which.empty() ? "" : ": ", which.c_str());
        std::printf("  largest fold shares:");
        for (std::size_t i = 0; i < std::min<std::size_t>(3, folds.size()); ++i)
            std::printf("%s %s %.2f%%", i ? "," : "", folds[i].second.c_str(), folds[i].first);
        std::vector<double> fold_values;
        for (const auto& f : folds) fold_values.push_back(f.first);
        std::printf("; median %.2f%%\n", bench::median(fold_values));
        if (worst_iou)
            std::printf("  silhouette iou: min %.3f (%s%s), median %.3f\n", worst_iou->iou,
                        worst_iou->name.c_str(),
                        lod ? (" LOD" + std::to_string(worst_iou->level)).c_str() : "",
                        bench::median(ious));
    }
    const double n = static_cast<double>(std::max<std::size_t>(costs.rows, 1));
    std::printf(
        "\ncost per measured tree (%zu trees, %.0f trunk + crown triangles on average):\n"
        "  pairs (trunk + crown) %.2f ms, folds %.3f ms, silhouette (9 views at %d px) %.2f ms\n"
        "  the full-detail reference's silhouettes: %.1f ms per template\n"
        "  (making the trees: full detail %.0f ms, game meshes %.0f ms, reduction %.0f ms, all "
        "templates)\n",
        costs.rows, static_cast<double>(costs.triangles) / n, costs.pairs_ms / n,
        costs.folds_ms / n, resolution, costs.silhouette_ms / n,
        costs.reference_ms / static_cast<double>(names.size()), full_ms, generate_ms, finish_ms);
    return 0;
}
