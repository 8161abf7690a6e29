#include "export/fbx_writer.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <glm/geometric.hpp>
#include <map>

#include "core/errors.h"
#include "core/file_set.h"
#include "export/mesh_normals.h"

namespace sylva {
namespace {

using fbx::Node;
using fbx::Value;

constexpr std::uint32_t kVersion = 7400;
// Blender's fixed FileId and creation time, which the FBX SDK accepts (encode_bin.py).
constexpr std::string_view kFileId(
    "\x28\xb3\x2a\xeb\xb6\x24\xcc\xc2\xbf\xc8\xb0\x2a\xa9\x2b\xfc\xf1", 16);
constexpr std::string_view kCreationTime = "1970-01-01 10:00:00:000";
constexpr std::string_view kCreator = "Sylva";
// FBX's "name\x00\x01class" object names.
std::string object_name(const std::string& name, std::string_view type) {
    return name + std::string("\x00\x01", 2) + std::string(type);
}

// A Properties70 entry: P: name, type, label, flags, values...
void property(Node& props, std::string_view name, std::string_view type, std::string_view label,
              std::string_view flags, std::vector<Value> values = {}) {
    std::vector<Value> all = {fbx::string(name), fbx::string(type), fbx::string(label),
                              fbx::string(flags)};
    for (Value& v : values) all.push_back(std::move(v));
    props.add("P", std::move(all));
}

void int_property(Node& props, std::string_view name, std::int32_t v) {
    property(props, name, "int", "Integer", "", {fbx::int32(v)});
}

void enum_property(Node& props, std::string_view name, std::int32_t v) {
    property(props, name, "enum", "", "", {fbx::int32(v)});
}

void double_property(Node& props, std::string_view name, double v) {
    property(props, name, "double", "Number", "", {fbx::float64(v)});
}

void color_property(Node& props, std::string_view name, const glm::vec3& c) {
    property(props, name, "Color", "", "A",
             {fbx::float64(c.r), fbx::float64(c.g), fbx::float64(c.b)});
}

void number_property(Node& props, std::string_view name, double v) {
    property(props, name, "Number", "", "A", {fbx::float64(v)});
}

// The wind the kits' shaders play the wind data in (export/wind_motion.h), as user
// properties: Unity's importer hands a material's to OnPreprocessMaterialDescription,
// Unreal's keeps a node's as the mesh's metadata.
void wind_properties(Node& props, const WindMotion& motion) {
    for (const WindValue& w : wind_values(motion))
        property(props, w.key, "double", "Number", "U", {fbx::float64(w.value)});
}

bool has_wind(const NamedMesh& part) {
    return part.attributes && !part.attributes->wind.empty();
}

// Values of one per-corner layer, stored once each and indexed (IndexToDirect), as Blender
// writes UVs and colours; -0 is stored as 0 so equal values share an entry.
template <std::size_t N>
class IndexedLayer {
  public:
    void add(std::array<double, N> v) {
        for (double& x : v)
            if (x == 0.0) x = 0.0;
        auto [it, added] = index_.try_emplace(v, static_cast<std::int64_t>(index_.size()));
        if (added) values_.insert(values_.end(), v.begin(), v.end());
        indices_.push_back(it->second);
    }
    std::vector<double> values() const { return values_; }
    std::vector<std::int64_t> indices() const { return indices_; }

