// Variants of one template: a seed per index and a seeded jitter of a fixed set of
// parameters, shared by `sylva batch`, the forest's unique variants and the studio's Variants
// strip. Index i's seed is the top 53 bits of the i-th output of splitmix64 (core/random.h)
// started at the base seed, so any index is found without drawing the ones before it, every
// shard of a batch agrees on it, and it is a seed of core/seed.h's range.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/tree_params.h"
#include "core/tree_template.h"

namespace sylva {

// The seed of variant `index` of a batch or species seeded with `base` (any 64-bit number):
// always within 0 to kMaxSeed (core/seed.h).
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

// A key varied besides jitter_params(), by up to +-amount (0 to 1): a #define constant of the
// template's rules or a parameter that is a number (`sylva batch --jitter a=0.2`).
struct KeyJitter {
    std::string key;
    double amount = 0;
};

// Throws InputError unless every key can be varied: a #define of `tree`'s grammar whose value
// is a number, or a registry parameter that is neither a choice nor a flag; and each amount is
// 0 to 1.
void check_key_jitter(const TreeTemplate& tree, std::span<const KeyJitter> keys);

// The values the keys take for a variant seeded with `seed`: each value * (1 + amount * r),
// r uniform in [-1, 1] from a stream of the seed and the key's name (so adding a key changes
// no other key's value), clamped to its range (a #define's comment, a parameter's valid
// range) and rounded for whole numbers. Set them with set_template_value()
// (tree/template_setting.h). Throws as check_key_jitter.
std::vector<std::pair<std::string, double>> varied_keys(const TreeTemplate& tree,
                                                        std::uint64_t seed,
                                                        std::span<const KeyJitter> keys);

}  // namespace sylva
