#include "core/crown_shape.h"

#include <array>

namespace sylva {
namespace {

// One line per shape, in the order of CrownShape's values.
constexpr std::array kShapes{
    CrownShapeInfo{CrownShape::Automatic, "auto",
                   "hulls when the crown's blobs touch in rings (handles), else blobs",
                   CrownHulls::WithHandles},
    CrownShapeInfo{CrownShape::Blobs, "blobs", "the crown's own surface, reduced",
                   CrownHulls::Never},
    CrownShapeInfo{CrownShape::Hulls, "hulls", "a few convex lumps, at every budget",
                   CrownHulls::Always},
};

constexpr auto kNames = [] {
    std::array<std::string_view, kShapes.size()> names{};
    for (std::size_t i = 0; i < kShapes.size(); ++i) names[i] = kShapes[i].name;
    return names;
}();

static_assert([] {
    for (std::size_t i = 0; i < kShapes.size(); ++i)
        if (static_cast<std::size_t>(kShapes[i].shape) != i) return false;
    return true;
}());

}  // namespace

std::span<const CrownShapeInfo> crown_shapes() {
    return kShapes;
}

std::span<const std::string_view> crown_shape_names() {
    return kNames;
}

const CrownShapeInfo& crown_shape_info(CrownShape shape) {
    return kShapes[static_cast<std::size_t>(shape)];
}

const CrownShapeInfo* find_crown_shape(std::string_view name) {
    for (const CrownShapeInfo& info : kShapes)
        if (info.name == name) return &info;
    return nullptr;
}

}  // namespace sylva