  private:
    std::map<std::array<double, N>, std::int64_t> index_;
    std::vector<double> values_;
    std::vector<std::int64_t> indices_;
};

// A level's parts as one FBX geometry: vertices appended part after part, one polygon per
// triangle, and per corner the normal, three UV sets and two colour sets.
struct Geometry {
    std::vector<double> vertices;
    std::vector<std::int64_t> polygon_vertex_index;
    std::vector<double> normals;          // per corner, Direct
    std::vector<std::int64_t> materials;  // per polygon
    std::vector<std::int64_t> smoothing;  // per polygon: 0 flat, 1 smooth
    std::array<IndexedLayer<2>, 3> uv;
    std::array<IndexedLayer<4>, 2> colors;
    bool has_uv = false, has_colors = false;
};

Geometry merge(const std::vector<const NamedMesh*>& parts, const ExportOptions& options,
               bool bare) {
    Geometry g;
    for (const NamedMesh* part : parts) {
        const PartAttributes* a = bare ? nullptr : part->attributes;
        if (!a) continue;
        g.has_uv |= !a->uv.empty() || !a->wind.empty();
        g.has_colors |= !a->tint.empty() || !a->wind.empty();
    }
    const bool flat = bare || options.shading == Shading::Flat;
    for (std::size_t p = 0; p < parts.size(); ++p) {
        const Mesh& mesh = *parts[p]->mesh;
        const PartAttributes* a = bare ? nullptr : parts[p]->attributes;
        const auto base = static_cast<std::int64_t>(g.vertices.size() / 3);
        for (const glm::vec3& v : mesh.positions)
            g.vertices.insert(g.vertices.end(), {v.x, v.y, v.z});
        std::vector<glm::vec3> face;
        ShadedMesh shaded;
        if (flat)
            face = face_normals(mesh);
        else
            shaded = smooth_shaded(mesh, options.crease_degrees);
        for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
            const auto& t = mesh.triangles[f];
            g.polygon_vertex_index.insert(g.polygon_vertex_index.end(),
                                          {base + t[0], base + t[1], ~(base + t[2])});
            g.materials.push_back(static_cast<std::int64_t>(p));
            g.smoothing.push_back(flat ? 0 : 1);
            for (std::size_t k = 0; k < 3; ++k) {
                glm::vec3 n = flat ? face[f] : shaded.normals[shaded.mesh.triangles[f][k]];
                if (n == glm::vec3(0.0f)) n = glm::vec3(0, 1, 0);  // a degenerate triangle
                g.normals.insert(g.normals.end(), {n.x, n.y, n.z});
                const std::uint32_t v = t[k];
                const bool uv = a && !a->uv.empty();
                const bool wind = a && !a->wind.empty();
                const glm::vec4 w = wind ? a->wind[v] : glm::vec4(0.0f);
                if (g.has_uv) {
                    const glm::vec2 u = uv ? a->uv[f][k] : glm::vec2(0.0f);
                    g.uv[0].add({u.x, u.y});
                    g.uv[1].add({w.x, w.y});
                    g.uv[2].add({w.z, w.w});
                }
                if (g.has_colors) {
                    const glm::vec3 tint = a && !a->tint.empty() && options.palette_png.empty()
                                               ? a->tint[v]
                                               : glm::vec3(1.0f);
                    g.colors[0].add({tint.r, tint.g, tint.b, 1.0});
                    g.colors[1].add({w.x, w.y, w.z, w.w});
                }
            }
        }
    }
    return g;
}

class FbxBuilder {
  public:
    explicit FbxBuilder(const ExportOptions& options)
        : options_(options), objects_{"Objects", {}, {}}, connections_{"Connections", {}, {}} {}

    void add_levels(const std::vector<ModelParts>& levels) {
        std::vector<const NamedMesh*> collision;
        for (const ModelParts& level : levels)
            for (const NamedMesh& part : level)
                if (part.collision && part.mesh && !part.mesh->triangles.empty())
                    collision.push_back(&part);
        if (levels.size() == 1) {
            mesh_model(options_.model_name, visible_parts(levels[0]), 0, false);
        } else {
            const std::int64_t group = lod_group(options_.model_name, levels.size());
            for (std::size_t i = 0; i < levels.size(); ++i)
                mesh_model(options_.model_name + "_LOD" + std::to_string(i),
                           visible_parts(levels[i]), group, false);
        }
        for (const NamedMesh* part : collision) mesh_model(part->name, {part}, 0, true);
    }

