// The organs part of a tree (docs/lowpoly.md, "Organs"): flowers, fruit and cones, as one
// mesh beside trunk, crown and leaves. It holds the surfaces the turtle placed with "~name"
// (tree/organ_surfaces.h) and, with polygon_part = organs, the turtle's { } polygons (petals,
// leaves traced by f), each with its colour index and its UVs. Organs are whole pieces: a
// budget keeps or drops an organ, never part of one.
//
// Pure functions of their inputs; safe on any thread.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <vector>

#include "core/mesh.h"
#include "core/skeleton.h"
#include "core/tree_params.h"

namespace sylva {

struct OrganMesh {
    // Every organ's vertices and triangles, one organ after the other. Polygons are open
    // (one-sided, fanned from their first vertex), surfaces closed.
    Mesh mesh;
    std::vector<glm::vec2> uv;  // per vertex, in [0, 1]: a card per polygon, the surface's own
    std::vector<int> color;     // per vertex: its organ's colour index
    // Organ k: vertices [first_vertex[k], first_vertex[k+1]), triangles
    // [first_triangle[k], first_triangle[k+1]); one entry more than organs.
    std::vector<std::uint32_t> first_vertex{0};
    std::vector<std::uint32_t> first_triangle{0};
    std::vector<std::uint8_t> polygon;  // per organ: 1 for a polygon (a fan), 0 for a surface

    std::size_t organs() const { return first_vertex.size() - 1; }
    bool empty() const { return mesh.triangles.empty(); }
};

// The skeleton's organs: its surfaces, then (with params.polygon_part = organs) its
// polygons. Throws InputError naming an unknown surface and the known ones.
OrganMesh tree_organs(const Skeleton& skeleton, const TreeParams& params);

// At most `max_triangles` triangles of organs (docs/lowpoly.md, "Organs"): when the organs
// have more, polygons of more than four vertices first become quads (their base, their tip
// and their widest vertex on either side, in outline order); then, if still more, whole
// organs are dropped, taken in a fixed order that halves the gaps between taken ones again
// and again (bit-reversed positions), so a smaller budget keeps a subset of a larger one's
// organs and a LOD chain loses organs evenly. SIZE_MAX keeps every organ as it is.
OrganMesh thin_organs(const OrganMesh& organs, std::size_t max_triangles);

}  // namespace sylva
