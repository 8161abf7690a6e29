#include "export/glb_writer.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>

#include "core/atomic_file.h"
#include "core/errors.h"
#include "core/file_set.h"
#include "export/mesh_normals.h"

namespace sylva {
namespace {

constexpr int kArrayBuffer = 34962;         // GL_ARRAY_BUFFER
constexpr int kElementArrayBuffer = 34963;  // GL_ELEMENT_ARRAY_BUFFER

// Builds one glTF model with a single buffer; every part adds its arrays to it.
class GltfBuilder {
  public:
    explicit GltfBuilder(const ExportOptions& options) : options_(options) {
        model_.asset.version = "2.0";
        model_.asset.generator = "Sylva";
        model_.buffers.emplace_back();
        tinygltf::Node root;
        root.name = options.model_name;
        model_.nodes.push_back(root);
        tinygltf::Scene scene;
        scene.name = options.model_name;
        scene.nodes.push_back(0);
        model_.scenes.push_back(scene);
        model_.defaultScene = 0;
    }

    // A node without a mesh under `parent`; returns its index.
    int add_group(int parent, const std::string& name) {
        tinygltf::Node node;
        node.name = name;
        model_.nodes.push_back(node);
        const int index = static_cast<int>(model_.nodes.size()) - 1;
        model_.nodes[static_cast<std::size_t>(parent)].children.push_back(index);
        return index;
    }

    // A node with the part's mesh under `parent`, named `name`; empty parts are skipped.
    // A mesh handed in twice with the same material and attributes (leaves in every LOD
    // level) is stored once and shared by the nodes. Collision parts get no material.
    void add_part(int parent, const NamedMesh& part, const std::string& name) {
        if (!part.mesh || part.mesh->triangles.empty()) return;
        const int mat = part.collision ? -1 : material(part);
        auto [shared, added] = meshes_.try_emplace({part.mesh, part.attributes, mat},
                                                   static_cast<int>(model_.meshes.size()));
        if (added) add_mesh(part, mat, name);
        const int node = add_group(parent, name);
        model_.nodes[static_cast<std::size_t>(node)].mesh = shared->second;
        if (part.textures && !part.textures->extras_json.empty())
            model_.nodes[static_cast<std::size_t>(node)].extras =
                gltf_value(nlohmann::json::parse(part.textures->extras_json));
    }

    void write(std::ostream& out) {
        model_.buffers[0].data = std::move(bytes_);
        tinygltf::TinyGLTF gltf;
        if (!gltf.WriteGltfSceneToStream(&model_, out, false, true))
            throw IoError("tinygltf could not write the glTF model");
    }

  private:
    // The vertices glTF gets: one per distinct (corner normal, UV) at each mesh vertex, so
    // flat shading splits every triangle apart and smooth shading splits only at creases
    // and UV seams. `source` is the mesh vertex each one copies.
    struct Vertices {
        std::vector<glm::vec3> positions, normals;
        std::vector<glm::vec2> uv;
        std::vector<std::uint32_t> source;
        std::vector<std::uint32_t> indices;
    };

    Vertices vertices(const NamedMesh& part) const {
        const Mesh& mesh = *part.mesh;
        const PartAttributes* attributes = part.collision ? nullptr : part.attributes;
        const bool with_uv = attributes && !attributes->uv.empty();
        Vertices out;
        if (part.collision) {  // shared vertices: a closed hull, no normals needed
            out.positions = mesh.positions;
            for (const auto& t : mesh.triangles)
                out.indices.insert(out.indices.end(), t.begin(), t.end());
            return out;
        }
        auto add = [&](std::uint32_t source, const glm::vec3& normal, const glm::vec2& uv) {
            out.indices.push_back(static_cast<std::uint32_t>(out.positions.size()));
            out.positions.push_back(mesh.positions[source]);
            out.normals.push_back(normal);
            if (with_uv) out.uv.push_back(uv);
            out.source.push_back(source);
        };
        if (options_.shading == Shading::Flat) {
            const std::vector<glm::vec3> face = face_normals(mesh);
            for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
                for (std::size_t k = 0; k < 3; ++k)
                    // A degenerate triangle has no normal; glTF wants unit length.
                    add(mesh.triangles[f][k],
                        face[f] == glm::vec3(0.0f) ? glm::vec3(0, 1, 0) : face[f],
                        with_uv ? attributes->uv[f][k] : glm::vec2(0.0f));
            return out;
        }
        const ShadedMesh shaded = smooth_shaded(mesh, options_.crease_degrees);
        std::map<std::tuple<std::uint32_t, float, float>, std::uint32_t> welded;
        for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
            for (std::size_t k = 0; k < 3; ++k) {
                const std::uint32_t corner = shaded.mesh.triangles[f][k];
                const glm::vec2 uv = with_uv ? attributes->uv[f][k] : glm::vec2(0.0f);
                auto [found, added] = welded.try_emplace(
                    {corner, uv.x, uv.y}, static_cast<std::uint32_t>(out.positions.size()));
                if (added) {
                    add(mesh.triangles[f][k], shaded.normals[corner], uv);
                } else {
                    out.indices.push_back(found->second);
                }
            }
        return out;
    }

