// The L-system's own parameters (growth = "lsystem"): how far the grammar is derived and
// the turtle's defaults for steps, angles, widths and bending. Kept in TreeParams::blocks;
// their table (lsystem_param_table) gives their keys and ranges. Another growth method
// never reads them.
#pragma once

#include "core/noise.h"
#include "core/param_table.h"
#include "core/tree_params.h"

namespace sylva {

struct LSystemParams {
    int generations = 6;           // P_Tgen: derivation steps
    double branch_length = 0.5;    // P_Bl: default step of F and f, meters
    double branch_width = 0.1;     // P_Bw: starting width (diameter) of the trunk, meters
    double trunk_taper = 0.95;     // P_r1: width factor per trunk segment
    double branch_taper = 0.8;     // P_r2: width factor per branch level and segment
    double pitch_angle = 22.5;     // P_alpha, degrees: & ^
    double yaw_angle = 22.5;       // P_beta, degrees: + - (and roll \ /)
    double tropism = 0.0;          // elasticity e of the bend towards gravity (ABOP)
    double bend = 0.0;             // degrees per meter of curvature noise along branches
    double jitter = 0.0;           // per-branch angles and lengths times 1 +- jitter
    double width_variation = 0.0;  // widths times 1 + this * noise along the branch
    NoiseKind noise_kind = NoiseKind::gradient;  // the noise of expressions and variation
};

const ParamTable& lsystem_param_table();

// The template's L-system parameters (defaults when none were set); change them with
// params.blocks.edit<LSystemParams>().
inline const LSystemParams& lsystem_params(const TreeParams& params) {
    return params.blocks.get<LSystemParams>();
}

}  // namespace sylva
