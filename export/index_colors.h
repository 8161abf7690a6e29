// Colour by index (ABOP's colour map): with a template palette (PartColors::palette), the
// colour index the grammar gave each segment (' and ;), polygon and organ reaches the export
// as vertex colours. Trunk vertices take the colour of the segment they lie on, leaves drawn
// from the turtle's polygons the colour of their polygon, organs their own; leaves scattered
// in the crown are not drawn by the grammar and keep the leaves' colour. Index i takes
// palette[i % size].
//
// The colours go into PartAttributes::tint, which the writers multiply with the part's
// colour (glb COLOR_0, OBJ `v x y z r g b`, PLY red/green/blue): the part's colour becomes
// white and a tint already there (colour variation, occlusion) multiplies in. Flat shading is
// untouched: the writers split vertices per face as always, each face taking its corners'
// colours.
//
// Pure functions; safe on any thread.
#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "core/mesh.h"
#include "core/skeleton.h"
#include "export/named_mesh.h"
#include "tree/organs.h"

namespace sylva {

// palette[index % size]; white for an empty palette.
glm::vec3 palette_color(const std::vector<glm::vec3>& palette, int index);

// Each does nothing for an empty palette; else sets `part.color` to white and `attributes`'
// tint per vertex of `mesh` (part.mesh).
void color_trunk_by_index(NamedMesh& part, PartAttributes& attributes, const Skeleton& skeleton,
                          const std::vector<glm::vec3>& palette);
// Leaves as tree/leaves.h makes them (no two share a vertex; a polygon leaf starts at the
// polygon's first vertex, which is how it is recognised).
void color_leaves_by_index(NamedMesh& part, PartAttributes& attributes, const Skeleton& skeleton,
                           const std::vector<glm::vec3>& palette);
// `organs` is the OrganMesh whose mesh `part` shows.
void color_organs_by_index(NamedMesh& part, PartAttributes& attributes, const OrganMesh& organs,
                           const std::vector<glm::vec3>& palette);

}  // namespace sylva
