// An axis-aligned box: where a field is meshed, what a skeleton or a mesh spans.
#pragma once

#include <glm/vec3.hpp>

namespace sylva {

struct Box {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
};

}  // namespace sylva
