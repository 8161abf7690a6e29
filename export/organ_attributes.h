// What engines get on the organs part (tree/organs.h) besides its shape: each organ's own
// UVs (a card per polygon, the surface's own mapping) and the wind data of
// export/part_attributes.h (sway with the tree's height, flex 1 like leaves, one phase per
// organ, no flutter: fruit and cones swing with their twig, they do not flutter).
#pragma once

#include "export/export_options.h"
#include "export/named_mesh.h"
#include "export/part_attributes.h"
#include "tree/organs.h"

namespace sylva {

PartAttributes organ_attributes(const OrganMesh& organs, const TreeFrame& frame,
                                const EngineSettings& settings);

}  // namespace sylva
