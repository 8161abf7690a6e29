// The templates compiled into the binary, so Sylva works with no files around.
#include "app/pipeline.h"
#include "app/template_library.h"

namespace sylva {

const TreeTemplate& default_template() {
    static const TreeTemplate tree = [] {
        TreeTemplate t;
        t.name = "default";
        t.description = "A ternary branching tree (after ABOP Fig. 2.8), built into Sylva";
        t.grammar = R"(# Sylva's default tree: a ternary branching tree after ABOP Fig. 2.8, in meters.
# Every apex A grows a short internode and three branches spread by the divergence
# angles d1 and d2; older internodes lengthen (lr) and thicken (vr) each generation.
#define a  18.95     # branching angle
#define d1 94.74     # divergence angle between the first and second branch
#define d2 132.63    # ... between the second and third
#define lr 1.109     # internode elongation per generation
#define vr 1.732     # width growth per generation
#define w0 0.022     # width of the first internode when it appears, meters
axiom: !(w0)F(1.6)/(45)A
A -> !(w0*vr)F(0.45)[&(a)F(0.45)A]/(d1)[&(a)F(0.45)A]/(d2)[&(a)F(0.45)A]
F(l) -> F(l*lr)
!(w) -> !(w*vr)
)";
        t.width_model = WidthModel::Explicit;
        t.params.generations = 5;
        t.params.tropism = 0.22;
        return t;
    }();
    return tree;
}

const TreeTemplate& spruce_template() {
    static const TreeTemplate tree = [] {
        TreeTemplate t;
        t.name = "spruce";
        t.description = "Seed 001's spruce (appendix B.1): LPTG turtle, whorls of drooping branches";
        // Appendix B.1 as printed; the axiom is the start symbol P, and the identity rules
        // of the seed (F -> F, + -> +, ...) are implied for symbols without a rule.
        t.grammar = R"(# Seed 001, appendix B.1: the spruce ("Fichte"), in the seed's own rule format.
#axiom
P
#rules
P -> ^^^^FFFFM
M -> FFF[]AAAAAM
A -> +++[&&&&&F[]F[]^F&[]O^^^^^^]
N -> ^^&&&[]N
O -> [--F[]N++]++[F[]N]--&[]^&&[]N
)";
        t.mode = TurtleMode::Lptg;
        t.width_model = WidthModel::Taper;
        TreeParams& p = t.params;
        p.crown_resolution = 75;
        p.trunk_resolution = 75;
        p.generations = 6;
        p.branch_length = 0.11;
        p.branch_width = 0.1;
        p.trunk_taper = 0.95;
        p.branch_taper = 0.825;
        p.sphere_diameter = 0.08;
        p.crown_offset = 0.06;
        p.crown_fusion = 0.01;
        p.pitch_angle = 22.5;
        p.yaw_angle = 22.5;
        return t;
    }();
    return tree;
}

const std::vector<const TreeTemplate*>& builtin_templates() {
    static const std::vector<const TreeTemplate*> all = {&default_template(), &spruce_template()};
    return all;
}

}  // namespace sylva
