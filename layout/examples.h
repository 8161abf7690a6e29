// The example plans Sylva ships (layout/examples/*.mesh, compiled in at configure time) and
// the one way to open an example by name or file. Thread-safe.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "layout/polygon_mesh.h"

namespace sylva::layout {

// The shipped examples: (name, .mesh text), by name.
const std::vector<std::pair<std::string, std::string>>& builtin_examples();

// A shipped example by name, or a .mesh / .json file (read through core/input_file.h).
// Throws InputError (not an example, bad content) or IoError (the file cannot be read).
PolygonMesh load_example(const std::string& name_or_path);

}  // namespace sylva::layout