    std::vector<Node> records() {
        std::vector<Node> top;
        header(top);
        top.push_back(global_settings());
        top.push_back(documents());
        top.push_back({"References", {}, {}});
        top.push_back(definitions());
        top.push_back(std::move(objects_));
        top.push_back(std::move(connections_));
        Node takes{"Takes", {}, {}};
        takes.add("Current", {fbx::string("")});
        top.push_back(std::move(takes));
        return top;
    }

  private:
    static std::vector<const NamedMesh*> visible_parts(const ModelParts& level) {
        std::vector<const NamedMesh*> parts;
        for (const NamedMesh& part : level)
            if (!part.collision && part.mesh && !part.mesh->triangles.empty())
                parts.push_back(&part);
        return parts;
    }

    std::int64_t uid() { return next_uid_++; }

    void connect(std::int64_t child, std::int64_t parent) {
        connections_.add("C", {fbx::string("OO"), fbx::int64(child), fbx::int64(parent)});
    }

    Node& object(std::string type, std::int64_t id, const std::string& name,
                 std::string_view class_name, std::string_view subclass) {
        ++counts_[type];
        return objects_.add(type, {fbx::int64(id), fbx::string(object_name(name, class_name)),
                                   fbx::string(subclass)});
    }

    // A Model with an identity transform under `parent` (0: the scene root).
    // With `wind`, the wind's user properties too.
    std::int64_t model(const std::string& name, std::string_view subclass, std::int64_t parent,
                       bool wind = false) {
        const std::int64_t id = uid();
        Node& m = object("Model", id, name, "Model", subclass);
        m.add("Version", {fbx::int32(232)});
        Node& props = m.add("Properties70");
        property(props, "Lcl Translation", "Lcl Translation", "", "A",
                 {fbx::float64(0), fbx::float64(0), fbx::float64(0)});
        property(props, "Lcl Rotation", "Lcl Rotation", "", "A",
                 {fbx::float64(0), fbx::float64(0), fbx::float64(0)});
        property(props, "Lcl Scaling", "Lcl Scaling", "", "A",
                 {fbx::float64(1), fbx::float64(1), fbx::float64(1)});
        int_property(props, "DefaultAttributeIndex", 0);
        enum_property(props, "InheritType", 1);
        if (wind) wind_properties(props, options_.engine.wind_motion);
        m.add("MultiLayer", {fbx::int32(0)});
        m.add("MultiTake", {fbx::int32(0)});
        m.add("Shading", {fbx::character('\x01')});
        m.add("Culling", {fbx::string("CullingOff")});
        connect(id, parent);
        return id;
    }

    // A LodGroup model and its FbxLODGroup attribute: level i+1 takes over below
    // 50% / 2^i of the screen height (ThresholdsUsedAsPercentage), every level shown by its
    // distance (DisplayLevels 0 = UseLOD).
    std::int64_t lod_group(const std::string& name, std::size_t levels) {
        const std::int64_t group = model(name, "LodGroup", 0);
        const std::int64_t id = uid();
        Node& attribute = object("NodeAttribute", id, name, "NodeAttribute", "LodGroup");
        Node& props = attribute.add("Properties70");
        property(props, "MinMaxDistance", "bool", "", "", {fbx::int32(0)});
        property(props, "MinDistance", "double", "Number", "", {fbx::float64(-100.0)});
        property(props, "MaxDistance", "double", "Number", "", {fbx::float64(100.0)});
        property(props, "WorldSpace", "bool", "", "", {fbx::int32(0)});
        property(props, "ThresholdsUsedAsPercentage", "bool", "", "", {fbx::int32(1)});
        double percent = 50.0;
        for (std::size_t i = 0; i + 1 < levels; ++i, percent *= 0.5)
            property(props, "Thresholds|Level" + std::to_string(i), "Distance", "", "",
                     {fbx::float64(percent), fbx::string("cm")});
        for (std::size_t i = 0; i < levels; ++i)
            enum_property(props, "DisplayLevels|Level" + std::to_string(i), 0);
        attribute.add("TypeFlags", {fbx::string("LodGroup")});
        connect(id, group);
        return group;
    }

