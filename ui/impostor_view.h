// Sylva Studio's impostor slot: after LOD 0-3, the low-poly view's LOD slider has one more
// slot that shows the octahedral impostor an export with --impostor writes (impostor/),
// drawn with the reference shader docs/impostor.glsl as one quad turned to the camera. A
// toggle swaps it for the tree it stands for (LOD 0) at the same place, to compare. The
// atlas is baked on a worker thread (std::async) from level 0 of the tree on screen and
// uploaded when done; the slot shows nothing until then. Needs a current GL 3.3 context;
// UI thread only.
#pragma once

#include <future>
#include <glm/mat4x4.hpp>
#include <memory>

#include "impostor/impostor_bake.h"
#include "ui/gl_program.h"
#include "ui/state/studio_state.h"

namespace sylva::studio {

// The LOD slider's slot after the chain's levels.
constexpr int kImpostorSlot = kLodLevels;

// The impostor slot is on screen (low poly, slider at kImpostorSlot).
inline bool impostor_slot_shown(const ViewToggles& view) {
    return view.low_poly && view.lod_level == kImpostorSlot;
}

// The chain level whose meshes the view uploads: 0 at the impostor slot (the tree it
// stands for), lod_level otherwise.
inline int mesh_level(const ViewToggles& view) {
    return view.lod_level == kImpostorSlot ? 0 : view.lod_level;
}

class ImpostorView {
  public:
    ImpostorView();  // needs a current GL 3.3 context
    ~ImpostorView();
    ImpostorView(const ImpostorView&) = delete;
    ImpostorView& operator=(const ImpostorView&) = delete;

    // Starts baking `tree`'s level 0 with the shown template's colours if it is not the
    // tree baked last (or being baked); uploads a finished bake. Call every frame the slot
    // is shown.
    void update(const std::shared_ptr<const GeneratedTree>& tree, const PartColors& colors);

    // Draws the impostor turned toward the camera at `eye` (world = model space here).
    void draw(const glm::mat4& view, const glm::mat4& projection, const glm::vec3& eye) const;

  private:
    GlProgram program_;
    GLuint vertex_array_ = 0, vertex_buffer_ = 0, albedo_ = 0, normal_ = 0;
    std::shared_ptr<const GeneratedTree> baking_, baked_;
    std::future<ImpostorAtlas> job_;
    ImpostorAtlas atlas_;  // the uploaded one's layout (pixels dropped)
    bool ready_ = false;
};

}  // namespace sylva::studio
