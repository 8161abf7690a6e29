// Reads skeleton.json (docs/skeleton-json.md), the file `sylva skeleton` writes, back into
// an example tree: segments with their parents, branch depths and radii, and the
// parameters the tree was made with. Tips and crown spheres are derived data and ignored;
// polygons are counted in a note (infer regrows branches, not leaf surfaces).
#pragma once

#include <string>
#include <string_view>

#include "infer/example_tree.h"

namespace sylva {

// Throws InputError naming `source` and the key at fault ("segments[12].parent") for a
// file that is not JSON (with its line and column), not a sylva-skeleton of version 1, or
// has a value of the wrong kind; then the checks of finish_example_tree(). Thread-safe.
ExampleTree parse_skeleton_json(std::string_view text, const std::string& source);

}  // namespace sylva
