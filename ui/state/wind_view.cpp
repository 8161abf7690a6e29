#include "ui/state/wind_view.h"

#include "export/part_attributes.h"

namespace sylva::studio {

void set_wind_parts(WindView& view, const Skeleton& skeleton, const Mesh& tree_trunk,
                    const Mesh& tree_crown, const Mesh& tree_leaves, const Mesh& trunk,
                    const Mesh& crown, const Mesh& leaves) {
    const TreeFrame frame = tree_frame(tree_trunk, tree_crown, tree_leaves);
    EngineSettings settings;
    settings.uvs = false;
    view.parts[0] = {trunk, trunk_attributes(trunk, skeleton, frame, settings).wind, trunk};
    view.parts[1] = {crown, crown_attributes(crown, frame, settings).wind, crown};
    view.parts[2] = {leaves, leaf_attributes(leaves, frame, settings).wind, leaves};
    view.ready = true;
}

void sway(WindView& view, float seconds) {
    for (WindView::Part& part : view.parts)
        for (std::size_t v = 0; v < part.rest.positions.size(); ++v)
            part.swayed.positions[v] =
                wind_position(part.rest.positions[v], part.wind[v], seconds, view.motion);
}

}  // namespace sylva::studio
