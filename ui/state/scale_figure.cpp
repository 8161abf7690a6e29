#include "ui/state/scale_figure.h"

#include <cmath>
#include <numbers>

namespace sylva::studio {

std::vector<glm::vec3> scale_figure_lines(const glm::vec3& feet) {
    // Proportions of an adult: head an eighth of the height, hips at half, shoulders at 0.82.
    const float h = kFigureHeight;
    const float head_radius = h / 16.0f;
    const glm::vec3 neck = feet + glm::vec3(0.0f, h - 2.0f * head_radius, 0.0f);
    const glm::vec3 shoulders = feet + glm::vec3(0.0f, 0.82f * h, 0.0f);
    const glm::vec3 hips = feet + glm::vec3(0.0f, 0.5f * h, 0.0f);
    const float shoulder = 0.12f * h, hip = 0.055f * h;
    std::vector<glm::vec3> lines = {
        neck,
        hips,  // body
        shoulders + glm::vec3(-shoulder, 0, 0),
        shoulders + glm::vec3(shoulder, 0, 0),
        shoulders + glm::vec3(-shoulder, 0, 0),
        feet + glm::vec3(-shoulder - 0.03f * h, 0.47f * h, 0),  // left arm
        shoulders + glm::vec3(shoulder, 0, 0),
        feet + glm::vec3(shoulder + 0.03f * h, 0.47f * h, 0),  // right arm
        hips + glm::vec3(-hip, 0, 0),
        hips + glm::vec3(hip, 0, 0),
        hips + glm::vec3(-hip, 0, 0),
        feet + glm::vec3(-hip - 0.02f * h, 0, 0),  // left leg
        hips + glm::vec3(hip, 0, 0),
        feet + glm::vec3(hip + 0.02f * h, 0, 0),  // right leg
    };
    const glm::vec3 head = neck + glm::vec3(0.0f, head_radius, 0.0f);
    constexpr int kSides = 16;
    for (int i = 0; i < kSides; ++i) {
        const float a = 2.0f * std::numbers::pi_v<float> * static_cast<float>(i) / kSides;
        const float b = 2.0f * std::numbers::pi_v<float> * static_cast<float>(i + 1) / kSides;
        lines.push_back(head + head_radius * glm::vec3(std::cos(a), std::sin(a), 0.0f));
        lines.push_back(head + head_radius * glm::vec3(std::cos(b), std::sin(b), 0.0f));
    }
    return lines;
}

}  // namespace sylva::studio
