// A solid given by a membership test and the box that holds it: any shape one stage draws
// for another without either knowing the other's types (another template's crown as a
// colonization envelope, an SDF read as field < 0).
#pragma once

#include <functional>
#include <glm/vec3.hpp>

#include "core/box.h"

namespace sylva {

struct Region {
    Box bounds;  // every point of the solid lies in it
    // True inside (boundary included). Must be deterministic; called from one thread.
    std::function<bool(const glm::vec3&)> contains;
};

}  // namespace sylva
