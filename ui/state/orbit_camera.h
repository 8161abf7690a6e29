// An orbit camera: it circles a target point at a distance, Y up, and frames a point set.
// Plain data plus free functions, so panels and tests can read and set it directly.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <span>

namespace sylva::studio {

struct OrbitCamera {
    glm::vec3 target{0.0f};
    float distance = 5.0f;    // meters from the target
    float yaw_deg = 35.0f;    // around +Y; 0 looks down -Z
    float pitch_deg = 12.0f;  // positive looks down at the target
    float fov_y_deg = 40.0f;
    float scene_radius = 1.0f;  // sets the zoom limits and the clip planes
};

// Looks at the centre of the points' bounding box from the camera's current angles, just far
// enough back that every point is in view in a viewport of this aspect (width / height).
// Does nothing for no points.
void frame_points(OrbitCamera& camera, std::span<const glm::vec3> points, float aspect);

// Left-drag: `pixels` is the mouse movement since the last frame.
void orbit(OrbitCamera& camera, glm::vec2 pixels);

// Right- or middle-drag: slides the target in the view plane, `pixels` since the last frame,
// for a viewport `viewport_height` pixels tall.
void pan(OrbitCamera& camera, glm::vec2 pixels, float viewport_height);

// Scroll: positive `steps` move closer. Distance is clamped to a range around the scene.
void zoom(OrbitCamera& camera, float steps);

glm::vec3 eye_position(const OrbitCamera& camera);
glm::mat4 view_matrix(const OrbitCamera& camera);
glm::mat4 projection_matrix(const OrbitCamera& camera, float aspect);

}  // namespace sylva::studio
