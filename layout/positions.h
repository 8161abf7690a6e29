// Vertex positions for an angle graph (Schröder 2024, section 3.4.2): every edge e from v0 to v1
// with direction u and unknown length s gives v0 + s u = v1. Around each closed face the
// steps sum to zero, so the lengths lie in the null space of a (2 faces x edges) matrix,
// found by Gauss-Jordan elimination (reduced row echelon form). Random target lengths near
// the example's are projected onto that space and pushed above a minimum length by
// alternating projections; positions follow by walking a spanning tree. Edges keep the
// example's directions exactly. A solution whose drawing is not planar (the turning test
// admits spirals that overlap for some lengths) is rejected and sampled again.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "layout/angle_graph.h"
#include "layout/graph_grammar.h"

namespace sylva::layout {

// A planar drawing of the complete graph `g`, or nullopt when `attempts` samples failed.
std::optional<PolygonMesh> realize(const AngleGraph& g, const Directions& dirs, std::uint64_t seed,
                                   int attempts = 12);

// The null space of a row-major matrix (rows x cols) by Gauss-Jordan: one basis vector per
// free column.
std::vector<std::vector<double>> null_space(std::vector<double> a, int rows, int cols);

// `count` variations from the grammar: variation i grows with a seed made from `seed` and i,
// so the same seed gives the same layouts. Each one is planar (checked by validate_mesh).
std::vector<PolygonMesh> generate_layouts(const Grammar& grammar, int count, std::uint64_t seed,
                                          const GenerateSettings& settings = {});

}  // namespace sylva::layout