    std::int64_t material(const NamedMesh& part) {
        const std::string& name = material_name(part);
        if (auto found = materials_.find(name); found != materials_.end()) return found->second;
        const std::int64_t id = uid();
        Node& m = object("Material", id, name, "Material", "");
        m.add("Version", {fbx::int32(102)});
        m.add("ShadingModel", {fbx::string("Phong")});
        m.add("MultiLayer", {fbx::int32(0)});
        Node& props = m.add("Properties70");
        property(props, "ShadingModel", "KString", "", "", {fbx::string("Phong")});
        color_property(props, "DiffuseColor", part.color);
        number_property(props, "DiffuseFactor", 1.0);
        color_property(props, "AmbientColor", glm::vec3(0.0f));
        number_property(props, "AmbientFactor", 0.0);
        color_property(props, "EmissiveColor", glm::vec3(0.0f));
        number_property(props, "EmissiveFactor", 0.0);
        // Bark and leaves are dull: no specular highlight (Blender reads roughness 0.9 from
        // Shininess 1).
        color_property(props, "SpecularColor", glm::vec3(0.0f));
        number_property(props, "SpecularFactor", 0.0);
        number_property(props, "Shininess", 1.0);
        number_property(props, "ShininessExponent", 1.0);
        number_property(props, "Opacity", 1.0);
        number_property(props, "ReflectionFactor", 0.0);
        if (has_wind(part)) wind_properties(props, options_.engine.wind_motion);
        materials_[name] = id;
        return id;
    }

    // A Mesh model named `name` whose geometry holds `parts`, each its own material (none
    // for a collision shape).
    void mesh_model(const std::string& name, const std::vector<const NamedMesh*>& parts,
                    std::int64_t parent, bool bare) {
        if (parts.empty()) return;
        const bool wind = !bare && std::any_of(parts.begin(), parts.end(),
                                               [](const NamedMesh* p) { return has_wind(*p); });
        const std::int64_t id = model(name, "Mesh", parent, wind);
        const std::int64_t geometry_id = uid();
        geometry(geometry_id, name, merge(parts, options_, bare), !bare);
        connect(geometry_id, id);
        if (!bare)
            for (const NamedMesh* part : parts) connect(material(*part), id);
    }

