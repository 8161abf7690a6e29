// Several meshes as one (indices shifted, nothing welded): how the trunk and the crown are
// measured together against a reference tree. And one mesh as several: its connected
// components dealt into meshes of their own (how a large part is reduced on both cores).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/mesh.h"

namespace sylva {

// Null pointers and empty meshes are skipped.
Mesh merge_meshes(std::span<const Mesh* const> meshes);

// Each triangle's connected component (triangles joined through shared vertices), numbered
// by first triangle as component_volumes() (core/mesh_checks.h) orders them; `count`
// gets the number of components.
std::vector<std::uint32_t> component_of_triangles(const Mesh& mesh, std::size_t& count);

// The triangles dealt into `count` meshes by `label` (one per triangle; a label of `count`
// or more drops the triangle), each mesh with the vertices its triangles use, in order of
// first use.
std::vector<Mesh> split_by_label(const Mesh& mesh, std::span<const std::uint32_t> label,
                                 std::size_t count);

}  // namespace sylva
