#include "impostor/hemi_octahedral.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

namespace sylva {

glm::vec2 hemi_octahedral_encode(glm::vec3 direction) {
    direction.y = std::max(direction.y, 0.0f);
    const float sum = std::abs(direction.x) + direction.y + std::abs(direction.z);
    if (!(sum > 0.0f)) return {0.0f, 0.0f};  // a zero direction: straight up
    const glm::vec2 p(direction.x / sum, direction.z / sum);
    return {p.x + p.y, p.x - p.y};
}

glm::vec3 hemi_octahedral_decode(glm::vec2 square) {
    const glm::vec2 p(0.5f * (square.x + square.y), 0.5f * (square.x - square.y));
    const float y = std::max(1.0f - std::abs(p.x) - std::abs(p.y), 0.0f);
    return glm::normalize(glm::vec3(p.x, y, p.y));
}

glm::vec3 view_direction(int i, int j, int views) {
    const float step = 2.0f / static_cast<float>(views - 1);
    return hemi_octahedral_decode(
        {static_cast<float>(i) * step - 1.0f, static_cast<float>(j) * step - 1.0f});
}

ViewFrame view_frame(glm::vec3 direction) {
    direction = glm::normalize(direction);
    glm::vec3 right = glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), direction);
    const float length = glm::length(right);
    right = length > 1e-6f ? right / length : glm::vec3(1.0f, 0.0f, 0.0f);
    return {direction, right, glm::cross(direction, right)};
}

ViewBlend view_blend(glm::vec3 direction, int views) {
    const float last = static_cast<float>(views - 1);
    const glm::vec2 grid = (hemi_octahedral_encode(direction) * 0.5f + 0.5f) * last;
    // The cell's lower corner, kept inside so (1, 1) of the cell is still a view.
    const glm::vec2 base = glm::clamp(glm::floor(grid), glm::vec2(0.0f), glm::vec2(last - 1.0f));
    const glm::vec2 f = glm::clamp(grid - base, glm::vec2(0.0f), glm::vec2(1.0f));
    const glm::ivec2 b(static_cast<int>(base.x), static_cast<int>(base.y));
    ViewBlend blend;
    if (f.x + f.y <= 1.0f) {
        blend.views = {b, b + glm::ivec2(1, 0), b + glm::ivec2(0, 1)};
        blend.weights = {1.0f - f.x - f.y, f.x, f.y};
    } else {
        blend.views = {b + glm::ivec2(1, 1), b + glm::ivec2(1, 0), b + glm::ivec2(0, 1)};
        blend.weights = {f.x + f.y - 1.0f, 1.0f - f.y, 1.0f - f.x};
    }
    return blend;
}

}  // namespace sylva
