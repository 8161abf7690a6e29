// Organs (tree/organs.h): closed, outward surfaces placed in the turtle's frame, polygons
// with their colours, thinning that keeps whole organs and nested subsets, template
// palettes, and the three templates that use them.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <set>
#include <string>

#include "core/errors.h"
#include "core/mesh_checks.h"
#include "tree/organ_surfaces.h"
#include "tree/organs.h"
#include "tree/pipeline.h"
#include "tree/template_file.h"
#include "tree/template_library.h"

namespace sylva {
namespace {

// Six times the enclosed volume (divergence theorem): positive for an outward mesh.
double signed_volume(const Mesh& m) {
    double v = 0.0;
    for (const auto& t : m.triangles)
        v += glm::dot(glm::dvec3(m.positions[t[0]]),
                      glm::cross(glm::dvec3(m.positions[t[1]]), glm::dvec3(m.positions[t[2]])));
    return v;
}

TEST(OrganSurfaces, ClosedOnesAreOutwardManifoldsAlongPlusY) {
    for (const std::string& name : organ_surface_names()) {
        const OrganSurface* s = find_organ_surface(name);
        ASSERT_NE(s, nullptr) << name;
        EXPECT_EQ(s->uv.size(), s->mesh.positions.size()) << name;
        EXPECT_GT(s->size, 0.0f) << name;
        float lo = 1.0f, hi = 0.0f;
        for (const glm::vec3& p : s->mesh.positions) lo = std::min(lo, p.y), hi = std::max(hi, p.y);
        EXPECT_GE(lo, 0.0f) << name;
        EXPECT_LE(hi, 1.0f) << name;
        EXPECT_GT(hi - lo, 0.5f) << name;
        if (!s->closed) continue;
        EXPECT_TRUE(check_topology(s->mesh).is_closed_manifold()) << name;
        EXPECT_GT(signed_volume(s->mesh), 0.0) << name << " is inside out";
    }
    EXPECT_EQ(find_organ_surface("pear"), nullptr);
}

Skeleton skeleton_with_organs() {
    Skeleton s;
    Organ up;  // the default frame: heading +Y
    up.surface = "cone";
    up.position = {1, 2, 3};
    up.size = 0.5f;
    up.color = 4;
    Organ apple;
    apple.surface = "apple";
    apple.heading = {1, 0, 0};  // sideways; an apple hangs anyway
    apple.left = {0, 1, 0};
    apple.up = glm::cross(apple.heading, apple.left);
    s.organs = {up, apple};
    s.polygons = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-0.5f, 0.5f, 0}}};
    s.polygon_colors = {2};
    return s;
}

TEST(Organs, SurfacesTakeTheTurtlesFrameFruitHangs) {
    TreeParams params;
    const OrganMesh organs = tree_organs(skeleton_with_organs(), params);
    ASSERT_EQ(organs.organs(), 2u);  // polygons stay with the leaves by default
    EXPECT_EQ(organs.uv.size(), organs.mesh.positions.size());
    EXPECT_EQ(organs.color.size(), organs.mesh.positions.size());
    // The cone runs 0.5 m up from (1, 2, 3), its colour on every vertex.
    for (std::uint32_t v = organs.first_vertex[0]; v < organs.first_vertex[1]; ++v) {
        EXPECT_EQ(organs.color[v], 4);
        EXPECT_GE(organs.mesh.positions[v].y, 2.0f - 1e-5f);
        EXPECT_LE(organs.mesh.positions[v].y, 2.5f + 1e-5f);
    }
    // The apple hangs below its stalk, at its own size.
    const float size = find_organ_surface("apple")->size;
    for (std::uint32_t v = organs.first_vertex[1]; v < organs.first_vertex[2]; ++v) {
        EXPECT_LE(organs.mesh.positions[v].y, 1e-5f);
        EXPECT_GE(organs.mesh.positions[v].y, -size - 1e-5f);
    }
    // Still outward: the frame keeps the winding.
    Mesh apple;
    apple.positions.assign(organs.mesh.positions.begin() + organs.first_vertex[1],
                           organs.mesh.positions.end());
    for (std::uint32_t t = organs.first_triangle[1]; t < organs.first_triangle[2]; ++t) {
        auto tri = organs.mesh.triangles[t];
        for (auto& i : tri) i -= organs.first_vertex[1];
        apple.triangles.push_back(tri);
    }
    EXPECT_GT(signed_volume(apple), 0.0);
}

