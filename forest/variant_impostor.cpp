#include "forest/variant_impostor.h"

#include "export/impostor_level.h"
#include "impostor/impostor_files.h"

namespace sylva::forest {

EngineModel variant_model_levels(const Tree& tree, const FinishedTree& finished,
                                 const PartColors& colors, const ExportOptions& options,
                                 const std::string& variant_name) {
    EngineModel model;
    model.levels = finished_parts(tree, finished, colors);
    if (options.impostor.kind == ImpostorKind::None || model.levels.empty()) return model;
    add_far_levels(model, options);
    // The glb writer names images `<textures.name>_albedo`: prefixed with the variant, each
    // variant's images stay apart in the merged scene, and the layout says so.
    ImpostorImageNames names = impostor_image_names({}, true);
    for (std::string* name : {&names.atlas_albedo, &names.atlas_normal, &names.billboard_albedo,
                              &names.billboard_normal})
        *name = variant_name + "_" + *name;
    for (PartTextures& textures : model.textures) {
        const bool octahedral = textures.name == "impostor";
        textures.name = variant_name + "_" + textures.name;
        textures.extras_json = octahedral ? impostor_layout_json(&*model.atlas, nullptr, names)
                                          : impostor_layout_json(nullptr, &*model.billboard, names);
    }
    return model;
}

}  // namespace sylva::forest
