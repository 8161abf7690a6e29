#include "turtle/lsystem_params.h"

namespace sylva {
namespace {

constexpr std::string_view kNoiseKinds[] = {"gradient", "value_linear", "value_cosine",
                                            "value_cubic"};

}  // namespace

const ParamTable& lsystem_param_table() {
    using P = LSystemParams;
    using enum ParamGroup;
    static const ParamTable table = ParamTable::owned<P>(
        "lsystem",
        {
            param("generations", &P::generations, 0, 15, Shape, "derivation steps of the grammar")
                .symbol("P_Tgen"),
            param("branch_length", &P::branch_length, 0.001, 100, Shape,
                  "length of F and f without a parameter, meters")
                .symbol("P_Bl"),
            param("pitch_angle", &P::pitch_angle, 0, 360, Shape,
                  "default angle of & and ^, degrees")
                .symbol("P_alpha"),
            param("yaw_angle", &P::yaw_angle, 0, 360, Shape, "default angle of + - \\ /, degrees")
                .symbol("P_beta"),
            param("tropism", &P::tropism, -1, 1, Shape,
                  "elasticity of the bend towards gravity (or tropism_vector) after each F (0 = "
                  "none, negative bends away)"),
            param("branch_width", &P::branch_width, 0.0, 10, Branches,
                  "starting trunk width (diameter), meters")
                .symbol("P_Bw"),
            param("trunk_taper", &P::trunk_taper, 0, 1, Branches, "width factor per trunk segment")
                .symbol("P_r1"),
            param("branch_taper", &P::branch_taper, 0, 1, Branches,
                  "width factor per branch segment")
                .symbol("P_r2"),
            param("bend", &P::bend, 0, 360, Variation,
                  "branches curve coherently, by up to this many degrees per meter (noise "
                  "along each branch; 0 = straight)"),
            param("jitter", &P::jitter, 0, 0.9, Variation,
                  "each branch's angles and lengths times a factor in 1 +- jitter, drawn per "
                  "branch from the seed"),
            param("width_variation", &P::width_variation, 0, 0.9, Variation,
                  "widths swell and thin by up to this share along each branch (noise)"),
            param("noise_kind", &P::noise_kind, kNoiseKinds, Variation,
                  "the noise of noise(), fbm() and noise_loop() in rules and of bend, width and "
                  "tropism variation: gradient (Perlin) or value noise with linear, cosine or "
                  "cubic interpolation (Limbach 2004)"),
        });
    return table;
}

}  // namespace sylva
