#include "ui/ground_grid.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <glm/gtc/type_ptr.hpp>
#include <vector>

namespace sylva::studio {
namespace {

constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_view_projection;
out vec3 v_world;
void main() {
    v_world = a_position;
    gl_Position = u_view_projection * vec4(a_position, 1.0);
}
)";

constexpr const char* kFragmentShader = R"(#version 330 core
in vec3 v_world;
uniform vec3 u_centre;
uniform float u_radius;
out vec4 frag_color;
void main() {
    float fade = 1.0 - smoothstep(0.35 * u_radius, u_radius, length(v_world.xz - u_centre.xz));
    frag_color = vec4(0.55, 0.60, 0.68, 0.45 * fade);
}
)";

}  // namespace

float grid_cell_for(float size) {
    float target = std::max(size, 1e-3f) / 10.0f;
    float decade = std::pow(10.0f, std::floor(std::log10(target)));
    for (float step : {1.0f, 2.5f, 5.0f}) {
        if (step * decade >= target) return step * decade;
    }
    return 10.0f * decade;
}

GroundGrid::GroundGrid() : program_("ground grid", kVertexShader, kFragmentShader) {}

void GroundGrid::layout(glm::vec3 centre, float radius, float cell) {
    assert(radius > 0.0f && cell > 0.0f);
    // Snap to the cell so the lines stay on round coordinates (x = 0 is a line).
    centre_ =
        glm::vec3(std::round(centre.x / cell) * cell, 0.0f, std::round(centre.z / cell) * cell);
    radius_ = radius;
    int half = static_cast<int>(std::ceil(radius / cell));
    float extent = static_cast<float>(half) * cell;
    std::vector<glm::vec3> lines;
    lines.reserve(static_cast<std::size_t>(4 * (2 * half + 1)));
    for (int i = -half; i <= half; ++i) {
        float offset = static_cast<float>(i) * cell;
        lines.push_back(centre_ + glm::vec3(offset, 0.0f, -extent));
        lines.push_back(centre_ + glm::vec3(offset, 0.0f, extent));
        lines.push_back(centre_ + glm::vec3(-extent, 0.0f, offset));
        lines.push_back(centre_ + glm::vec3(extent, 0.0f, offset));
    }
    lines_.upload(lines);
}

void GroundGrid::draw(const glm::mat4& view, const glm::mat4& projection) const {
    if (lines_.count() == 0) return;
    glm::mat4 view_projection = projection * view;
    glUseProgram(program_.id());
    glUniformMatrix4fv(program_.uniform("u_view_projection"), 1, GL_FALSE,
                       glm::value_ptr(view_projection));
    glUniform3fv(program_.uniform("u_centre"), 1, glm::value_ptr(centre_));
    glUniform1f(program_.uniform("u_radius"), radius_);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    lines_.draw(GL_LINES);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
}

}  // namespace sylva::studio
