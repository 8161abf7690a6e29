// How far a reduced mesh strays from a reference surface: the one-sided distance from
// points sampled on the reduced mesh to the reference (for a tree, its resolution-200
// surface), as a mean and a max, in meters and in percent of the tree's height.
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/mesh.h"

namespace sylva {

struct FidelitySettings {
    std::size_t samples = 20000;  // points on the reduced mesh, uniform by area
    std::uint64_t seed = 1;
    // The length the percentages refer to; 0 = the reference's extent along Y (Y is up,
    // so for a tree: its height).
    double height = 0.0;
};

struct Fidelity {
    double mean = 0.0;          // meters
    double max = 0.0;           // meters; the largest over the samples (a lower bound)
    double mean_percent = 0.0;  // of height
    double max_percent = 0.0;
    double height = 0.0;  // meters
    std::size_t samples = 0;
};

// One-sided: it sees where `reduced` strays from `reference`, not parts of `reference`
// that `reduced` lost (swap the arguments for that). 0 for identical meshes.
// Throws InputError (core/errors.h) when `reference` has no triangles or the height is 0.
// Deterministic for a given seed.
Fidelity measure_fidelity(const Mesh& reduced, const Mesh& reference,
                          const FidelitySettings& settings = {});

}  // namespace sylva
