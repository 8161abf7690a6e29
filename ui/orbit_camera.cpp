#include "ui/orbit_camera.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

namespace sylva::studio {
namespace {

constexpr float kDegreesPerPixel = 0.3f;
constexpr float kZoomPerStep = 0.9f;
// Not quite +-90 so the view direction never becomes parallel to Y (lookAt's up vector).
constexpr float kMaxPitchDeg = 89.0f;

}  // namespace

void frame_box(OrbitCamera& camera, const Box& box, float aspect) {
    camera.target = 0.5f * (box.min + box.max);
    float radius = 0.5f * glm::length(box.max - box.min);
    camera.scene_radius = std::max(radius, 1e-3f);
    float half_fov_y = 0.5f * glm::radians(camera.fov_y_deg);
    float half_fov_x = std::atan(std::tan(half_fov_y) * aspect);
    float half_fov = std::min(half_fov_y, half_fov_x);
    // The bounding sphere is loose for a tall tree, so fit it slightly tighter than exact.
    camera.distance = 0.9f * camera.scene_radius / std::sin(half_fov);
}

void orbit(OrbitCamera& camera, glm::vec2 pixels) {
    camera.yaw_deg = std::fmod(camera.yaw_deg - kDegreesPerPixel * pixels.x, 360.0f);
    camera.pitch_deg =
        std::clamp(camera.pitch_deg + kDegreesPerPixel * pixels.y, -kMaxPitchDeg, kMaxPitchDeg);
}

void zoom(OrbitCamera& camera, float steps) {
    camera.distance *= std::pow(kZoomPerStep, steps);
    camera.distance =
        std::clamp(camera.distance, 0.05f * camera.scene_radius, 20.0f * camera.scene_radius);
}

glm::vec3 eye_position(const OrbitCamera& camera) {
    float yaw = glm::radians(camera.yaw_deg);
    float pitch = glm::radians(camera.pitch_deg);
    // Direction from the target to the eye: yaw 0 puts the eye on +Z looking down -Z.
    glm::vec3 back(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                   std::cos(pitch) * std::cos(yaw));
    return camera.target + camera.distance * back;
}

glm::mat4 view_matrix(const OrbitCamera& camera) {
    return glm::lookAt(eye_position(camera), camera.target, glm::vec3(0.0f, 1.0f, 0.0f));
}

glm::mat4 projection_matrix(const OrbitCamera& camera, float aspect) {
    float near_plane = std::max(1e-3f, camera.distance - 4.0f * camera.scene_radius);
    near_plane = std::max(near_plane, 0.01f * camera.distance);
    float far_plane = camera.distance + 8.0f * camera.scene_radius;
    return glm::perspective(glm::radians(camera.fov_y_deg), aspect, near_plane, far_plane);
}

}  // namespace sylva::studio
