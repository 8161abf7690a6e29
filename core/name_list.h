// Names of a registry's entries as a person reads them in help and error text: "obj, glb or
// ply". Registries (growth methods, meshers, formats, crown shapes) list their names so that
// no message spells them out by hand.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace sylva {

// "a", "a or b", "a, b or c" (with `joint` "or"; "and" for "a, b and c"). `prefix` goes
// before each name (".obj, .glb or .ply").
inline std::string name_list(std::span<const std::string_view> names, std::string_view joint = "or",
                             std::string_view prefix = "") {
    std::string text;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0) text += i + 1 == names.size() ? " " + std::string(joint) + " " : ", ";
        text += std::string(prefix) + std::string(names[i]);
    }
    return text;
}

}  // namespace sylva
