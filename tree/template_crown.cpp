#include "tree/template_crown.h"

#include <memory>
#include <string>

#include "core/errors.h"
#include "tree/growth.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"

namespace sylva {

Region template_crown(std::string_view name, CancelFlag cancel) {
    const std::string wanted(name);
    const TreeTemplate* other = nullptr;
    for (const TreeTemplate* t : builtin_templates())
        if (t->name == wanted) other = t;
    if (!other) throw InputError("envelope_template '" + wanted + "' is not a built-in template");
    GrowthContext context;
    context.cancel = cancel;
    // A crown inside a crown inside ...: one level is enough and cannot loop.
    context.template_crown = [wanted](std::string_view inner) -> Region {
        throw InputError("envelope_template '" + wanted + "' itself fills the crown of '" +
                         std::string(inner) + "'; a template's crown envelope cannot nest");
    };
    const Skeleton skeleton = grow(*other, context);
    TreeFields fields = tree_fields(skeleton, other->params);
    if (!fields.crown)
        throw InputError("envelope_template '" + wanted +
                         "' has no crown (no tips or sphere_diameter 0)");
    auto crown = std::make_shared<const SphereField>(std::move(*fields.crown));
    return {fields.crown_box, [crown](const glm::vec3& p) { return (*crown)(p) < 0.0f; }};
}

}  // namespace sylva
