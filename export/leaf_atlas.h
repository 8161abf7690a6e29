// The texture of textured leaf cards (leaf_style = textured): engines that draw leaves
// alpha-tested then show leaf silhouettes on each card, not a diamond. A spray of the
// template's leaf shape (tree/leaves.h's outlines) along a midrib, drawn into the diamond a
// card's UVs cover (tree/leaf_cards.h: v from the base at 0 to the tip at 1, u across), each
// leaf's colour varied a little around the leaves' colour, transparent around them; the
// colour is carried into the transparent texels so mipmaps do not darken the edges.
// Deterministic; thread-safe.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>

#include "core/tree_params.h"
#include "export/named_mesh.h"

namespace sylva {

// The texture of leaf cards of `shape` and linear colour `color`: an sRGB PNG of `size` x
// `size` pixels with straight alpha (opaque on the leaves), named `leaves`, cut out at half
// alpha.
PartTextures leaf_atlas(LeafShape shape, const glm::vec3& color, int size = 256,
                        std::uint64_t seed = 1);

}  // namespace sylva
