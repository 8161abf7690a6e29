// Another template's crown as a solid: what colonization's `envelope = "template"` fills.
// Here in tree/ because it needs the template library, the growth registry and the
// pipeline's crown field; growth methods reach it through GrowthContext::template_crown,
// which tree/growth.h's grow() sets, so colonization/ stays free of tree/.
#pragma once

#include <string_view>

#include "core/cancel.h"
#include "core/region.h"

namespace sylva {

// The built-in template `name` grown by its own method (with its own parameters and
// seed), its crown field built as the pipeline builds it (tree_fields), and the region
// where that field is negative, in the template's own frame (root at the origin).
// Throws InputError for an unknown name, a template without crown spheres, or one whose
// own envelope is a template's crown (one level only); Cancelled when the flag is set.
Region template_crown(std::string_view name, CancelFlag cancel = nullptr);

}  // namespace sylva