    // Per vertex, the direction of increasing u and in w the sign that makes
    // cross(normal, tangent) run up the image (v up, as PartAttributes' v runs; glTF's
    // normal maps are +Y up): a normal map then reads the same in every engine, as the
    // validator asks, instead of a tangent space each runtime generates its own way.
    static std::vector<glm::vec4> tangents(const Vertices& v) {
        std::vector<glm::vec4> out(v.positions.size(), glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
        for (std::size_t k = 0; k + 2 < v.indices.size(); k += 3) {
            const std::uint32_t a = v.indices[k], b = v.indices[k + 1], c = v.indices[k + 2];
            const glm::vec3 e1 = v.positions[b] - v.positions[a],
                            e2 = v.positions[c] - v.positions[a];
            const glm::vec2 d1 = v.uv[b] - v.uv[a], d2 = v.uv[c] - v.uv[a];
            const float det = d1.x * d2.y - d2.x * d1.y;
            if (det == 0.0f) continue;  // no UV area: keep the default
            const glm::vec3 t = (e1 * d2.y - e2 * d1.y) / det;
            const glm::vec3 bitangent = (e2 * d1.x - e1 * d2.x) / det;
            for (std::uint32_t i : {a, b, c}) {
                const glm::vec3& n = v.normals[i];
                const glm::vec3 orthogonal = t - n * glm::dot(n, t);  // Gram-Schmidt
                const float length = glm::length(orthogonal);
                if (!(length > 0.0f)) continue;
                const float w =
                    glm::dot(glm::cross(n, orthogonal), bitangent) < 0.0f ? -1.0f : 1.0f;
                out[i] = glm::vec4(orthogonal / length, w);
            }
        }
        return out;
    }

    void add_mesh(const NamedMesh& part, int mat, const std::string& name) {
        const Vertices v = vertices(part);
        tinygltf::Primitive primitive;
        primitive.mode = TINYGLTF_MODE_TRIANGLES;
        primitive.attributes["POSITION"] = add_vec3(v.positions, true);
        if (!part.collision) {
            primitive.attributes["NORMAL"] = add_vec3(v.normals, false);
            if (part.textures && !part.textures->normal_png.empty() && !v.uv.empty())
                primitive.attributes["TANGENT"] = add_floats(tangents(v));
            add_engine_attributes(primitive, part, v);
            primitive.material = mat;
        }
        primitive.indices = add_indices(v.indices, v.positions.size());

        tinygltf::Mesh gltf_mesh;
        gltf_mesh.name = name;
        gltf_mesh.primitives.push_back(primitive);
        model_.meshes.push_back(gltf_mesh);
    }

    // TEXCOORD_0 (UVs), COLOR_0 (tint) and the wind in the profile's channel. glTF wants
    // each set numbered from 0 without gaps, so wind in TEXCOORD_1/2 comes with a
    // TEXCOORD_0 (zeros without UVs) and wind in COLOR_1 with a COLOR_0 (white without a
    // tint).
    void add_engine_attributes(tinygltf::Primitive& primitive, const NamedMesh& part,
                               const Vertices& v) {
        if (!part.attributes) return;
        const PartAttributes& a = *part.attributes;
        const bool wind = !a.wind.empty();
        const WindChannel channel = profile_info(options_.profile).wind;
        if (!v.uv.empty() || (wind && channel == WindChannel::TexCoord12)) {
            // PartAttributes' v runs up the image (OBJ, OpenGL); glTF's runs down.
            std::vector<glm::vec2> uv(v.positions.size(), glm::vec2(0.0f));
            for (std::size_t i = 0; i < v.uv.size(); ++i) uv[i] = {v.uv[i].x, 1.0f - v.uv[i].y};
            primitive.attributes["TEXCOORD_0"] = add_floats(uv);
        }
        // With a palette the texture carries the tint.
        const bool tinted = !a.tint.empty() && options_.palette_png.empty();
        if (tinted || (wind && channel == WindChannel::Color1)) {
            std::vector<glm::vec4> tint;
            for (std::uint32_t s : v.source)
                tint.push_back(glm::vec4(tinted ? a.tint[s] : glm::vec3(1.0f), 1.0f));
            primitive.attributes["COLOR_0"] = add_normalized<std::uint8_t>(tint);
        }
        if (!wind) return;
        if (channel == WindChannel::Color1) {
            std::vector<glm::vec4> w;
            for (std::uint32_t s : v.source) w.push_back(a.wind[s]);
            primitive.attributes["COLOR_1"] = add_normalized<std::uint8_t>(w);
        } else {
            const ProfileInfo& profile = profile_info(options_.profile);
            // Unity's importers flip v on every set: written flipped, it arrives as in the
            // other profiles.
            auto v_of = [&](float y) { return profile.wind_v_flipped ? 1.0f - y : y; };
            std::vector<glm::vec2> w1, w2;
            for (std::uint32_t s : v.source) {
                w1.push_back({a.wind[s].x, v_of(a.wind[s].y)});
                w2.push_back({a.wind[s].z, v_of(a.wind[s].w)});
            }
            if (profile.wind_as_floats) {
                primitive.attributes["TEXCOORD_1"] = add_floats(w1);
                primitive.attributes["TEXCOORD_2"] = add_floats(w2);
            } else {
                primitive.attributes["TEXCOORD_1"] = add_normalized<std::uint16_t>(w1);
                primitive.attributes["TEXCOORD_2"] = add_normalized<std::uint16_t>(w2);
            }
        }
    }

    // Values in [0, 1] as normalized 8- or 16-bit integers: colours and wind need no more,
    // and a vertex takes 4 bytes per attribute instead of 8-16 (glTF wants each element
    // 4-byte aligned, hence vec4 bytes and vec2 shorts).
    template <class Int, class Vec>
    int add_normalized(const std::vector<Vec>& values) {
        static_assert(sizeof(Int) * Vec::length() % 4 == 0);
        constexpr float top = static_cast<float>(std::numeric_limits<Int>::max());
        std::vector<Int> ints;
        ints.reserve(values.size() * Vec::length());
        for (const Vec& value : values)
            for (int c = 0; c < Vec::length(); ++c) {
                // Rounded half up, as lround does for these non-negative values (the sum is
                // exact in double), without its library call (costly in a hot loop); NaN as 0.
                const float scaled = (value[c] > 0.0f ? std::min(value[c], 1.0f) : 0.0f) * top;
                ints.push_back(static_cast<Int>(static_cast<double>(scaled) + 0.5));
            }
        tinygltf::Accessor accessor;
        accessor.bufferView = add_view(ints.data(), ints.size() * sizeof(Int), kArrayBuffer);
        accessor.componentType = sizeof(Int) == 1 ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE
                                                  : TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
        accessor.normalized = true;
        accessor.type = Vec::length() == 2 ? TINYGLTF_TYPE_VEC2 : TINYGLTF_TYPE_VEC4;
        accessor.count = values.size();
        model_.accessors.push_back(accessor);
        return static_cast<int>(model_.accessors.size()) - 1;
    }

    // A float vertex attribute of 2, 3 or 4 components.
    template <class Vec>
    int add_floats(const std::vector<Vec>& values) {
        static_assert(sizeof(Vec) == Vec::length() * sizeof(float));
        tinygltf::Accessor accessor;
        accessor.bufferView = add_view(values.data(), values.size() * sizeof(Vec), kArrayBuffer);
        accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        accessor.type = Vec::length() == 2   ? TINYGLTF_TYPE_VEC2
                        : Vec::length() == 3 ? TINYGLTF_TYPE_VEC3
                                             : TINYGLTF_TYPE_VEC4;
        accessor.count = values.size();
        model_.accessors.push_back(accessor);
        return static_cast<int>(model_.accessors.size()) - 1;
    }

    // Appends raw bytes to the buffer as one buffer view (4-byte aligned).
    int add_view(const void* data, std::size_t size, int target) {
        while (bytes_.size() % 4 != 0) bytes_.push_back(0);
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = bytes_.size();
        view.byteLength = size;
        view.target = target;
        const auto* p = static_cast<const unsigned char*>(data);
        bytes_.insert(bytes_.end(), p, p + size);
        model_.bufferViews.push_back(view);
        return static_cast<int>(model_.bufferViews.size()) - 1;
    }

    int add_vec3(const std::vector<glm::vec3>& values, bool with_bounds) {
        static_assert(sizeof(glm::vec3) == 3 * sizeof(float));
        tinygltf::Accessor accessor;
        accessor.bufferView =
            add_view(values.data(), values.size() * sizeof(glm::vec3), kArrayBuffer);
        accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        accessor.type = TINYGLTF_TYPE_VEC3;
        accessor.count = values.size();
        if (with_bounds) {  // required for POSITION
            glm::vec3 lo(std::numeric_limits<float>::max()),
                hi(std::numeric_limits<float>::lowest());
            for (const glm::vec3& v : values) {
                lo = glm::min(lo, v);
                hi = glm::max(hi, v);
            }
            accessor.minValues = {lo.x, lo.y, lo.z};
            accessor.maxValues = {hi.x, hi.y, hi.z};
        }
        model_.accessors.push_back(accessor);
        return static_cast<int>(model_.accessors.size()) - 1;
    }

    // 16-bit indices when they fit (half the bytes), else 32-bit.
    int add_indices(const std::vector<std::uint32_t>& indices, std::size_t vertex_count) {
        tinygltf::Accessor accessor;
        accessor.type = TINYGLTF_TYPE_SCALAR;
        accessor.count = indices.size();
        if (vertex_count <= 65535) {
            std::vector<std::uint16_t> small(indices.begin(), indices.end());
            accessor.bufferView = add_view(small.data(), small.size() * 2, kElementArrayBuffer);
            accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
        } else {
            accessor.bufferView = add_view(indices.data(), indices.size() * 4, kElementArrayBuffer);
            accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        }
        model_.accessors.push_back(accessor);
        return static_cast<int>(model_.accessors.size()) - 1;
    }

    // One material per material name, shared by every LOD level.
    int material(const NamedMesh& part) {
        const std::string& name = material_name(part);
        auto found = materials_.find(name);
        if (found != materials_.end()) return found->second;
        tinygltf::Material m;
        m.name = name;
        m.pbrMetallicRoughness.baseColorFactor = {part.color.r, part.color.g, part.color.b, 1.0};
        if (part.textures) {  // the images carry colour and normals, alpha-tested
            const PartTextures& t = *part.textures;
            m.pbrMetallicRoughness.baseColorFactor = {1.0, 1.0, 1.0, 1.0};
            m.pbrMetallicRoughness.baseColorTexture.index =
                image_texture(t.name + "_albedo", t.albedo_png);
            if (!t.normal_png.empty())
                m.normalTexture.index = image_texture(t.name + "_normal", t.normal_png);
            m.alphaMode = "MASK";
            m.alphaCutoff = t.alpha_cutoff;
        } else if (!options_.palette_png.empty()) {  // the swatches carry the colour
            m.pbrMetallicRoughness.baseColorFactor = {1.0, 1.0, 1.0, 1.0};
            m.pbrMetallicRoughness.baseColorTexture.index = palette_texture();
        }
        m.pbrMetallicRoughness.metallicFactor = 0.0;  // bark and leaves are dielectric
        m.pbrMetallicRoughness.roughnessFactor = 0.9;
        m.doubleSided = !part.closed;
        // The wind the kits' shaders play the part's wind data in (export/wind_motion.h).
        if (part.attributes && !part.attributes->wind.empty()) {
            tinygltf::Value::Object extras;
            for (const WindValue& w : wind_values(options_.engine.wind_motion))
                extras[std::string(w.key)] = tinygltf::Value(w.value);
            m.extras = tinygltf::Value(std::move(extras));
        }
        model_.materials.push_back(m);
        const int index = static_cast<int>(model_.materials.size()) - 1;
        materials_[name] = index;
        return index;
    }

    // A PNG as an image and a texture with a trilinear, clamped sampler (made once, shared):
    // the impostors' textures, minified far away. Returns the texture's index.
    int image_texture(const std::string& name, const std::vector<std::uint8_t>& png) {
        if (mipmapped_sampler_ < 0) {
            tinygltf::Sampler sampler;
            sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
            sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
            sampler.wrapS = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
            sampler.wrapT = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
            model_.samplers.push_back(sampler);
            mipmapped_sampler_ = static_cast<int>(model_.samplers.size()) - 1;
        }
        tinygltf::Image image;
        image.name = name;
        image.mimeType = "image/png";
        image.bufferView = add_view(png.data(), png.size(), 0);
        model_.images.push_back(image);
        tinygltf::Texture texture;
        texture.name = name;
        texture.source = static_cast<int>(model_.images.size()) - 1;
        texture.sampler = mipmapped_sampler_;
        model_.textures.push_back(texture);
        return static_cast<int>(model_.textures.size()) - 1;
    }

    // JSON (extras) as tinygltf's value tree.
    static tinygltf::Value gltf_value(const nlohmann::json& j) {
        if (j.is_object()) {
            tinygltf::Value::Object object;
            for (const auto& [key, value] : j.items()) object[key] = gltf_value(value);
            return tinygltf::Value(std::move(object));
        }
        if (j.is_array()) {
            tinygltf::Value::Array array;
            for (const auto& value : j) array.push_back(gltf_value(value));
            return tinygltf::Value(std::move(array));
        }
        if (j.is_string()) return tinygltf::Value(j.get<std::string>());
        if (j.is_boolean()) return tinygltf::Value(j.get<bool>());
        if (j.is_number_integer()) return tinygltf::Value(j.get<int>());
        if (j.is_number()) return tinygltf::Value(j.get<double>());
        return {};
    }

    // The palette PNG as an image, texture and (nearest, clamped) sampler; made once.
    int palette_texture() {
        if (palette_texture_ >= 0) return palette_texture_;
        tinygltf::Image image;
        image.name = "palette";
        image.mimeType = "image/png";
        image.bufferView = add_view(options_.palette_png.data(), options_.palette_png.size(), 0);
        model_.images.push_back(image);
        tinygltf::Sampler sampler;
        sampler.magFilter = TINYGLTF_TEXTURE_FILTER_NEAREST;
        sampler.minFilter = TINYGLTF_TEXTURE_FILTER_NEAREST;
        sampler.wrapS = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
        sampler.wrapT = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
        model_.samplers.push_back(sampler);
        tinygltf::Texture texture;
        texture.source = static_cast<int>(model_.images.size()) - 1;
        texture.sampler = static_cast<int>(model_.samplers.size()) - 1;
        model_.textures.push_back(texture);
        palette_texture_ = static_cast<int>(model_.textures.size()) - 1;
        return palette_texture_;
    }

    const ExportOptions& options_;
    tinygltf::Model model_;
    std::vector<unsigned char> bytes_;
    std::map<std::string, int> materials_;
    int palette_texture_ = -1;
    int mipmapped_sampler_ = -1;
    std::map<std::tuple<const Mesh*, const PartAttributes*, int>, int> meshes_;
};

// IoErrors from serialising, with the path in front.
template <class F>
void with_path(const std::filesystem::path& path, F&& f) {
    try {
        f();
    } catch (const IoError& e) {
        throw IoError("cannot write '" + path.string() + "': " + e.what(), path);
    }
}

}  // namespace

void write_glb(std::ostream& out, const std::vector<NamedMesh>& parts,
               const ExportOptions& options) {
    GltfBuilder builder(options);
    for (const NamedMesh& part : parts) builder.add_part(0, part, part.name);
    builder.write(out);
}

void write_glb(const std::filesystem::path& path, const std::vector<NamedMesh>& parts,
               const ExportOptions& options) {
    write_file_atomically(
        path, [&](std::ostream& out) { with_path(path, [&] { write_glb(out, parts, options); }); });
}

void write_glb_lods(std::ostream& out, const std::vector<std::vector<NamedMesh>>& levels,
                    const ExportOptions& options) {
    GltfBuilder builder(options);
    for (std::size_t i = 0; i < levels.size(); ++i) {
        const std::string suffix = "_LOD" + std::to_string(i);
        const int level = builder.add_group(0, options.model_name + suffix);
        for (const NamedMesh& part : levels[i])
            if (!part.collision) builder.add_part(level, part, part.name + suffix);
    }
    // Collision belongs to the model, not to a level: once, under the root.
    for (const auto& level : levels)
        for (const NamedMesh& part : level)
            if (part.collision) builder.add_part(0, part, part.name);
    builder.write(out);
}

void write_glb_lods(const std::filesystem::path& path,
                    const std::vector<std::vector<NamedMesh>>& levels,
                    const ExportOptions& options) {
    write_file_atomically(path, [&](std::ostream& out) {
        with_path(path, [&] { write_glb_lods(out, levels, options); });
    });
}

namespace {

void add_glb_file(FileSet& files, const std::filesystem::path& path,
                  const std::vector<ModelParts>& levels, const ExportOptions& options) {
    files.add(path, [&](std::ostream& out) {
        with_path(path, [&] {
            if (levels.size() == 1)
                write_glb(out, levels[0], options);
            else
                write_glb_lods(out, levels, options);
        });
    });
}

}  // namespace

const ExportFormat glb_format = {"glb", ".glb", add_glb_file};

}  // namespace sylva
