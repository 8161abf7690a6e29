// Leaves (Heuer 2022, 5.5): walk a grid over the crown's box and, at every (jittered) grid
// point inside the crown field, place a small flat leaf with a random orientation and size.
// Each leaf is its outline fanned into triangles once, one-sided (two triangles for the
// simplest shape): a back-facing copy would double the triangles, and sharing vertices with
// it would cancel the smooth normals. Renderers show both sides from the material instead
// (the glTF leaf material is doubleSided). Leaves are open surfaces by design; no two
// leaves share a vertex, and a leaf's first vertex is where it is attached (its base), so
// leaf_thinning.h can find, rank and grow each leaf.
#pragma once

#include <cstdint>
#include <functional>
#include <glm/vec2.hpp>
#include <vector>

#include "core/box.h"
#include "core/cancel.h"
#include "core/mesh.h"
#include "core/tree_params.h"

namespace sylva {

struct LeafSettings {
    double density = 60.0;  // leaves per cubic meter of crown
    double size = 0.25;     // leaf length, meters (each leaf varies by +-20%)
    LeafShape shape = LeafShape::Round;
    std::uint64_t seed = 1;
    std::size_t max_leaves = 200'000;  // the grid is coarsened to stay below this
    CancelFlag cancel = nullptr;       // polled per grid row; throws Cancelled
    // The `inside` function is 1-Lipschitz (a distance bound, as the crown's root smooth
    // min is): space far outside is skipped, with the same leaves as without.
    bool inside_is_distance_bound = false;
};

// The outline of a leaf shape in its own plane: x along the leaf from its base (0) to its
// tip (1), y across. Star-shaped around (0.5, 0), so a fan from there covers it.
const std::vector<glm::vec2>& leaf_outline(LeafShape shape);

// The turtle's polygons ({ . }), each fanned once from its first vertex (at least three
// vertices each), appended to `leaves`.
void add_polygon_leaves(Mesh& leaves, const std::vector<std::vector<glm::vec3>>& polygons);

// `inside` is negative inside the crown. Same inputs, same leaves. Throws Cancelled when
// settings.cancel becomes true.
Mesh scatter_leaves(const std::function<float(const glm::vec3&)>& inside, const Box& box,
                    const LeafSettings& settings);

}  // namespace sylva
