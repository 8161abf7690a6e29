// Union-find over 0..n-1 with path halving: which vertices, balls or triangles belong
// together (mesh pieces, crown pieces, handle cutting). A union links the larger root under
// the smaller: marching cubes numbers a piece's vertices close together, so its trees stay
// shallow (faster than linking the first under the second). Callers use the sets only,
// never which element is the root.
#pragma once

#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace sylva {

struct DisjointSets {
    std::vector<std::uint32_t> parent;

    explicit DisjointSets(std::size_t n) : parent(n) {
        std::iota(parent.begin(), parent.end(), 0u);
    }
    std::uint32_t find(std::uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    }
    // False when a and b were one set already.
    bool unite(std::uint32_t a, std::uint32_t b) {
        a = find(a);
        b = find(b);
        if (a == b) return false;
        if (a < b) std::swap(a, b);
        parent[a] = b;
        return true;
    }
};

}  // namespace sylva
