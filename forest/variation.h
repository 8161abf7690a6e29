// Variants of one template: a seed per index and a seeded jitter of a fixed set of
// parameters, shared by `sylva batch` and the forest's unique variants. Index i's seed is the
// i-th output of splitmix64 (core/random.h) started at the base seed, so any index is found
// without drawing the ones before it and every shard of a batch agrees on it.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "core/tree_params.h"

namespace sylva {

// The seed of variant `index` of a batch or species seeded with `base`.
std::uint64_t variant_seed(std::uint64_t base, std::uint64_t index);

// A parameter the jitter varies: value * (1 + jitter * spread * r), r uniform in [-1, 1],
// clamped to the parameter's valid range (param_infos()). Integers and choices are never
// varied; a parameter at 0 stays 0.
struct JitterParam {
    std::string_view key;
    double spread;
};

// The documented set, in draw order: shape (lengths, angles, tapers, widths), crown and
// leaf size, and the colonization envelope. Growth methods ignore the keys they do not use.
std::span<const JitterParam> jitter_params();

// `params` with its seed set to `seed` and, when jitter > 0, the parameters of
// jitter_params() varied by a Random seeded from `seed` (jitter 0.1: +-10 % at spread 1).
// Throws InputError when jitter is not in [0, 1].
TreeParams varied_params(const TreeParams& params, std::uint64_t seed, double jitter);

}  // namespace sylva