    void geometry(std::int64_t id, const std::string& name, Geometry g, bool with_material) {
        Node& geo = object("Geometry", id, name, "Geometry", "Mesh");
        geo.add("Properties70");
        geo.add("GeometryVersion", {fbx::int32(124)});
        geo.add("Vertices", {fbx::float64_array(std::move(g.vertices))});
        geo.add("PolygonVertexIndex", {fbx::int32_array(std::move(g.polygon_vertex_index))});

        Node& normals = geo.add("LayerElementNormal", {fbx::int32(0)});
        normals.add("Version", {fbx::int32(101)});
        normals.add("Name", {fbx::string("")});
        normals.add("MappingInformationType", {fbx::string("ByPolygonVertex")});
        normals.add("ReferenceInformationType", {fbx::string("Direct")});
        normals.add("Normals", {fbx::float64_array(std::move(g.normals))});

        Node& smoothing = geo.add("LayerElementSmoothing", {fbx::int32(0)});
        smoothing.add("Version", {fbx::int32(102)});
        smoothing.add("Name", {fbx::string("")});
        smoothing.add("MappingInformationType", {fbx::string("ByPolygon")});
        smoothing.add("ReferenceInformationType", {fbx::string("Direct")});
        smoothing.add("Smoothing", {fbx::int32_array(std::move(g.smoothing))});

        static const char* const kColorNames[] = {"tint", "wind"};
        if (g.has_colors)
            for (std::size_t i = 0; i < 2; ++i) {
                Node& c = geo.add("LayerElementColor", {fbx::int32(static_cast<std::int32_t>(i))});
                c.add("Version", {fbx::int32(101)});
                c.add("Name", {fbx::string(kColorNames[i])});
                c.add("MappingInformationType", {fbx::string("ByPolygonVertex")});
                c.add("ReferenceInformationType", {fbx::string("IndexToDirect")});
                c.add("Colors", {fbx::float64_array(g.colors[i].values())});
                c.add("ColorIndex", {fbx::int32_array(g.colors[i].indices())});
            }
        static const char* const kUvNames[] = {"UVMap", "wind_sway_flex", "wind_phase_flutter"};
        if (g.has_uv)
            for (std::size_t i = 0; i < 3; ++i) {
                Node& uv = geo.add("LayerElementUV", {fbx::int32(static_cast<std::int32_t>(i))});
                uv.add("Version", {fbx::int32(101)});
                uv.add("Name", {fbx::string(kUvNames[i])});
                uv.add("MappingInformationType", {fbx::string("ByPolygonVertex")});
                uv.add("ReferenceInformationType", {fbx::string("IndexToDirect")});
                uv.add("UV", {fbx::float64_array(g.uv[i].values())});
                uv.add("UVIndex", {fbx::int32_array(g.uv[i].indices())});
            }
        if (with_material) {
            Node& m = geo.add("LayerElementMaterial", {fbx::int32(0)});
            m.add("Version", {fbx::int32(101)});
            m.add("Name", {fbx::string("")});
            m.add("MappingInformationType", {fbx::string("ByPolygon")});
            m.add("ReferenceInformationType", {fbx::string("IndexToDirect")});
            m.add("Materials", {fbx::int32_array(std::move(g.materials))});
        }

        // The layer table: layer 0 holds the first set of everything, layers 1 and 2 the
        // second colour set and the wind UV sets.
        auto element = [](Node& layer, std::string_view type, std::int32_t index) {
            Node& e = layer.add("LayerElement");
            e.add("Type", {fbx::string(type)});
            e.add("TypedIndex", {fbx::int32(index)});
        };
        const std::int32_t layers = g.has_uv ? 3 : g.has_colors ? 2 : 1;
        for (std::int32_t i = 0; i < layers; ++i) {
            Node& layer = geo.add("Layer", {fbx::int32(i)});
            layer.add("Version", {fbx::int32(100)});
            if (i == 0) {
                element(layer, "LayerElementNormal", 0);
                element(layer, "LayerElementSmoothing", 0);
                if (with_material) element(layer, "LayerElementMaterial", 0);
            }
            if (g.has_colors && i < 2) element(layer, "LayerElementColor", i);
            if (g.has_uv) element(layer, "LayerElementUV", i);
        }
    }

    void header(std::vector<Node>& top) const {
        Node ext{"FBXHeaderExtension", {}, {}};
        ext.add("FBXHeaderVersion", {fbx::int32(1003)});
        ext.add("FBXVersion", {fbx::int32(static_cast<std::int32_t>(kVersion))});
        ext.add("EncryptionType", {fbx::int32(0)});
        Node& stamp = ext.add("CreationTimeStamp");
        for (auto [field, value] : {std::pair{"Version", 1000},
                                    {"Year", 1970},
                                    {"Month", 1},
                                    {"Day", 1},
                                    {"Hour", 10},
                                    {"Minute", 0},
                                    {"Second", 0},
                                    {"Millisecond", 0}})
            stamp.add(field, {fbx::int32(value)});
        ext.add("Creator", {fbx::string(kCreator)});
        Node& info = ext.add("SceneInfo", {fbx::string(object_name("GlobalInfo", "SceneInfo")),
                                           fbx::string("UserData")});
        info.add("Type", {fbx::string("UserData")});
        info.add("Version", {fbx::int32(100)});
        Node& meta = info.add("MetaData");
        meta.add("Version", {fbx::int32(100)});
        for (const char* field : {"Title", "Subject", "Author", "Keywords", "Revision", "Comment"})
            meta.add(field, {fbx::string("")});
        Node& props = info.add("Properties70");
        property(props, "Original|ApplicationVendor", "KString", "", "", {fbx::string("Sylva")});
        property(props, "Original|ApplicationName", "KString", "", "", {fbx::string("Sylva")});
        top.push_back(std::move(ext));
        top.push_back({"FileId", {fbx::raw(kFileId)}, {}});
        top.push_back({"CreationTime", {fbx::string(kCreationTime)}, {}});
        top.push_back({"Creator", {fbx::string(kCreator)}, {}});
    }

