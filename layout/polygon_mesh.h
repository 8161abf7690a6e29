// The 2D polygon structure the layout module reads and writes (Schröder 2024, sections 3.2.1 and
// 4.4.1): vertex positions, polygons as vertex index lists, one colour per polygon. Two
// text forms are read: the plain `.mesh` form
//
//     # comment
//     v X Y                      one vertex per line, numbered from 0
//     p #rrggbb I J K ...        one polygon: its colour, then at least 3 vertex indices
//
// and JSON {"vertices": [[x, y], ...], "polygons": [{"vertices": [i, ...], "color":
// "#rrggbb"}]}. Both readers check that the structure is a planar subdivision: every polygon
// closed (3+ distinct vertices, non-zero area) and simple, no two polygons overlapping, no
// edge crossing another, no vertex lying inside another polygon's edge (a T-junction leaves
// the neighbour's boundary unclosed). Bad input raises InputError naming the file with the
// line and column (.mesh) or the JSON key.
#pragma once

#include <cstdint>
#include <filesystem>
#include <glm/vec2.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace sylva::layout {

struct Polygon {
    std::vector<int> vertices;  // counter-clockwise after reading
    std::uint32_t color = 0;    // 0xrrggbb
};

struct PolygonMesh {
    std::vector<glm::dvec2> vertices;
    std::vector<Polygon> polygons;
};

// `source` names the text in errors (a file name).
PolygonMesh read_mesh_text(std::string_view text, const std::string& source = "mesh");
PolygonMesh read_mesh_json(std::string_view text, const std::string& source = "json");
// By extension: .json is JSON, anything else the .mesh form. Throws IoError when the file
// cannot be read.
PolygonMesh read_mesh_file(const std::filesystem::path& path);

// Throws InputError (naming `source` and the polygon) unless `mesh` is a planar subdivision
// as described above; makes every polygon counter-clockwise. The readers call it.
void validate_mesh(PolygonMesh& mesh, const std::string& source);

// A point strictly inside `poly` (for containment tests).
glm::dvec2 interior_point(const PolygonMesh& mesh, const Polygon& poly);

std::string write_mesh_text(const PolygonMesh& mesh);
std::string color_hex(std::uint32_t color);

// The link to forests: each polygon colour maps to the nearest of the planting classes
// "forest" (#2e7d32), "orchard" (#9ccc65), "meadow" (#e6ee9c), "path" (#a1887f).
std::string planting_class(std::uint32_t color);
struct PlantingPolygon {
    std::string planting_class;
    std::vector<glm::dvec2> points;  // counter-clockwise
};
std::vector<PlantingPolygon> planting_polygons(const PolygonMesh& mesh);

// The JSON form read above, each polygon also carrying what `sylva forest --layout` reads:
// {"polygons": [{"vertices": [...], "color": "#rrggbb", "points": [[x, y], ...],
// "class": "forest"}, ...]}; read_mesh_json reads it back.
std::string write_mesh_json(const PolygonMesh& mesh);
// An SVG picture (y up), each polygon filled with its colour.
std::string write_mesh_svg(const PolygonMesh& mesh);

}  // namespace sylva::layout
