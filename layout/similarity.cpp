#include "layout/similarity.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace sylva::layout {

std::optional<AngleGraph> in_example_terms(const Example& example, const PolygonMesh& layout,
                                           std::string* why) {
    const Example out = make_example(layout);
    std::vector<int> dir(out.dirs.degrees.size(), -1), color(out.dirs.palette.size(), -1);
    color[0] = 0;
    for (std::size_t d = 0; d < dir.size(); ++d) {
        for (std::size_t k = 0; k < example.dirs.degrees.size(); ++k) {
            double diff = std::abs(out.dirs.degrees[d] - example.dirs.degrees[k]);
            diff = std::min(diff, 360.0 - diff);
            if (diff < 1e-6) dir[d] = static_cast<int>(k);
        }
        if (dir[d] < 0) {
            if (why) *why = "a direction the example lacks: " + std::to_string(out.dirs.degrees[d]);
            return std::nullopt;
        }
    }
    for (std::size_t c = 1; c < color.size(); ++c) {
        const auto& pal = example.dirs.palette;
        const auto it = std::find(pal.begin() + 1, pal.end(), out.dirs.palette[c]);
        if (it == pal.end()) {
            if (why) *why = "a colour the example lacks: " + color_hex(out.dirs.palette[c]);
            return std::nullopt;
        }
        color[c] = static_cast<int>(it - pal.begin());
    }
    AngleGraph g = out.graph;
    for (auto& ds : g.vertices) {
        for (Dart& d : ds) d.dir = dir[d.dir], d.left = color[d.left];
        std::sort(ds.begin(), ds.end(), [](const Dart& a, const Dart& b) { return a.dir < b.dir; });
    }
    return g;
}

bool locally_similar(const Example& example, const PolygonMesh& layout, std::string* why) {
    const std::optional<AngleGraph> g = in_example_terms(example, layout, why);
    if (!g) return false;
    std::set<std::vector<Label>> stars;
    for (std::size_t v = 0; v < example.graph.vertices.size(); ++v)
        stars.insert(star(example.graph, static_cast<int>(v)));
    for (std::size_t v = 0; v < g->vertices.size(); ++v)
        if (!stars.count(star(*g, static_cast<int>(v)))) {
            if (why)
                *why = "vertex " + std::to_string(v) + " has a neighbourhood the example lacks";
            return false;
        }
    return true;
}

std::vector<int> structure_key(const Example& example, const PolygonMesh& layout) {
    const std::optional<AngleGraph> g = in_example_terms(example, layout);
    return g ? canonical_code(*g) : std::vector<int>{};
}

}  // namespace sylva::layout
