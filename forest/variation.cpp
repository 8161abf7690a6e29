#include "forest/variation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/errors.h"
#include "core/random.h"
#include "core/seed.h"
#include "tree/grammar_constants.h"
#include "tree/parameters.h"

namespace sylva {
namespace {

constexpr std::uint64_t kGolden = 0x9e3779b97f4a7c15ULL;
// Keeps the jitter's stream apart from the tree's own use of the same seed.
constexpr std::uint64_t kJitterStream = 0x6a09e667f3bcc909ULL;

constexpr JitterParam kJitterParams[] = {
    {"branch_length", 1.0},    {"branch_width", 0.5},    {"pitch_angle", 1.0},
    {"yaw_angle", 1.0},        {"trunk_taper", 0.1},     {"branch_taper", 0.2},
    {"sphere_diameter", 0.5},  {"leaf_size", 0.5},       {"leaf_density", 0.5},
    {"influence_radius", 0.5}, {"envelope_size_x", 1.0}, {"envelope_size_y", 1.0},
    {"envelope_size_z", 1.0},  {"trunk_height", 1.0},
};

const ParamInfo* info_of(std::string_view key) {
    for (const ParamInfo& info : param_infos())
        if (info.key == key) return &info;
    return nullptr;
}

// FNV-1a of a key's name: its own jitter stream.
std::uint64_t name_hash(std::string_view name) {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (const char c : name) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
    return h;
}

// A key's value, range and wholeness, or a throw saying why it cannot be varied.
struct Varied {
    double value, min, max;
    bool integer;
};

Varied varied_of(const TreeTemplate& tree, const KeyJitter& k) {
    if (!(k.amount >= 0.0 && k.amount <= 1.0))
        throw InputError("the jitter of " + k.key + " must be from 0 to 1, not " +
                         std::to_string(k.amount));
    if (const ParamInfo* info = find_param(k.key)) {
        if (!info->choices.empty() || info->flag)
            throw InputError("parameter " + k.key +
                             " is a choice or a flag: it cannot be jittered");
        return {*get_param(tree.params, k.key), info->min, info->max, info->integer};
    }
    const std::optional<GrammarDefine> define = find_grammar_define(tree.grammar, k.key);
    if (!define)
        throw InputError("cannot jitter '" + k.key + "': not a parameter nor a #define of " +
                         (tree.name.empty() ? std::string("the template") : tree.name) +
                         "'s rules");
    if (!define->value)
        throw InputError("cannot jitter #define " + k.key + ": its value is an expression");
    const double inf = std::numeric_limits<double>::infinity();
    return {*define->value, define->min ? *define->min : -inf, define->max ? *define->max : inf,
            define->integer};
}

}  // namespace

void check_key_jitter(const TreeTemplate& tree, std::span<const KeyJitter> keys) {
    for (const KeyJitter& k : keys) varied_of(tree, k);
}

std::vector<std::pair<std::string, double>> varied_keys(const TreeTemplate& tree,
                                                        std::uint64_t seed,
                                                        std::span<const KeyJitter> keys) {
    std::vector<std::pair<std::string, double>> out;
    for (const KeyJitter& k : keys) {
        const Varied v = varied_of(tree, k);
        Random random(seed ^ kJitterStream ^ name_hash(k.key));
        const double r = 2.0 * random.uniform() - 1.0;
        double value = std::clamp(v.value * (1.0 + k.amount * r), v.min, v.max);
        if (v.integer) value = std::clamp(std::round(value), std::ceil(v.min), std::floor(v.max));
        out.emplace_back(k.key, value);
    }
    return out;
}

std::uint64_t variant_seed(std::uint64_t base, std::uint64_t index) {
    // Random(base) returns splitmix64(base + (i + 1) * golden) as its i-th number.
    return seed_from_bits(Random(base + index * kGolden).next());
}

std::span<const JitterParam> jitter_params() {
    return kJitterParams;
}

TreeParams varied_params(const TreeParams& params, std::uint64_t seed, double jitter) {
    if (!(jitter >= 0.0 && jitter <= 1.0))
        throw InputError("jitter must be from 0 to 1, not " + std::to_string(jitter));
    TreeParams out = params;
    out.seed = seed;
    if (jitter == 0.0) return out;
    Random random(seed ^ kJitterStream);
    for (const JitterParam& p : kJitterParams) {
        const double r = 2.0 * random.uniform() - 1.0;  // drawn for every key: a stable stream
        const ParamInfo* info = info_of(p.key);
        const std::optional<double> value = get_param(out, p.key);
        if (!info || !value || info->integer) continue;
        const double varied =
            std::clamp(*value * (1.0 + jitter * p.spread * r), info->min, info->max);
        set_param(out, p.key, varied);
    }
    return out;
}

}  // namespace sylva
