// Several meshes as one (indices shifted, nothing welded): how the trunk and the crown are
// measured together against a reference tree.
#pragma once

#include <span>

#include "core/mesh.h"

namespace sylva {

// Null pointers and empty meshes are skipped.
Mesh merge_meshes(std::span<const Mesh* const> meshes);

}  // namespace sylva
