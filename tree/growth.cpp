#include "tree/growth.h"

#include "colonization/colonization_growth.h"
#include "core/errors.h"
#include "core/tree_age.h"
#include "tree/template_crown.h"
#include "turtle/lsystem_growth.h"

namespace sylva {
namespace {

// The registry: one line per growth method.
const GrowthMethod* const kMethods[] = {
    &lsystem_growth,
    &colonization_growth,
};

}  // namespace

std::span<const GrowthMethod* const> growth_methods() {
    return kMethods;
}

const GrowthMethod* find_growth_method(std::string_view name) {
    for (const GrowthMethod* method : kMethods)
        if (method->name == name) return method;
    return nullptr;
}

namespace {

Skeleton grow_mature(const GrowthMethod& method, const TreeTemplate& tree,
                     const GrowthContext& context) {
    if (context.template_crown) return method.grow(tree, context);
    GrowthContext with_crowns = context;
    with_crowns.template_crown = [cancel = context.cancel](std::string_view name) {
        return template_crown(name, cancel);
    };
    return method.grow(tree, with_crowns);
}

}  // namespace

Skeleton grow(const TreeTemplate& tree, const GrowthContext& context, Skeleton* mature) {
    const GrowthMethod* method = find_growth_method(tree.growth);
    if (!method) {
        std::string known;
        for (const GrowthMethod* m : kMethods)
            known += (known.empty() ? "" : ", ") + std::string(m->name);
        throw InputError("unknown growth method '" + tree.growth + "' (known: " + known + ")",
                         {tree.source});
    }
    if (tree.params.age >= 1.0) return grow_mature(*method, tree, context);
    TreeTemplate grown = tree;
    grown.params.age = 1.0;
    Skeleton full = grow_mature(*method, grown, context);
    Skeleton young = skeleton_at_age(full, tree.params.age);
    if (mature) *mature = std::move(full);
    return young;
}

}  // namespace sylva
