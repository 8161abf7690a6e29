#include "forest/forest_scene.h"

#include <tiny_gltf.h>

#include <cmath>
#include <glm/vec3.hpp>
#include <map>
#include <sstream>

#include "core/errors.h"
#include "export/glb_writer.h"

namespace sylva::forest {
namespace {

// The variant as the tree exporter writes it, read back.
tinygltf::Model variant_model(const SceneVariant& variant, const ExportOptions& options) {
    ExportOptions own = options;
    own.model_name = variant.name;
    std::ostringstream out;
    if (variant.levels.size() == 1)
        write_glb(out, variant.levels[0], own);
    else
        write_glb_lods(out, variant.levels, own);
    const std::string bytes = out.str();
    tinygltf::Model model;
    tinygltf::TinyGLTF gltf;
    // Images (the impostor levels' atlases) stay the PNG bytes in their buffer views:
    // merged as they are, never decoded.
    gltf.SetImageLoader([](tinygltf::Image*, int, std::string*, std::string*, int, int,
                           const unsigned char*, int, void*) { return true; },
                        nullptr);
    std::string error, warning;
    if (!gltf.LoadBinaryFromMemory(&model, &error, &warning,
                                   reinterpret_cast<const unsigned char*>(bytes.data()),
                                   static_cast<unsigned int>(bytes.size())))
        throw IoError("cannot read back variant '" + variant.name + "': " + error);
    return model;
}

class SceneBuilder {
  public:
    SceneBuilder() {
        model_.asset.version = "2.0";
        model_.asset.generator = "Sylva forest";
        model_.buffers.emplace_back();
        tinygltf::Node root;
        root.name = "forest";
        model_.nodes.push_back(root);
        tinygltf::Scene scene;
        scene.name = "forest";
        scene.nodes.push_back(0);
        model_.scenes.push_back(scene);
        model_.defaultScene = 0;
    }

    // Merges the variant's buffer, views, accessors, images, materials and meshes; returns
    // the mesh index offset and keeps its nodes for cloning. Materials with textures (the
    // far levels) are the variant's own, named with `variant_name`; the others are shared
    // by name with `material_prefix`.
    void add_variant(tinygltf::Model&& v, const std::string& material_prefix,
                     const std::string& variant_name) {
        align(4);
        const std::size_t byte_base = bytes_.size();
        const int view_base = static_cast<int>(model_.bufferViews.size());
        const int accessor_base = static_cast<int>(model_.accessors.size());
        const int mesh_base = static_cast<int>(model_.meshes.size());
        bytes_.insert(bytes_.end(), v.buffers[0].data.begin(), v.buffers[0].data.end());
        for (tinygltf::BufferView view : v.bufferViews) {
            view.buffer = 0;
            view.byteOffset += byte_base;
            model_.bufferViews.push_back(view);
        }
        for (tinygltf::Accessor accessor : v.accessors) {
            accessor.bufferView += view_base;
            model_.accessors.push_back(accessor);
        }
        const int image_base = static_cast<int>(model_.images.size());
        const int sampler_base = static_cast<int>(model_.samplers.size());
        const int texture_base = static_cast<int>(model_.textures.size());
        for (tinygltf::Image image : v.images) {
            if (image.bufferView >= 0) image.bufferView += view_base;
            model_.images.push_back(std::move(image));
        }
        for (const tinygltf::Sampler& sampler : v.samplers) model_.samplers.push_back(sampler);
        for (tinygltf::Texture texture : v.textures) {
            if (texture.source >= 0) texture.source += image_base;
            if (texture.sampler >= 0) texture.sampler += sampler_base;
            model_.textures.push_back(texture);
        }
        std::vector<int> material_map;
        for (tinygltf::Material material : v.materials) {
            int* const textures[] = {&material.pbrMetallicRoughness.baseColorTexture.index,
                                     &material.pbrMetallicRoughness.metallicRoughnessTexture.index,
                                     &material.normalTexture.index,
                                     &material.occlusionTexture.index,
                                     &material.emissiveTexture.index};
            bool textured = false;
            for (int* index : textures)
                if (*index >= 0) {
                    *index += texture_base;
                    textured = true;
                }
            material.name = (textured ? variant_name : material_prefix) + "_" + material.name;
            auto [found, added] =
                materials_.try_emplace(material.name, static_cast<int>(model_.materials.size()));
            if (added) model_.materials.push_back(material);
            material_map.push_back(found->second);
        }
        for (tinygltf::Mesh mesh : v.meshes) {
            for (tinygltf::Primitive& p : mesh.primitives) {
                for (auto& [name, accessor] : p.attributes) accessor += accessor_base;
                if (p.indices >= 0) p.indices += accessor_base;
                if (p.material >= 0)
                    p.material = material_map[static_cast<std::size_t>(p.material)];
            }
            model_.meshes.push_back(mesh);
        }
        variants_.push_back({std::move(v.nodes), mesh_base});
    }

