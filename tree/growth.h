// The growth methods a template can name (`growth = "..."`), and the one entry the pipeline
// calls. Adding a method: its own folder with a GrowthMethod (core/growth.h), one line in
// the table in growth.cpp, and its library linked to sylva_tree.
#pragma once

#include <span>
#include <string_view>

#include "core/growth.h"

namespace sylva {

// Every registered method, the default ("lsystem") first.
std::span<const GrowthMethod* const> growth_methods();

// nullptr for an unknown name.
const GrowthMethod* find_growth_method(std::string_view name);

// The template's skeleton, grown by the method it names, at the template's `age`
// (core/tree_age.h: the method grows the mature tree, with `age` 1 for its expressions, and
// the front takes it back). When `mature` is given and the age is below 1, it receives the
// mature skeleton. Throws InputError for an unknown method (naming the known ones) and
// whatever the method throws.
Skeleton grow(const TreeTemplate& tree, const GrowthContext& context = {},
              Skeleton* mature = nullptr);

}  // namespace sylva