TEST(Organs, PolygonsJoinWithTheirColourWhenAskedAndUnknownSurfacesFail) {
    TreeParams params;
    params.polygon_part = PolygonPart::Organs;
    const OrganMesh organs = tree_organs(skeleton_with_organs(), params);
    ASSERT_EQ(organs.organs(), 3u);
    EXPECT_EQ(organs.polygon, (std::vector<std::uint8_t>{0, 0, 1}));
    EXPECT_EQ(organs.first_triangle[3] - organs.first_triangle[2], 3u);  // a fan of 5 vertices
    for (std::uint32_t v = organs.first_vertex[2]; v < organs.first_vertex[3]; ++v) {
        EXPECT_EQ(organs.color[v], 2);
        EXPECT_GE(organs.uv[v].x, 0.0f);
        EXPECT_LE(organs.uv[v].y, 1.0f);
    }
    Skeleton bad;
    bad.organs.push_back({});
    bad.organs.back().surface = "pear";
    try {
        tree_organs(bad, params);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("'~pear' (known: apple, cone"), std::string::npos)
            << e.what();
    }
}

OrganMesh many_organs() {
    Skeleton s;
    for (int i = 0; i < 40; ++i) {
        Organ o;
        o.surface = i % 2 ? "berry" : "apple";
        o.position = {float(i), 0, 0};
        s.organs.push_back(o);
        s.polygons.push_back({{float(i), 1, 0},
                              {float(i) + 0.2f, 1.3f, 0},
                              {float(i) + 0.25f, 1.6f, 0},
                              {float(i), 2, 0},
                              {float(i) - 0.25f, 1.6f, 0},
                              {float(i) - 0.2f, 1.3f, 0}});
        s.polygon_colors.push_back(i);
    }
    TreeParams params;
    params.polygon_part = PolygonPart::Organs;
    return tree_organs(s, params);
}

TEST(OrganThinning, PolygonsBecomeQuadsThenWholeOrgansGoInNestedSubsets) {
    const OrganMesh all = many_organs();
    EXPECT_EQ(thin_organs(all, SIZE_MAX).mesh.triangles.size(), all.mesh.triangles.size());
    // Just below: polygons to quads (2 triangles each), every organ kept.
    const OrganMesh quads = thin_organs(all, all.mesh.triangles.size() - 1);
    EXPECT_EQ(quads.organs(), all.organs());
    EXPECT_EQ(quads.mesh.triangles.size(), all.mesh.triangles.size() - 40 * 2);
    for (std::size_t k = 40; k < 80; ++k) {
        EXPECT_EQ(quads.first_vertex[k + 1] - quads.first_vertex[k], 4u);
        // The quad keeps the base, the tip and the two widest vertices.
        const glm::vec3 base = quads.mesh.positions[quads.first_vertex[k]];
        EXPECT_FLOAT_EQ(quads.mesh.positions[quads.first_vertex[k] + 2].y, base.y + 1.0f);
    }
    std::set<glm::vec3::value_type> previous;
    bool first = true;
    for (std::size_t budget : {1500u, 900u, 400u, 100u, 0u}) {
        const OrganMesh kept = thin_organs(all, budget);
        EXPECT_LE(kept.mesh.triangles.size(), budget);
        EXPECT_EQ(kept.uv.size(), kept.mesh.positions.size());
        EXPECT_EQ(kept.color.size(), kept.mesh.positions.size());
        // Every kept organ is whole: its first vertex keys it (x + 1000 * kind).
        std::set<glm::vec3::value_type> keys;
        for (std::size_t k = 0; k < kept.organs(); ++k) {
            const glm::vec3 p = kept.mesh.positions[kept.first_vertex[k]];
            keys.insert(p.x + (kept.polygon[k] ? 1000.0f : 0.0f));
        }
        if (!first) {
            for (float key : keys) EXPECT_TRUE(previous.count(key)) << "budget " << budget;
        }
        previous = keys;
        first = false;
        // Spread: a budget for a quarter of the organs keeps some from both halves.
        if (budget == 400u) {
            int low = 0, high = 0;
            for (float key : keys) (std::fmod(key, 1000.0f) < 20.0f ? low : high)++;
            EXPECT_GT(low, 2);
            EXPECT_GT(high, 2);
        }
    }
}

