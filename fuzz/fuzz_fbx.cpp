// The FBX writer (export/fbx_writer.h) and its container (export/fbx_document.h), round
// trip: random parts (positions within 100 km, triangles on them, UVs, tints and wind in
// [0, 1], collision shapes), one to four levels, are written and read back with
// decode_fbx(); every geometry must give back its vertices, triangles, per-corner UVs and
// colours and material indices exactly, every level its name. The input's tail is also
// read as an FBX file on its own, where InputError is the only allowed failure.
#include <fuzzer/FuzzedDataProvider.h>

#include <deque>
#include <map>

#include "export/fbx_document.h"
#include "export/fbx_writer.h"
#include "fuzz_guard.h"

namespace {

using namespace sylva;

float unit(FuzzedDataProvider& in) {
    return in.ConsumeFloatingPointInRange<float>(0.0f, 1.0f);
}

struct Parts {
    std::deque<Mesh> meshes;
    std::deque<PartAttributes> attributes;
    std::vector<ModelParts> levels;
};

Parts random_parts(FuzzedDataProvider& in) {
    Parts p;
    const int levels = in.ConsumeIntegralInRange(1, 4);
    for (int l = 0; l < levels; ++l) {
        ModelParts& level = p.levels.emplace_back();
        const int parts = in.ConsumeIntegralInRange(0, 3);
        for (int k = 0; k < parts; ++k) {
            Mesh& mesh = p.meshes.emplace_back();
            const int vertices = in.ConsumeIntegralInRange(3, 40);
            for (int v = 0; v < vertices; ++v) {
                auto c = [&] { return in.ConsumeFloatingPointInRange<float>(-1e5f, 1e5f); };
                const float x = c(), y = c(), z = c();
                mesh.positions.push_back({x, y, z});
            }
            const int triangles = in.ConsumeIntegralInRange(1, 40);
            for (int t = 0; t < triangles; ++t) {
                auto v = [&] { return in.ConsumeIntegralInRange<std::uint32_t>(0, vertices - 1); };
                const std::uint32_t a = v(), b = v(), c = v();
                mesh.triangles.push_back({a, b, c});
            }
            PartAttributes& a = p.attributes.emplace_back();
            if (in.ConsumeBool())
                for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
                    a.uv.push_back({glm::vec2(unit(in), unit(in)), glm::vec2(unit(in), unit(in)),
                                    glm::vec2(unit(in), unit(in))});
            if (in.ConsumeBool())
                for (int v = 0; v < vertices; ++v) a.tint.push_back({unit(in), unit(in), unit(in)});
            if (in.ConsumeBool())
                for (int v = 0; v < vertices; ++v)
                    a.wind.push_back({unit(in), unit(in), unit(in), unit(in)});
            NamedMesh part{"part" + std::to_string(k), &mesh,
                           glm::vec3(unit(in), unit(in), unit(in)), in.ConsumeBool(), &a};
            part.collision = l == 0 && in.ConsumeIntegralInRange(0, 3) == 0;
            if (part.collision) part.name = "UCX_tree_" + std::to_string(k);
            level.push_back(part);
        }
    }
    return p;
}

const fbx::Node* child(const fbx::Node& n, std::string_view name) {
    const fbx::Node* c = n.find(name);
    if (!c || c->values.empty()) fuzz_finding("a geometry record is missing");
    return c;
}

// Checks one geometry against the parts it was made of.
void check_geometry(const fbx::Node& geo, const std::vector<const NamedMesh*>& parts, bool bare) {
    const std::vector<double>& vertices = child(geo, "Vertices")->values[0].reals;
    const std::vector<std::int64_t>& polygons =
        child(geo, "PolygonVertexIndex")->values[0].integers;
    bool any_uv = false, any_color = false;
    for (const NamedMesh* p : parts)
        if (!bare && p->attributes) {
            any_uv |= !p->attributes->uv.empty() || !p->attributes->wind.empty();
            any_color |= !p->attributes->tint.empty() || !p->attributes->wind.empty();
        }
    std::map<std::int64_t, const fbx::Node*> uv, color;
    for (const fbx::Node& c : geo.children) {
        if (c.name == "LayerElementUV") uv[c.values.at(0).integer] = &c;
        if (c.name == "LayerElementColor") color[c.values.at(0).integer] = &c;
    }
    if (uv.size() != (any_uv ? 3u : 0u) || color.size() != (any_color ? 2u : 0u))
        fuzz_finding("UV or colour sets missing or extra");
    std::size_t vertex = 0, corner = 0, polygon = 0;
    for (std::size_t k = 0; k < parts.size(); ++k) {
        const Mesh& mesh = *parts[k]->mesh;
        const PartAttributes* a = bare ? nullptr : parts[k]->attributes;
        for (const glm::vec3& p : mesh.positions) {
            if (3 * vertex + 2 >= vertices.size() || vertices[3 * vertex] != p.x ||
                vertices[3 * vertex + 1] != p.y || vertices[3 * vertex + 2] != p.z)
                fuzz_finding("a vertex does not read back");
            ++vertex;
        }
        const std::size_t base = vertex - mesh.positions.size();
        for (std::size_t f = 0; f < mesh.triangles.size(); ++f, ++polygon) {
            if (!bare && child(geo, "LayerElementMaterial")
                                 ->find("Materials")
                                 ->values.at(0)
                                 .integers.at(polygon) != static_cast<std::int64_t>(k))
                fuzz_finding("a polygon's material index is wrong");
            for (std::size_t c = 0; c < 3; ++c, ++corner) {
                const std::uint32_t v = mesh.triangles[f][c];
                const std::int64_t want = static_cast<std::int64_t>(base + v);
                const std::int64_t got = polygons.at(corner);
                if ((c == 2 ? ~got : got) != want) fuzz_finding("a triangle does not read back");
                auto layer = [&](const fbx::Node* n, const char* data, const char* index,
                                 std::size_t width) {
                    const std::int64_t i = n->find(index)->values.at(0).integers.at(corner);
                    const std::vector<double>& d = n->find(data)->values.at(0).reals;
                    std::vector<double> out;
                    for (std::size_t w = 0; w < width; ++w)
                        out.push_back(d.at(static_cast<std::size_t>(i) * width + w));
                    return out;
                };
                const glm::vec4 wind = a && !a->wind.empty() ? a->wind[v] : glm::vec4(0.0f);
                if (any_uv) {
                    const glm::vec2 u = a && !a->uv.empty() ? a->uv[f][c] : glm::vec2(0.0f);
                    if (layer(uv[0], "UV", "UVIndex", 2) != std::vector<double>{u.x, u.y} ||
                        layer(uv[1], "UV", "UVIndex", 2) != std::vector<double>{wind.x, wind.y} ||
                        layer(uv[2], "UV", "UVIndex", 2) != std::vector<double>{wind.z, wind.w})
                        fuzz_finding("a UV does not read back");
                }
                if (any_color) {
                    const glm::vec3 t = a && !a->tint.empty() ? a->tint[v] : glm::vec3(1.0f);
                    if (layer(color[0], "Colors", "ColorIndex", 4) !=
                            std::vector<double>{t.r, t.g, t.b, 1.0} ||
                        layer(color[1], "Colors", "ColorIndex", 4) !=
                            std::vector<double>{wind.x, wind.y, wind.z, wind.w})
                        fuzz_finding("a colour does not read back");
                }
            }
        }
    }
    if (vertex * 3 != vertices.size() || corner != polygons.size())
        fuzz_finding("a geometry has more than its parts");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider in(data, size);
    const Parts parts = random_parts(in);
    ExportOptions options;
    options.shading = in.ConsumeBool() ? Shading::Flat : Shading::Smooth;
    const std::string bytes = fbx::encode_fbx(fbx_records(parts.levels, options));
    fbx::Document doc;
    try {
        doc = fbx::decode_fbx(bytes);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "sylva fuzz: the FBX writer's bytes do not read back: %s\n", e.what());
        std::abort();
    }
    const fbx::Node* objects = nullptr;
    for (const fbx::Node& n : doc.top)
        if (n.name == "Objects") objects = &n;
    if (!objects || doc.version != 7400) fuzz_finding("no Objects record or a wrong version");
    // Geometries in the order the writer makes them: levels, then collision shapes.
    std::vector<std::pair<std::vector<const NamedMesh*>, bool>> expected;
    std::vector<const NamedMesh*> collision;
    for (const ModelParts& level : parts.levels) {
        std::vector<const NamedMesh*> visible;
        for (const NamedMesh& p : level) (p.collision ? collision : visible).push_back(&p);
        if (!visible.empty()) expected.push_back({visible, false});
    }
    for (const NamedMesh* p : collision) expected.push_back({{p}, true});
    std::size_t g = 0;
    for (const fbx::Node& n : objects->children)
        if (n.name == "Geometry") {
            if (g >= expected.size()) fuzz_finding("more geometries than parts");
            check_geometry(n, expected[g].first, expected[g].second);
            ++g;
        }
    if (g != expected.size()) fuzz_finding("fewer geometries than parts");

    const std::vector<std::uint8_t> rest = in.ConsumeRemainingBytes<std::uint8_t>();
    expect_only_input_errors([&] {
        fbx::decode_fbx(std::string_view(reinterpret_cast<const char*>(rest.data()), rest.size()));
    });
    return 0;
}
