#include "forest/ground.h"

#include <cmath>
#include <glm/common.hpp>
#include <limits>
#include <nlohmann/json.hpp>

#include "core/errors.h"
#include "core/input_file.h"

namespace sylva::forest {

bool contains(const GroundPolygon& polygon, glm::dvec2 p) {
    bool in = false;
    const auto& pts = polygon.points;
    for (std::size_t i = 0, j = pts.size() - 1; i < pts.size(); j = i++) {
        const glm::dvec2 a = pts[i], b = pts[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
            in = !in;
    }
    return in;
}

namespace {

// Line and column of a byte offset, for JSON syntax errors.
SourceLocation location_of(const std::string& text, std::size_t offset, const std::string& source) {
    SourceLocation where{source, 1, 1};
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++where.line;
            where.column = 1;
        } else {
            ++where.column;
        }
    }
    return where;
}

double number(const nlohmann::json& value, const std::string& path, const std::string& source) {
    if (!value.is_number() || !std::isfinite(value.get<double>()))
        throw InputError(source + ": " + path + " must be a finite number, not " + value.dump());
    return value.get<double>();
}

}  // namespace

Ground rectangle_ground(double width, double depth) {
    const double x = width / 2, y = depth / 2;
    return {{{{{-x, -y}, {x, -y}, {x, y}, {-x, y}}, std::string(kForestClass)}}};
}

bool plantable(const Ground& ground, glm::dvec2 p) {
    bool in_forest = false;
    for (const GroundPolygon& polygon : ground.polygons) {
        if (polygon.points.size() < 3 || !contains(polygon, p)) continue;
        if (polygon.cls != kForestClass) return false;
        in_forest = true;
    }
    return in_forest;
}

GroundBounds forest_bounds(const Ground& ground, std::string_view cls) {
    glm::dvec2 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
    bool any = false;
    for (const GroundPolygon& polygon : ground.polygons) {
        if (polygon.cls != cls) continue;
        for (glm::dvec2 p : polygon.points) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
            any = true;
        }
    }
    if (!any) return {};
    return {lo, hi};
}

void scale_ground(Ground& ground, double scale) {
    for (GroundPolygon& polygon : ground.polygons)
        for (glm::dvec2& p : polygon.points) p *= scale;
}

Ground parse_ground_json(const std::string& text, const std::string& source) {
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        const SourceLocation where = location_of(text, e.byte == 0 ? 0 : e.byte - 1, source);
        throw InputError(std::string("invalid JSON: ") + e.what(), where);
    } catch (const nlohmann::json::exception& e) {
        // out_of_range 406, a number past any double (1e999), names the token but no byte.
        const std::string what = e.what();
        const std::size_t quote = what.find('\'');
        const std::string token =
            quote == std::string::npos ? "" : what.substr(quote + 1, what.rfind('\'') - quote - 1);
        const std::size_t at = token.empty() ? std::string::npos : text.find(token);
        throw InputError("a number no double can hold" + (token.empty() ? "" : ": " + token),
                         location_of(text, at == std::string::npos ? 0 : at, source));
    }
    if (!doc.is_object() || !doc.contains("polygons") || !doc["polygons"].is_array())
        throw InputError(source + ": expected an object with a \"polygons\" array");
    Ground ground;
    const auto& polygons = doc["polygons"];
    for (std::size_t i = 0; i < polygons.size(); ++i) {
        const std::string at = "polygons[" + std::to_string(i) + "]";
        const auto& p = polygons[i];
        if (!p.is_object() || !p.contains("points") || !p["points"].is_array())
            throw InputError(source + ": " + at + " needs a \"points\" array");
        GroundPolygon polygon;
        if (p.contains("class")) {
            if (!p["class"].is_string())
                throw InputError(source + ": " + at + ".class must be a string");
            polygon.cls = p["class"].get<std::string>();
        }
        const auto& points = p["points"];
        for (std::size_t k = 0; k < points.size(); ++k) {
            const std::string pat = at + ".points[" + std::to_string(k) + "]";
            if (!points[k].is_array() || points[k].size() != 2)
                throw InputError(source + ": " + pat + " must be [x, y]");
            polygon.points.push_back({number(points[k][0], pat + "[0]", source),
                                      number(points[k][1], pat + "[1]", source)});
        }
        if (polygon.points.size() < 3)
            throw InputError(source + ": " + at + " has " + std::to_string(polygon.points.size()) +
                             " points; a polygon needs at least 3");
        ground.polygons.push_back(std::move(polygon));
    }
    return ground;
}

Ground load_ground(const std::filesystem::path& path) {
    return parse_ground_json(read_input_file(path, "ground file"), path.string());
}

}  // namespace sylva::forest