TEST(TemplatePalette, ReadsBothFormsAndWritesBack) {
    const std::string with_table = R"(name = "p"
grammar = "axiom: F"
[colors]
trunk = [0.1, 0.2, 0.3]
palette = [[0.5, 0.25, 0.0], [1, 1, 1]]
)";
    const TreeTemplate a = parse_template_file(with_table, "a.toml");
    ASSERT_EQ(a.colors.palette.size(), 2u);
    EXPECT_EQ(a.colors.palette[0], glm::vec3(0.5f, 0.25f, 0.0f));
    const TreeTemplate again = parse_template_file(template_file_text(a), "b.toml");
    EXPECT_EQ(again.colors.palette, a.colors.palette);
    EXPECT_EQ(again.colors.trunk, a.colors.trunk);

    const TreeTemplate b = parse_template_file(
        "name = \"p\"\ngrammar = \"axiom: F\"\ncolors = [[0, 1, 0]]\n", "c.toml");
    EXPECT_EQ(b.colors.palette, std::vector<glm::vec3>{glm::vec3(0, 1, 0)});
    EXPECT_EQ(b.colors.trunk, PartColors{}.trunk);

    for (const char* bad : {"colors = [[0, 1]]", "colors = [[0, 1, 2]]", "colors = 3",
                            "[colors]\npalette = [0.5]", "[colors]\nbark = [0, 0, 0]"}) {
        try {
            parse_template_file(std::string("name = \"p\"\ngrammar = \"axiom: F\"\n") + bad,
                                "d.toml");
            ADD_FAILURE() << bad;
        } catch (const InputError& e) {
            EXPECT_GE(e.line(), 3) << bad << ": " << e.what();
        }
    }
}

TEST(OrganTemplates, FlowersFruitAndConesGrowColouredOrgans) {
    struct Expect {
        const char* name;
        const char* surface;  // empty: polygons
        int color;
    };
    for (const Expect& e : {Expect{"flowering_shrub", "", 2}, Expect{"apple_tree", "apple", 1},
                            Expect{"cone_fir", "cone", 1}}) {
        TreeTemplate t = load_template(e.name);
        t.params.trunk_resolution = 40;  // the organs do not depend on the meshes
        t.params.crown_resolution = 24;
        const Tree tree = generate_tree(t, {});
        ASSERT_FALSE(tree.organs.empty()) << e.name;
        EXPECT_GE(t.colors.palette.size(), 2u) << e.name;
        std::set<int> colors(tree.organs.color.begin(), tree.organs.color.end());
        EXPECT_TRUE(colors.count(e.color)) << e.name;
        if (*e.surface) {
            EXPECT_GE(tree.skeleton.organs.size(), 5u) << e.name;
            for (const Organ& o : tree.skeleton.organs) EXPECT_EQ(o.surface, e.surface);
        } else {
            // The shrub's leaves and petals are organs, not leaves.
            EXPECT_TRUE(tree.leaves.triangles.empty());
            EXPECT_EQ(tree.organs.organs(), tree.skeleton.polygons.size());
        }
    }
}

}  // namespace
}  // namespace sylva
