// The ways a game mesh can draw the crown (tree/lowpoly_tree.h, tree/crown_hulls.h), one
// table that the crown_shape parameter, --crown-shape, the help text and the studio's combo
// read. Adding a shape: a value below and one line in crown_shape.cpp's table.
#pragma once

#include <span>
#include <string_view>

namespace sylva {

enum class CrownShape {
    Automatic = 0,  // hulls when the crown has handles (blobs touching in rings), else blobs
    Blobs = 1,      // the crown's own surface, reduced
    Hulls = 2,      // the convex hulls of a few clusters of the crown, reduced
};

// When a shape draws the crown as convex hulls.
enum class CrownHulls {
    Never,        // always the crown's own surface
    Always,       // hulls at every budget (and at no budget, as many as a default one gives)
    WithHandles,  // hulls only for a reduced crown with handles (genus above 0)
};

struct CrownShapeInfo {
    CrownShape shape;
    std::string_view name;  // what crown_shape and --crown-shape take
    std::string_view help;  // one line for help text and tooltips
    CrownHulls hulls;
};

// Every shape, in the order of their values (a shape's index is its value).
std::span<const CrownShapeInfo> crown_shapes();
// Their names in the same order, as a choice parameter lists them.
std::span<const std::string_view> crown_shape_names();
const CrownShapeInfo& crown_shape_info(CrownShape shape);
// nullptr for a name no shape has.
const CrownShapeInfo* find_crown_shape(std::string_view name);

}  // namespace sylva
