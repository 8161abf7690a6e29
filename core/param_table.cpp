#include "core/param_table.h"

#include <array>

namespace sylva {
namespace {

constexpr std::array kGroups{ParamGroup::Shape,     ParamGroup::Branches,    ParamGroup::Crown,
                             ParamGroup::Leaves,    ParamGroup::GameMesh,    ParamGroup::Wind,
                             ParamGroup::Variation, ParamGroup::GrowthMethod};

}  // namespace

std::span<const ParamGroup> param_groups() {
    return kGroups;
}

std::string_view group_title(ParamGroup group) {
    switch (group) {
        case ParamGroup::Shape:
            return "Shape";
        case ParamGroup::Branches:
            return "Branches";
        case ParamGroup::Crown:
            return "Crown";
        case ParamGroup::Leaves:
            return "Leaves";
        case ParamGroup::GameMesh:
            return "Game mesh";
        case ParamGroup::Wind:
            return "Wind";
        case ParamGroup::Variation:
            return "Variation";
        case ParamGroup::GrowthMethod:
            return "Growth method";
    }
    return "";
}

}  // namespace sylva
