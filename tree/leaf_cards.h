// Leaves as a game mesh draws them: cards. A budget of a few hundred leaf triangles buys a
// few dozen of the tree's own leaves, specks no player sees from where a game tree is seen;
// the same triangles as cards, each standing for the leaves of one patch of the crown,
// cover the crown as its foliage did. Each card is a diamond (two triangles) lying across
// its patch, facing out of the crown, its base first as tree/leaves.h makes a leaf, so the
// leaves' UVs (a 0-1 card, v from base to tip), wind and textures apply to it unchanged.
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/mesh.h"

namespace sylva {

struct LeafCardSettings {
    std::size_t max_triangles = 800;  // two per card
    // The smallest patch, in lengths of the tree's median leaf.
    float min_leaves_across = 0.5f;
    std::uint64_t seed = 1;  // the cards' tilt and turn
    // The crown the leaves lie on (its vertices), or none: a card in the open is no larger
    // than its leaves need (see leaf_cards()).
    const Mesh* crown = nullptr;
};

// The leaves of `leaves` (tree/leaves.h: no two share a vertex) as at most
// max_triangles / 2 cards. Where there are no more leaves than cards, a card per leaf, lying
// as the leaf lies but facing out of the crown. Else the leaves are gathered into patches of
// a grid, as many as there are cards (the cells start at min_leaves_across leaves and grow
// until they fit, as little as they must), and a card per patch: centred on its leaves,
// facing out of the crown (away from its spine and from the leaves around the patch), as
// long and wide as the leaves spread along and across it, leaning and turned a little at
// random; where the patch's leaves lie alike (their normals, turned outwards, mostly agree:
// a frond's leaflets, a row of leaves on a twig) the card lies in their mean plane instead
// and runs along their mean direction, so it covers them as they show from the side.
// A card whose patch has no crown surface near (settings.crown, within a cell) has at most 1.75
// times its leaves' area, shrunk evenly.
// Same leaves and settings, same cards. No leaves, or a budget below two triangles,
// give none.
Mesh leaf_cards(const Mesh& leaves, const LeafCardSettings& settings);

}  // namespace sylva
