// The organs part in the 3D view (tree/organs.h): flowers, fruit and cones drawn in their
// colours, one renderer per colour index (the palette's colour, the leaves' without a
// palette), polygons from both sides as the exports' double-sided material shows them.
// Needs a current GL context; UI thread only.
#pragma once

#include <glm/mat4x4.hpp>
#include <memory>
#include <vector>

#include "core/tree_template.h"
#include "tree/organs.h"
#include "ui/mesh_renderer.h"

namespace sylva::studio {

struct OrganView {
    std::vector<std::unique_ptr<MeshRenderer>> renderers;
    std::vector<int> indices;  // per renderer, its colour index
};

// Replaces what the view draws with `organs`.
void upload_organs(OrganView& view, const OrganMesh& organs);

void draw_organs(const OrganView& organs, const glm::mat4& view, const glm::mat4& projection,
                 const PartColors& colors, bool wireframe, const glm::vec3& wire_color);

}  // namespace sylva::studio