    // Y up, Z front, X right (right-handed, glTF's axes); the unit is the metre: 100 cm.
    static Node global_settings() {
        Node settings{"GlobalSettings", {}, {}};
        settings.add("Version", {fbx::int32(1000)});
        Node& props = settings.add("Properties70");
        int_property(props, "UpAxis", 1);
        int_property(props, "UpAxisSign", 1);
        int_property(props, "FrontAxis", 2);
        int_property(props, "FrontAxisSign", 1);
        int_property(props, "CoordAxis", 0);
        int_property(props, "CoordAxisSign", 1);
        int_property(props, "OriginalUpAxis", 1);
        int_property(props, "OriginalUpAxisSign", 1);
        double_property(props, "UnitScaleFactor", 100.0);
        double_property(props, "OriginalUnitScaleFactor", 100.0);
        property(props, "AmbientColor", "ColorRGB", "Color", "",
                 {fbx::float64(0), fbx::float64(0), fbx::float64(0)});
        property(props, "DefaultCamera", "KString", "", "", {fbx::string("Producer Perspective")});
        enum_property(props, "TimeMode", 11);  // 24 frames a second
        property(props, "TimeSpanStart", "KTime", "Time", "", {fbx::int64(0)});
        property(props, "TimeSpanStop", "KTime", "Time", "", {fbx::int64(46186158000)});
        double_property(props, "CustomFrameRate", 24.0);
        return settings;
    }

    Node documents() const {
        Node docs{"Documents", {}, {}};
        docs.add("Count", {fbx::int32(1)});
        Node& doc = docs.add("Document",
                             {fbx::int64(kDocumentId), fbx::string("Scene"), fbx::string("Scene")});
        Node& props = doc.add("Properties70");
        property(props, "SourceObject", "object", "", "");
        property(props, "ActiveAnimStackName", "KString", "", "", {fbx::string("")});
        doc.add("RootNode", {fbx::int64(0)});
        return docs;
    }

    Node definitions() const {
        Node defs{"Definitions", {}, {}};
        defs.add("Version", {fbx::int32(100)});
        std::int32_t total = 1;
        for (const auto& [type, count] : counts_) total += count;
        defs.add("Count", {fbx::int32(total)});
        defs.add("ObjectType", {fbx::string("GlobalSettings")}).add("Count", {fbx::int32(1)});
        for (const auto& [type, count] : counts_)
            defs.add("ObjectType", {fbx::string(type)}).add("Count", {fbx::int32(count)});
        return defs;
    }

    static constexpr std::int64_t kDocumentId = 1000000;
    const ExportOptions& options_;
    Node objects_, connections_;
    std::map<std::string, std::int32_t> counts_;
    std::map<std::string, std::int64_t> materials_;
    std::int64_t next_uid_ = kDocumentId + 1;
};

void add_fbx_file(FileSet& files, const std::filesystem::path& path,
                  const std::vector<ModelParts>& levels, const ExportOptions& options) {
    files.add(path, [&](std::ostream& out) {
        try {
            write_fbx(out, levels, options);
        } catch (const IoError& e) {
            throw IoError("cannot write '" + path.string() + "': " + e.what(), path);
        }
    });
}

}  // namespace

std::vector<fbx::Node> fbx_records(const std::vector<ModelParts>& levels,
                                   const ExportOptions& options) {
    FbxBuilder builder(options);
    builder.add_levels(levels);
    return builder.records();
}

void write_fbx(std::ostream& out, const std::vector<ModelParts>& levels,
               const ExportOptions& options) {
    const std::string bytes = fbx::encode_fbx(fbx_records(levels, options), kVersion);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) throw IoError("the FBX bytes could not be written");
}

const ExportFormat fbx_format = {"fbx", ".fbx", add_fbx_file};

}  // namespace sylva
