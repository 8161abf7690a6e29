// One SVG picture of several layouts side by side, each with a caption, each fitted to its
// cell or all at one scale (the gallery in docs/layout.md is made of these by `sylva layout
// generate --sheet`). y points up as in the layouts.
#pragma once

#include <string>
#include <vector>

#include "layout/polygon_mesh.h"

namespace sylva::layout {

struct SheetItem {
    const PolygonMesh* mesh = nullptr;
    std::string caption;
};

// `columns` per row, cells of `cell` pixels; with `same_scale` the largest layout fills its
// cell and the others are drawn at its scale.
std::string write_sheet_svg(const std::vector<SheetItem>& items, int columns = 4,
                            double cell = 220.0, bool same_scale = false);

}  // namespace sylva::layout
