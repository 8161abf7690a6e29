// The .mesh and JSON readers: a valid structure reads back; bad input names the file and the
// line and column (.mesh) or the key (JSON); non-planar, self-intersecting and unclosed
// structures are refused.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "core/errors.h"
#include "layout/polygon_mesh.h"

namespace sylva::layout {
namespace {

constexpr const char* kSquare = "v 0 0\nv 1 0\nv 1 1\nv 0 1\np #2e7d32 0 1 2 3\n";

InputError error_of(const std::string& text, bool json = false) {
    try {
        if (json)
            read_mesh_json(text, "plan.json");
        else
            read_mesh_text(text, "plan.mesh");
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "no error for:\n" << text;
    return InputError("none");
}

TEST(LayoutMesh, ReadsTheTextFormAndMakesPolygonsCounterClockwise) {
    const PolygonMesh m =
        read_mesh_text("# a square, clockwise\nv 0 0\nv 0 1\nv 1 1\nv 1 0\np #2E7D32 0 1 2 3\n");
    ASSERT_EQ(m.vertices.size(), 4u);
    ASSERT_EQ(m.polygons.size(), 1u);
    EXPECT_EQ(m.polygons[0].color, 0x2e7d32u);
    EXPECT_EQ(m.polygons[0].vertices, (std::vector<int>{3, 2, 1, 0}));
}

// Editors that save UTF-8 with a byte order mark: the mark is not the first line's content.
TEST(LayoutMesh, AByteOrderMarkIsSkipped) {
    const PolygonMesh m =
        read_mesh_text("\xEF\xBB\xBFv 0 0\nv 1 0\nv 1 1\nv 0 1\np #2E7D32 0 1 2 3\n");
    EXPECT_EQ(m.vertices.size(), 4u);
    EXPECT_EQ(m.polygons.size(), 1u);
}

TEST(LayoutMesh, TextErrorsNameLineAndColumn) {
    InputError e = error_of("v 0 0\nv 1 x\n");
    EXPECT_EQ(e.where().source, "plan.mesh");
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.column(), 5);
    e = error_of("v 0 0\nv 1 0\nv 1 1\np #00ff00 0 1 7\n");
    EXPECT_EQ(e.line(), 4);
    EXPECT_EQ(e.column(), 15);
    EXPECT_NE(e.reason().find("not the index"), std::string::npos);
    e = error_of("v 0 0\nv 1 0\np red 0 1\n");
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.column(), 3);
    e = error_of("q 1 2\n");
    EXPECT_EQ(e.line(), 1);
}

TEST(LayoutMesh, RefusesUnclosedPolygons) {
    EXPECT_NE(error_of("v 0 0\nv 1 0\nv 1 1\np #00ff00 0 1\n").reason().find("unclosed"),
              std::string::npos);
    EXPECT_NE(error_of("v 0 0\nv 1 0\nv 1 1\np #00ff00 0 1 0\n").reason().find("repeats"),
              std::string::npos);
    EXPECT_NE(error_of("v 0 0\nv 1 0\nv 2 0\np #00ff00 0 1 2\n").reason().find("zero area"),
              std::string::npos);
    // A T-junction: vertex 4 sits inside the right polygon's left edge.
    const InputError t = error_of(
        "v 0 0\nv 1 0\nv 1 2\nv 0 2\nv 1 1\nv 2 0\nv 2 2\np #00ff00 0 1 4 2 3\np #00ff00 1 5 6 "
        "2\n");
    EXPECT_NE(t.reason().find("T-junction"), std::string::npos);
    EXPECT_EQ(t.line(), 9);
}

TEST(LayoutMesh, RefusesSelfIntersectingAndOverlappingInput) {
    const InputError bow = error_of("v 0 0\nv 2 2\nv 2 0\nv 0 1\np #00ff00 0 1 2 3\n");
    EXPECT_NE(bow.reason().find("self-intersecting"), std::string::npos);
    EXPECT_EQ(bow.line(), 5);
    // Two squares overlapping: edges cross.
    const InputError cross =
        error_of(std::string(kSquare) + "v 0.5 0.5\nv 2 0.5\nv 2 2\nv 0.5 2\np #00ff00 4 5 6 7\n");
    EXPECT_NE(cross.reason().find("crosses"), std::string::npos);
    // One square inside another.
    const InputError nested =
        error_of(std::string("v -1 -1\nv 3 -1\nv 3 3\nv -1 3\np #00ff00 0 1 2 3\n") +
                 "v 0 0\nv 1 0\nv 1 1\nv 0 1\np #00ff00 4 5 6 7\n");
    EXPECT_NE(nested.reason().find("overlaps"), std::string::npos);
    // The same square twice.
    EXPECT_NE(error_of(std::string(kSquare) + "p #00ff00 0 1 2 3\n").reason().find("overlaps"),
              std::string::npos);
    // A plot whose edge runs through a path from corner to corner of it: no vertex inside,
    // no crossing, yet no angle graph can be made of it (a fuzz finding), so the reader
    // refuses it.
    const InputError through = error_of(
        "v 0 0\nv 30 0\nv 30 3\nv 20 3\nv 10 3\nv 0 3\nv 10 26\nv 20 13\n"
        "p #a1987f 0 1 2 3 4 5\np #9ccc65 4 0 3 7 6\n");
    EXPECT_NE(through.reason().find("runs inside"), std::string::npos) << through.what();
}

TEST(LayoutMesh, JsonErrorsNameTheKey) {
    EXPECT_NE(std::string(error_of("{\"vertices\": []}", true).what()).find("polygons"),
              std::string::npos);
    const InputError idx = error_of(
        "{\"vertices\": [[0,0],[1,0],[1,1]], \"polygons\": [{\"vertices\": [0,1,5], \"color\": "
        "\"#112233\"}]}",
        true);
    EXPECT_NE(std::string(idx.what()).find("polygons[0].vertices[2]"), std::string::npos);
    EXPECT_EQ(idx.where().source, "plan.json");
    const InputError color = error_of(
        "{\"vertices\": [[0,0],[1,0],[1,1]], \"polygons\": [{\"vertices\": [0,1,2], \"color\": "
        "\"green\"}]}",
        true);
    EXPECT_NE(std::string(color.what()).find("polygons[0].color"), std::string::npos);
    // A number beyond double's range (found by fuzz_layout_mesh).
    EXPECT_NE(std::string(error_of("{\"vertices\": [[1e99999, 0]]}", true).what()).find("JSON"),
              std::string::npos);
    const InputError syntax = error_of("{\n  \"vertices\": [,]\n}", true);
    EXPECT_EQ(syntax.line(), 2);
    const InputError bow = error_of(
        "{\"vertices\": [[0,0],[2,2],[2,0],[0,1]], \"polygons\": [{\"vertices\": [0,1,2,3], "
        "\"color\": \"#112233\"}]}",
        true);
    EXPECT_NE(std::string(bow.what()).find("polygons[0]: the polygon is self-intersecting"),
              std::string::npos);
}

TEST(LayoutMesh, JsonOutputReadsBackAndCarriesPlantingClasses) {
    PolygonMesh m = read_mesh_text(std::string(kSquare) + "v 2 0\nv 2 1\np #a1887f 1 4 5 2\n");
    const std::string json = write_mesh_json(m);
    const PolygonMesh back = read_mesh_json(json);
    EXPECT_EQ(back.vertices, m.vertices);
    ASSERT_EQ(back.polygons.size(), 2u);
    EXPECT_EQ(back.polygons[1].color, 0xa1887fu);
    const auto doc = nlohmann::json::parse(json);
    EXPECT_EQ(doc["polygons"][0]["class"], "forest");
    EXPECT_EQ(doc["polygons"][1]["class"], "path");
    EXPECT_EQ(doc["polygons"][1]["points"][1], nlohmann::json({2.0, 0.0}));
    const auto planting = planting_polygons(m);
    ASSERT_EQ(planting.size(), 2u);
    EXPECT_EQ(planting[0].planting_class, "forest");
    EXPECT_EQ(planting[0].points.size(), 4u);
    EXPECT_EQ(planting_class(0x9ccc65), "orchard");
    EXPECT_EQ(planting_class(0xe6ee9c), "meadow");
}

}  // namespace
}  // namespace sylva::layout
