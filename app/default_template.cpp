#include "app/pipeline.h"

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
#define vr 1.5       # width growth per generation
axiom: !(0.06)F(1.6)/(45)A
A -> !(0.035)F(0.45)[&(a)F(0.45)A]/(d1)[&(a)F(0.45)A]/(d2)[&(a)F(0.45)A]
F(l) -> F(l*lr)
!(w) -> !(w*vr)
)";
        t.width_model = WidthModel::Explicit;
        t.params.generations = 6;
        t.params.tropism = 0.22;
        return t;
    }();
    return tree;
}

}  // namespace sylva
