#include "forest/variation.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.h"
#include "core/random.h"
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

}  // namespace

std::uint64_t variant_seed(std::uint64_t base, std::uint64_t index) {
    // Random(base) returns splitmix64(base + (i + 1) * golden) as its i-th number.
    return Random(base + index * kGolden).next();
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
