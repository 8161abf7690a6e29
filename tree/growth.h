// The growth methods a template can name (`growth = "..."`), and the one entry the pipeline
// calls. Adding a method: its own folder with a GrowthMethod (core/growth.h) and its
// parameters' table, one line in the table in growth.cpp, and its library linked to
// sylva_tree. Help text, --set, template files, skeleton.json and the studio's controls
// then list its parameters (tree/parameters.h).
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "core/growth.h"

namespace sylva {

// Every registered method, the default ("lsystem") first.
std::span<const GrowthMethod* const> growth_methods();

// nullptr for an unknown name.
const GrowthMethod* find_growth_method(std::string_view name);

// The known names, "lsystem, colonization", for messages.
std::string growth_method_names();

// Adds a method after the built-in ones (a plug-in's, a test's), which must outlive every use.
// Not thread-safe: call before the registry is read from other threads. Throws
// std::invalid_argument when its name or one of its parameters' keys is taken.
void register_growth_method(const GrowthMethod& method);

// The template's skeleton, grown by the method it names, at the template's `age`
// (core/tree_age.h: the method grows the mature tree, with `age` 1 for its expressions, and
// the front takes it back). When `mature` is given and the age is below 1, it receives the
// mature skeleton. Throws InputError for an unknown method (naming the known ones) and
// whatever the method throws.
Skeleton grow(const TreeTemplate& tree, const GrowthContext& context = {},
              Skeleton* mature = nullptr);

// The context grow() gives a method: `context` with GrowthContext::template_crown set to the
// built-in templates' crowns when it has none.
GrowthContext with_template_crowns(const GrowthContext& context);

}  // namespace sylva
