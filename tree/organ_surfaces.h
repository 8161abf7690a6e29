// The organs a grammar places with "~name" (ABOP's predefined surfaces, 5.1): small low-poly
// meshes of fruit, cones and blossoms, each in its own frame. An organ's base is where the
// turtle stands; it grows along the turtle's heading H (the frame's +y), its right -L is +x
// and its up U is +z. Fruit hangs: its +y points straight down whatever the turtle's
// heading, as a stalk lets it. The meshes are made once and never change; any thread may
// read them.
#pragma once

#include <glm/vec2.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "core/mesh.h"

namespace sylva {

struct OrganSurface {
    std::string_view name;
    std::string_view description;
    float size;  // meters along +y when the module gives none
    // One unit long along +y from the base at the origin. Closed (counter-clockwise seen
    // from outside) except where `closed` is false (a flat blossom).
    Mesh mesh;
    std::vector<glm::vec2> uv;  // per vertex, in [0, 1]
    bool closed = true;
    bool hangs = false;  // +y points down (fruit on a stalk), not along the heading
};

// The surface called `name`, or null.
const OrganSurface* find_organ_surface(std::string_view name);

// Every surface's name, for help texts and warnings (turtle/lint.h).
std::vector<std::string> organ_surface_names();

}  // namespace sylva
