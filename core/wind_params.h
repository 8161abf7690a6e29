// The wind a tree is exported for and previewed in: how strong, from where, how often the
// gusts come and how much the leaves flutter. These do not shape the tree; they travel with
// it (glb material extras, FBX user properties) so an engine's wind shader moves it as Sylva
// Studio does (export/wind_motion.h has the motion, docs/wind.glsl the shader).
//
// A block of TreeParams (core/param_blocks.h) with its table (core/param_table.h); the
// table is built once and read-only after: safe to read from any thread.
#pragma once

#include "core/param_table.h"

namespace sylva {

struct WindParams {
    double strength = 0.3;         // metres the top leans in a steady wind
    double direction = 0.0;        // degrees on the ground, from +x towards +z
    double gust_frequency = 0.15;  // gusts per second (0: a steady wind)
    double flutter = 0.1;          // leaf flutter at the tips, as a share of strength
};

// wind_strength, wind_direction, wind_gust_frequency and wind_flutter, group Wind.
const ParamTable& wind_param_table();

}  // namespace sylva
