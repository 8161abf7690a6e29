// Reads an OBJ of line segments (`v x y z` vertices, `l i j ...` polylines, 1-based or
// negative indices) as a tree: the lowest vertex is the root, every edge is oriented away
// from it. Faces and other statements are ignored. Radii are unknown (0).
#pragma once

#include <string>
#include <string_view>

#include "infer/example_tree.h"

namespace sylva {

// Throws InputError naming `source` and the line at fault: a bad number or index, an edge
// that closes a cycle, edges not connected to the root (disconnected pieces), then the
// checks of finish_example_tree(). Thread-safe.
ExampleTree parse_segment_obj(std::string_view text, const std::string& source, UpAxis up);

}  // namespace sylva
