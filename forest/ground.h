// The ground a forest is planted on: polygons with a class, as a map or a layout module
// gives them. Points are map coordinates in meters, x east and y north; the scene puts map
// (x, y) at glTF (x, 0, -y) (Y up, north is -Z), so the map is not mirrored.
//
// Where trees stand: inside a polygon of class "forest" and inside no polygon of another
// class ("road", "clearing", "building", ...: holes cut out of the forest). A polygon is
// its points in order (either winding, closed implicitly); self-intersecting ones count by
// the even-odd rule.
#pragma once

#include <filesystem>
#include <glm/vec2.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace sylva::forest {

inline constexpr std::string_view kForestClass = "forest";

struct GroundPolygon {
    std::vector<glm::dvec2> points;
    std::string cls{kForestClass};
};

struct Ground {
    std::vector<GroundPolygon> polygons;
};

// A width x depth rectangle of forest centred on the origin.
Ground rectangle_ground(double width, double depth);

// Whether `p` lies inside the polygon (even-odd rule).
bool contains(const GroundPolygon& polygon, glm::dvec2 p);

// Whether a tree may stand at `p` (see above).
bool plantable(const Ground& ground, glm::dvec2 p);

// The box around every forest polygon (or every polygon of class `cls`): lo, hi. Both zero
// without such polygons.
struct GroundBounds {
    glm::dvec2 lo{0.0};
    glm::dvec2 hi{0.0};
};
GroundBounds forest_bounds(const Ground& ground, std::string_view cls = kForestClass);

// Every point multiplied by `scale` (a layout drawn in other units than meters).
void scale_ground(Ground& ground, double scale);

// `{"polygons": [{"points": [[x, y], ...], "class": "forest"}, ...]}`; "class" defaults to
// "forest". Throws InputError naming `source`, the line and column of a JSON syntax error,
// or the JSON path of a bad value (a polygon of fewer than 3 points, a non-finite number).
Ground parse_ground_json(const std::string& text, const std::string& source);
// Reads a file (IoError when it cannot be read) and parses it.
Ground load_ground(const std::filesystem::path& path);

}  // namespace sylva::forest
