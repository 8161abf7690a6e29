// Reduced pieces grown back to the size they had. A reduction keeps its vertices on (or
// near) the surface it simplifies, so a closed piece drawn with few triangles lies inside
// the piece it was made from: a ball of eight triangles is an inscribed octahedron, which
// shows about 60% of the ball's outline. By Cauchy's surface area formula (Santaló 1976)
// the mean area a convex body shows from all directions is a quarter of its surface area,
// so a piece scaled about its centroid until its surface area is the source's again shows,
// on average over views, the outline the source piece showed.
#pragma once

#include <cstddef>

#include "core/mesh.h"

namespace sylva {

struct PieceScaling {
    std::size_t scaled = 0;  // pieces grown
    float largest = 1.0f;    // the largest linear factor applied
};

// Scales each connected piece (by shared vertex indices) of `reduced` about its area
// centroid by sqrt(source area / reduced area), at most `most`, where that grows it (the
// source's area taken as that of the smooth surface its triangles stand for: a marching-cubes
// ball of 30 triangles counts as 1.2 times its own area): the
// source piece is the one of `source` whose box holds the reduced piece's centroid and whose
// centroid is nearest it, and only where each of the two is the other's only match (a piece
// split or merged by the reduction is left as it is). Scaling keeps each piece closed,
// outward and free of self-intersection; separate pieces may come to overlap. Pure: no
// state, safe from any thread on distinct meshes.
PieceScaling restore_piece_areas(Mesh& reduced, const Mesh& source, float most);

}  // namespace sylva
