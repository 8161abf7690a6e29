// Checks of a layout against its example (Schröder 2024, section 3.2.2: local similarity at the
// smallest radius): every edge in one of the example's directions, every vertex's star (its
// darts' directions with the colours between them) one of the example's, and a structure key
// that is equal for two layouts exactly when their plane graphs are (up to isomorphism:
// positions aside). Used by the tests, the benchmark and anyone checking a plan by hand.
// Pure functions; thread-safe.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "layout/angle_graph.h"

namespace sylva::layout {

// The layout's angle graph in the example's terms (direction and colour indices of
// `example`), or nullopt with `why` when it has a direction (within 1e-6 degrees) or a
// colour the example lacks.
std::optional<AngleGraph> in_example_terms(const Example& example, const PolygonMesh& layout,
                                           std::string* why = nullptr);

// True when every direction, colour and vertex star of `layout` is the example's.
bool locally_similar(const Example& example, const PolygonMesh& layout, std::string* why = nullptr);

// Equal for two layouts exactly when their plane graphs are isomorphic (with the example's
// directions and colours); empty when the layout is not in the example's terms.
std::vector<int> structure_key(const Example& example, const PolygonMesh& layout);

}  // namespace sylva::layout
