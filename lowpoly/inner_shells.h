// Hollows inside a solid. Where crown spheres or crossing branches enclose a pocket of
// outside space, marching cubes meshes the pocket's wall as a separate closed shell facing
// inwards (negative signed volume). No one ever sees it, yet it costs a reduction at least
// four triangles and more of a game budget; the low-poly stage drops such shells.
#pragma once

#include <optional>

#include "core/mesh.h"

namespace sylva {

// The mesh without every connected component whose signed volume is not positive (an inner
// shell, or a degenerate sliver) and the vertices only they used, the triangles left in
// their order; nothing when it has no such component (most meshes: no copy is made).
std::optional<Mesh> without_inner_shells(const Mesh& mesh);

}  // namespace sylva
