// The far levels of a forest's variants (docs/forests.md, docs/impostors.md): each unique
// variant's finished levels, with export options that ask for an impostor, get the far
// levels `sylva export --impostor` appends (export/impostor_level.h), baked once per
// variant, so K variants bake K atlases and every tree standing as that variant draws the
// same images. Their images are named after the variant (`oak_v3_impostor_albedo`), one
// set per variant in the scene, and the layout in the impostor node's extras names them.
// Thread-safe for distinct models.
#pragma once

#include <string>
#include <vector>

#include "export/export_tree.h"

namespace sylva::forest {

// The finished tree's levels as an EngineModel (finished_parts(); the meshes stay owned by
// `tree` and `finished`), with the far levels appended when options.impostor asks for them.
// The model owns the far levels' quads and textures: keep it while its levels are written.
EngineModel variant_model_levels(const Tree& tree, const FinishedTree& finished,
                                 const PartColors& colors, const ExportOptions& options,
                                 const std::string& variant_name);

}  // namespace sylva::forest
