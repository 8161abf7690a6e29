// A 1.8 m person drawn as lines beside the tree, so its size reads at a glance.
#pragma once

#include <glm/vec3.hpp>
#include <vector>

namespace sylva::studio {

constexpr float kFigureHeight = 1.8f;  // meters

// Line pairs (as LineRenderer takes them) of a standing person kFigureHeight tall whose
// feet stand at `feet`, facing +Z.
std::vector<glm::vec3> scale_figure_lines(const glm::vec3& feet);

}  // namespace sylva::studio
