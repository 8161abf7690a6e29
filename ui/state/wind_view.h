// Sylva Studio's wind toggle: the tree on screen swayed by the wind data an export writes
// (export/part_attributes.h), moved with the same formula as docs/wind.glsl
// (export/wind_motion.h). The parts are swayed on the CPU each frame and re-uploaded: a
// few thousand vertices at game budgets, and the renderers stay as they are. No GL here.
#pragma once

#include <array>
#include <vector>

#include "core/mesh.h"
#include "core/skeleton.h"
#include "export/wind_motion.h"

namespace sylva::studio {

struct WindView {
    WindMotion motion;
    struct Part {
        Mesh rest;                    // as generated
        std::vector<glm::vec4> wind;  // per vertex of rest
        Mesh swayed;                  // rest moved to the last time given to sway()
    };
    std::array<Part, 3> parts;  // trunk, crown, leaves
    bool ready = false;         // parts hold the tree on screen
};

// Takes the parts on screen and computes their wind data (the tree's whole trunk, crown
// and leaves set the frame, as in an export).
void set_wind_parts(WindView& view, const Skeleton& skeleton, const Mesh& tree_trunk,
                    const Mesh& tree_crown, const Mesh& tree_leaves, const Mesh& trunk,
                    const Mesh& crown, const Mesh& leaves);

// Moves every part to `seconds`; read view.parts[i].swayed.
void sway(WindView& view, float seconds);

}  // namespace sylva::studio