    // A node under `parent` named `name`; returns its index.
    int add_node(int parent, tinygltf::Node node) {
        model_.nodes.push_back(std::move(node));
        const int index = static_cast<int>(model_.nodes.size()) - 1;
        model_.nodes[static_cast<std::size_t>(parent)].children.push_back(index);
        return index;
    }

    // Copies the children of variant `v`'s root under `parent`, meshes shared. `extend` may
    // add extensions to each node with a mesh.
    // Nodes are named `prefix` + their name (groups too when `prefix_groups`), so the
    // engines' `_LOD<i>` suffixes stay at the end.
    template <class F>
    void clone_children(std::size_t v, int parent, const std::string& prefix, bool prefix_groups,
                        F&& extend) {
        const Prototype& proto = variants_[v];
        clone_children_of(proto, 0, parent, prefix, prefix_groups, extend);
    }

    // Float data in its own view (no target: instance attributes are no vertex data).
    int add_floats(const std::vector<float>& values, int components, int type) {
        align(4);
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = bytes_.size();
        view.byteLength = values.size() * sizeof(float);
        const auto* p = reinterpret_cast<const unsigned char*>(values.data());
        bytes_.insert(bytes_.end(), p, p + view.byteLength);
        model_.bufferViews.push_back(view);
        tinygltf::Accessor accessor;
        accessor.bufferView = static_cast<int>(model_.bufferViews.size()) - 1;
        accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        accessor.type = type;
        accessor.count = values.size() / static_cast<std::size_t>(components);
        model_.accessors.push_back(accessor);
        return static_cast<int>(model_.accessors.size()) - 1;
    }

    void use(const std::string& extension) { model_.extensionsUsed.push_back(extension); }

    // A root node in a scene of its own (after the default one); returns the node.
    int add_scene(const std::string& name) {
        tinygltf::Node root;
        root.name = name;
        model_.nodes.push_back(root);
        const int index = static_cast<int>(model_.nodes.size()) - 1;
        tinygltf::Scene scene;
        scene.name = name;
        scene.nodes.push_back(index);
        model_.scenes.push_back(scene);
        return index;
    }

    void write(std::ostream& out) {
        model_.buffers[0].data = std::move(bytes_);
        tinygltf::TinyGLTF gltf;
        if (!gltf.WriteGltfSceneToStream(&model_, out, false, true))
            throw IoError("tinygltf could not write the forest scene");
    }

  private:
    struct Prototype {
        std::vector<tinygltf::Node> nodes;
        int mesh_base = 0;
    };

    template <class F>
    void clone_children_of(const Prototype& proto, int from, int parent, const std::string& prefix,
                           bool prefix_groups, F& extend) {
        for (int child : proto.nodes[static_cast<std::size_t>(from)].children) {
            const tinygltf::Node& source = proto.nodes[static_cast<std::size_t>(child)];
            tinygltf::Node node;
            node.name = (source.mesh >= 0 || prefix_groups ? prefix : "") + source.name;
            node.translation = source.translation;
            node.rotation = source.rotation;
            node.scale = source.scale;
            node.matrix = source.matrix;
            node.extras = source.extras;  // an impostor's layout
            if (source.mesh >= 0) {
                node.mesh = source.mesh + proto.mesh_base;
                extend(node);
            }
            const int index = add_node(parent, std::move(node));
            clone_children_of(proto, child, index, prefix, prefix_groups, extend);
        }
    }

    void align(std::size_t n) {
        while (bytes_.size() % n != 0) bytes_.push_back(0);
    }

