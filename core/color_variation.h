// Colour variation (Limbach 2004: "die aktuelle Farbe ... variieren"): a template's
// part colours shifted per seed, so trees of one template planted together do not all wear
// the same green. Crown and leaves share one shift (they stay matched); the trunk has its own.
#pragma once

#include <cstdint>

#include "core/tree_template.h"

namespace sylva {

// `base` with brightness and hue (a tint per channel) shifted by up to `amount` (0: `base`
// exactly; 1: brightness by up to +-30%, each channel by up to +-15% more), drawn from
// `seed`. Channels stay in [0, 1].
PartColors varied_colors(const PartColors& base, double amount, std::uint64_t seed);

// The colours a template's tree is drawn and exported with: its colours varied by its
// color_variation and seed.
inline PartColors tree_colors(const TreeTemplate& tree) {
    return varied_colors(tree.colors, tree.params.color_variation, tree.params.seed);
}

}  // namespace sylva
