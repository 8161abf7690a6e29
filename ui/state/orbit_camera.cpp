#include "ui/state/orbit_camera.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>
#include <span>

namespace sylva::studio {
namespace {

constexpr float kDegreesPerPixel = 0.3f;
constexpr float kZoomPerStep = 0.9f;
// Not quite +-90 so the view direction never becomes parallel to Y (lookAt's up vector).
constexpr float kMaxPitchDeg = 89.0f;

// Unit vector from the target to the eye: yaw 0 puts the eye on +Z looking down -Z.
glm::vec3 back_direction(const OrbitCamera& camera) {
    float yaw = glm::radians(camera.yaw_deg);
    float pitch = glm::radians(camera.pitch_deg);
    return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)};
}

}  // namespace

void frame_points(OrbitCamera& camera, std::span<const glm::vec3> points, float aspect) {
    if (points.empty()) return;
    glm::vec3 low = points.front(), high = points.front();
    for (const glm::vec3& p : points) {
        low = glm::min(low, p);
        high = glm::max(high, p);
    }
    camera.target = 0.5f * (low + high);
    camera.scene_radius = std::max(0.5f * glm::length(high - low), 1e-3f);

    // Fit the points themselves, not a bounding sphere or box: both leave a tree (tall, or
    // with an open crown) small in the window.
    glm::vec3 back = back_direction(camera);
    glm::vec3 right = glm::normalize(glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), back));
    glm::vec3 up = glm::cross(back, right);
    float tan_y = std::tan(0.5f * glm::radians(camera.fov_y_deg));
    float tan_x = tan_y * aspect;
    float distance = 1e-3f;
    for (const glm::vec3& p : points) {
        glm::vec3 offset = p - camera.target;
        float toward_eye = glm::dot(offset, back);
        distance = std::max(distance, toward_eye + std::abs(glm::dot(offset, right)) / tan_x);
        distance = std::max(distance, toward_eye + std::abs(glm::dot(offset, up)) / tan_y);
    }
    constexpr float kMargin = 1.1f;  // a little air around the tree
    camera.distance = kMargin * distance;
}

void orbit(OrbitCamera& camera, glm::vec2 pixels) {
    camera.yaw_deg = std::fmod(camera.yaw_deg - kDegreesPerPixel * pixels.x, 360.0f);
    camera.pitch_deg =
        std::clamp(camera.pitch_deg + kDegreesPerPixel * pixels.y, -kMaxPitchDeg, kMaxPitchDeg);
}

void pan(OrbitCamera& camera, glm::vec2 pixels, float viewport_height) {
    glm::vec3 back = back_direction(camera);
    glm::vec3 right = glm::normalize(glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), back));
    glm::vec3 up = glm::cross(back, right);
    // Meters per pixel at the target's depth, so the tree follows the mouse.
    float meters = 2.0f * camera.distance * std::tan(0.5f * glm::radians(camera.fov_y_deg)) /
                   std::max(viewport_height, 1.0f);
    camera.target += (-pixels.x * right + pixels.y * up) * meters;
}

void zoom(OrbitCamera& camera, float steps) {
    camera.distance *= std::pow(kZoomPerStep, steps);
    camera.distance =
        std::clamp(camera.distance, 0.05f * camera.scene_radius, 20.0f * camera.scene_radius);
}

glm::vec3 eye_position(const OrbitCamera& camera) {
    return camera.target + camera.distance * back_direction(camera);
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
