// Branches as a low-poly artist models them: a regular polygon swept along a branch's axis
// (a prism per segment, mitred where the axis bends), closed by a flat cap at the base and
// ending in a point at a tip or in a cap. Fewer triangles than any reduction of a round
// surface leaves of a thin branch, and no blades: a reduced marching-cubes twig collapses
// to a flat sliver long before it runs out of triangles.
//
// A tube's faces do not cross one another as long as no bend is sharper than
// kMaxTubeBendDegrees and every segment is longer than the mitres of its two ends reach into
// it (tube_pieces() cuts an axis where that fails). Free functions on plain data; no state,
// safe to call from several threads at once.
#pragma once

#include <cstddef>
#include <glm/vec3.hpp>
#include <vector>

#include "core/mesh.h"

namespace sylva {

// Bends sharper than this split a tube in two pieces (each closed), which then overlap
// at the bend: a sharper mitre stretches the polygon into a blade.
inline constexpr float kMaxTubeBendDegrees = 70.0f;

// A pointed tube's point lies past its last axis point by this share of the last segment,
// times the tip's radius over the radius before it (append_tube).
inline constexpr float kTipReach = 0.25f;

struct TubeAxis {
    std::vector<glm::vec3> points;  // the centre line, base first; at least two points
    std::vector<float> radii;       // one per point, each above zero: half the mean width
    bool pointed = false;           // the tube ends in a point (a tip), not a cap
};

// The axis with fewer points: Douglas-Peucker on position and radius (a point stays when
// it lies farther than `tolerance` from the line between the points kept around it, or its
// radius differs from that line's by more than half of it: a width shows the radius twice),
// first and last point always kept.
TubeAxis simplify_axis(const TubeAxis& axis, float tolerance);

// The axis cut into pieces that each make a tube whose faces do not cross: at every bend
// sharper than kMaxTubeBendDegrees, and where a segment is too short for the mitres of its
// ends (with `sides` corners), at its sharper end. Points closer than a thousandth of their
// radius to the one before are dropped. Each piece but the last ends in a cap; the last
// keeps `pointed`. An axis with fewer than two distinct points gives no piece.
std::vector<TubeAxis> tube_pieces(const TubeAxis& axis, int sides);

// The triangles a tube of `points` axis points with `sides` corners has: its two caps (or
// cap and point) and two per corner and segment (one per corner on a pointed end).
std::size_t tube_triangles(std::size_t points, int sides, bool pointed);

// Appends the tube of `axis` (as tube_pieces() makes it) to `mesh` as one closed,
// 2-manifold, outward piece with `sides` (3 or more) corners. Its polygon's circumradius is
// chosen so that its mean width equals the axis' diameter (a triangle's is 1.21 times the
// radius); at a bend its corners lie in the plane halving the bend (a mitre), so each face
// of a segment is flat where the radius does not change. `side` points where the first
// corner points at the base (it is made perpendicular to the first segment; any direction
// not along it will do), and is carried along the axis without twist. A pointed tube's
// point lies just past its last axis point (kTipReach). The base is drawn 3%
// thinner: it lies inside another tube (a parent, or the piece before a cut), and no corner
// of the two then meets.
void append_tube(Mesh& mesh, const TubeAxis& axis, int sides, glm::vec3 side);

}  // namespace sylva