    tinygltf::Model model_;
    std::vector<unsigned char> bytes_;
    std::map<std::string, int> materials_;
    std::vector<Prototype> variants_;
};

std::vector<double> yaw_quaternion(float degrees) {
    const double half = 0.5 * static_cast<double>(degrees) * M_PI / 180.0;
    return {0.0, std::sin(half), 0.0, std::cos(half)};
}

}  // namespace

void write_forest_glb(std::ostream& out, std::span<const SceneVariant> variants,
                      std::span<const SceneInstance> instances, Instancing instancing,
                      const ExportOptions& options) {
    SceneBuilder builder;
    for (const SceneVariant& v : variants)
        builder.add_variant(variant_model(v, options), v.material_prefix, v.name);

    // Every reader loads the default scene: a node per tree. Nodes share the variants' meshes.
    for (std::size_t i = 0; i < instances.size(); ++i) {
        const SceneInstance& inst = instances[i];
        tinygltf::Node node;
        node.name = inst.name;
        node.translation = {inst.position.x, inst.position.y, inst.position.z};
        node.rotation = yaw_quaternion(inst.yaw_degrees);
        node.scale = {inst.scale, inst.scale, inst.scale};
        tinygltf::Value::Object extras;
        extras["sylva_variant"] = tinygltf::Value(variants[inst.variant].name);
        extras["sylva_row"] = tinygltf::Value(static_cast<int>(i));
        node.extras = tinygltf::Value(extras);
        const int index = builder.add_node(0, std::move(node));
        builder.clone_children(inst.variant, index, inst.name + "_", true, [](tinygltf::Node&) {});
    }
    if (instancing == Instancing::Gpu) {
        // The same forest GPU-instanced, in a second scene for readers that pick it; the
        // extension is used, never required, so readers without it still load the first.
        builder.use("EXT_mesh_gpu_instancing");
        // Each variant's group stands where its first tree stands and the instances are
        // relative to it: a reader that loads every scene's nodes without the extension
        // (Blender 3.4) draws that one extra copy exactly over the first tree.
        const int root = builder.add_scene("forest_gpu_instanced");
        for (std::size_t v = 0; v < variants.size(); ++v) {
            std::vector<float> translation, rotation, scale;
            const SceneInstance* first = nullptr;
            for (const SceneInstance& inst : instances) {
                if (inst.variant != v) continue;
                if (!first) first = &inst;
                // first^-1 * inst, for a turn about Y and a uniform scale.
                const double turn = -static_cast<double>(first->yaw_degrees) * M_PI / 180.0;
                const glm::dvec3 d =
                    glm::dvec3(inst.position - first->position) / static_cast<double>(first->scale);
                translation.insert(
                    translation.end(),
                    {static_cast<float>(d.x * std::cos(turn) + d.z * std::sin(turn)),
                     static_cast<float>(d.y),
                     static_cast<float>(-d.x * std::sin(turn) + d.z * std::cos(turn))});
                for (double q : yaw_quaternion(inst.yaw_degrees - first->yaw_degrees))
                    rotation.push_back(static_cast<float>(q));
                const float relative = inst.scale / first->scale;
                scale.insert(scale.end(), {relative, relative, relative});
            }
            if (!first) continue;
            tinygltf::Node group;
            group.name = variants[v].name;
            group.translation = {first->position.x, first->position.y, first->position.z};
            group.rotation = yaw_quaternion(first->yaw_degrees);
            group.scale = {first->scale, first->scale, first->scale};
            const int index = builder.add_node(root, std::move(group));
            tinygltf::Value::Object attributes;
            attributes["TRANSLATION"] =
                tinygltf::Value(builder.add_floats(translation, 3, TINYGLTF_TYPE_VEC3));
            attributes["ROTATION"] =
                tinygltf::Value(builder.add_floats(rotation, 4, TINYGLTF_TYPE_VEC4));
            attributes["SCALE"] = tinygltf::Value(builder.add_floats(scale, 3, TINYGLTF_TYPE_VEC3));
            tinygltf::Value::Object extension;
            extension["attributes"] = tinygltf::Value(attributes);
            builder.clone_children(
                v, index, variants[v].name + "_", false, [&](tinygltf::Node& node) {
                    node.extensions["EXT_mesh_gpu_instancing"] = tinygltf::Value(extension);
                });
        }
    }
    builder.write(out);
}

}  // namespace sylva::forest
