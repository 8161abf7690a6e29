// Reads a cylinder list as quantitative structure model (QSM) tools write it: one cylinder
// a row with its start point, axis direction, length, radius and parent. TreeQSM's text
// export (Raumonen et al. 2013) has no header and the columns
//   radius, length, start_x, start_y, start_z, axis_x, axis_y, axis_z, parent, extension,
//   branch, branch_order, position_in_branch, ...
// with rows counted from 1 and parent 0 for the first cylinder; AdQSM, 3D Forest and rTwig
// write the same quantities under column names. A header row names the columns (any
// order, case and unit suffix ignored: "Radius (m)", "start_x", "StartX", "start_point_x");
// see docs/infer.md for every name taken. Commas, tabs, semicolons or spaces separate.
#pragma once

#include <string>
#include <string_view>

#include "infer/example_tree.h"

namespace sylva {

// Throws InputError naming `source`, the row (its line) and the column at fault: a missing
// column, a cell that is not a number, a parent that is no row, then the checks of
// finish_example_tree(). Thread-safe.
ExampleTree parse_cylinder_csv(std::string_view text, const std::string& source, UpAxis up);

}  // namespace sylva
