#include "tree/growth.h"

#include <stdexcept>
#include <vector>

#include "colonization/colonization_growth.h"
#include "core/errors.h"
#include "core/param_table.h"
#include "core/tree_age.h"
#include "tree/template_crown.h"
#include "turtle/lsystem_growth.h"

namespace sylva {
namespace {

// The registry: one line per growth method.
const GrowthMethod* const kBuiltIn[] = {
    &lsystem_growth,
    &colonization_growth,
};

std::vector<const GrowthMethod*>& registry() {
    static std::vector<const GrowthMethod*> methods(std::begin(kBuiltIn), std::end(kBuiltIn));
    return methods;
}

bool key_taken(std::string_view key) {
    auto in = [&](const ParamTable& table) {
        for (const ParamInfo& info : table.infos())
            if (info.key == key) return true;
        return false;
    };
    if (in(shared_param_table())) return true;
    for (const GrowthMethod* method : registry())
        if (method->params && in(method->params())) return true;
    return false;
}

}  // namespace

std::span<const GrowthMethod* const> growth_methods() {
    return registry();
}

const GrowthMethod* find_growth_method(std::string_view name) {
    for (const GrowthMethod* method : registry())
        if (method->name == name) return method;
    return nullptr;
}

std::string growth_method_names() {
    std::string known;
    for (const GrowthMethod* m : registry())
        known += (known.empty() ? "" : ", ") + std::string(m->name);
    return known;
}

void register_growth_method(const GrowthMethod& method) {
    if (find_growth_method(method.name))
        throw std::invalid_argument("growth method '" + std::string(method.name) +
                                    "' is registered already");
    if (method.params)
        for (const ParamInfo& info : method.params().infos())
            if (key_taken(info.key))
                throw std::invalid_argument("growth method '" + std::string(method.name) +
                                            "': parameter '" + std::string(info.key) +
                                            "' has another owner");
    registry().push_back(&method);
}

GrowthContext with_template_crowns(const GrowthContext& context) {
    if (context.template_crown) return context;
    GrowthContext with_crowns = context;
    with_crowns.template_crown = [cancel = context.cancel](std::string_view name) {
        return template_crown(name, cancel);
    };
    return with_crowns;
}

Skeleton grow(const TreeTemplate& tree, const GrowthContext& context, Skeleton* mature) {
    const GrowthMethod* method = find_growth_method(tree.growth);
    if (!method)
        throw InputError(
            "unknown growth method '" + tree.growth + "' (known: " + growth_method_names() + ")",
            {tree.source});
    const GrowthContext full = with_template_crowns(context);
    if (tree.params.age >= 1.0) return method->grow(tree, full);
    TreeTemplate grown = tree;
    grown.params.age = 1.0;
    Skeleton whole = method->grow(grown, full);
    Skeleton young = skeleton_at_age(whole, tree.params.age);
    if (mature) *mature = std::move(whole);
    return young;
}

}  // namespace sylva
