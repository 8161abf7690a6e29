#include "tests/growth_method/dummy/dummy_growth.h"

#include <cmath>

#include "core/param_table.h"

namespace sylva::dummy {
namespace {

const ParamTable& dummy_param_table() {
    using P = DummyParams;
    static const ParamTable table = ParamTable::owned<P>(
        "dummy", {
                     param("dummy_height", &P::height, 0.1, 20, ParamGroup::Shape,
                           "height of every stem, meters"),
                     param("dummy_stems", &P::stems, 1, 9, ParamGroup::GrowthMethod,
                           "how many stems grow from the root"),
                     param("dummy_fan", &P::fan, ParamGroup::GrowthMethod,
                           "1: the stems lean outwards; 0: they stand upright"),
                 });
    return table;
}

Skeleton grow(const TreeTemplate& tree, const GrowthContext& context) {
    const DummyParams& p = tree.params.blocks.get<DummyParams>();
    Skeleton skeleton;
    for (int i = 0; i < p.stems; ++i) {
        const double angle = 2.0 * 3.14159265358979323846 * i / p.stems;
        const float lean = p.fan ? 0.3f : 0.0f;
        const glm::vec3 top(lean * static_cast<float>(std::cos(angle)), 1.0f,
                            lean * static_cast<float>(std::sin(angle)));
        Segment s;
        s.b = static_cast<float>(p.height) * top;
        s.ra = s.rb = static_cast<float>(0.5 * tree.params.tip_width);
        skeleton.segments.push_back(s);
    }
    if (context.progress) context.progress(1.0f);
    return skeleton;
}

}  // namespace

const GrowthMethod dummy_growth = {
    .name = "dummy",
    .description = "straight stems from the root (a test's growth method)",
    .grow = grow,
    .params = dummy_param_table,
};

}  // namespace sylva::dummy
