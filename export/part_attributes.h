// What engines want on a finished tree's parts besides their shape: texture coordinates, a
// colour tint and per-vertex wind data (PartAttributes, export/named_mesh.h). They are
// computed on the final, reduced meshes (each LOD level its own) from the skeleton and the
// tree's frame, so no reduction ever has to carry them and a reduced mesh has clean UVs.
//
// UVs, in metres of bark (kBarkTile):
// - trunk and branches: v is the distance along the branch from where it starts, u the
//   angle around it, a whole number of repeats per branch; the seam runs down the -Z side
//   (the back in a front view). Each vertex belongs to its nearest skeleton segment; a
//   triangle whose corners lie on different branches (a fork) takes its middle's branch.
// - crown: a box projection, each triangle onto the axis plane its normal faces most.
// - leaves: a card per leaf, v from the base (0) to the tip (1), u across (0.5 on the
//   midrib), so a leaf texture drawn upward in a square fits.
//
// Wind (each value in [0, 1]): x sway (the whole tree's bend: 0 at the ground, 1 at the
// top, quadratic), y flex (0 on the trunk, rising along each branch to 1 at its tip; a
// branch starts at its parent's value), z phase (one per first-order branch, shared by the
// branches on it; one per crown piece and per leaf), w flutter (leaves: 0 at the base, 1
// at the tip; 0 elsewhere). docs/wind.glsl is the reference vertex shader.
#pragma once

#include <glm/vec3.hpp>

#include "core/mesh.h"
#include "core/skeleton.h"
#include "export/export_options.h"
#include "export/named_mesh.h"

namespace sylva {

// Texture metres per UV unit on bark and crowns.
constexpr float kBarkTile = 1.0f;
constexpr float kCrownTile = 1.0f;

// What every part's attributes are measured against; the same for every LOD level (take
// it from the unreduced tree).
struct TreeFrame {
    float ground = 0.0f;  // lowest y of the tree
    float top = 1.0f;     // highest y
    // The box around crown and leaves (the trunk's when there are none): where crown
    // occlusion is darkest in the middle.
    glm::vec3 crown_center{0.0f};
    glm::vec3 crown_half_extent{1.0f};
};
TreeFrame tree_frame(const Mesh& trunk, const Mesh& crown, const Mesh& leaves);

PartAttributes trunk_attributes(const Mesh& trunk, const Skeleton& skeleton, const TreeFrame& frame,
                                const EngineSettings& settings);
PartAttributes crown_attributes(const Mesh& crown, const TreeFrame& frame,
                                const EngineSettings& settings);
// Leaves as tree/leaves.h makes them: no two share a vertex, each fanned from its base.
PartAttributes leaf_attributes(const Mesh& leaves, const TreeFrame& frame,
                               const EngineSettings& settings);

// Which skeleton segment each vertex of `mesh` lies on (nearest capsule surface); -1 for
// all when the skeleton has no segment. Also used for the trunk's collision shape.
std::vector<int> owning_segments(const Mesh& mesh, const Skeleton& skeleton);

}  // namespace sylva
