#include "layout/polygon_mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/errors.h"
#include "core/input_file.h"
#include "layout/geometry.h"

namespace sylva::layout {

namespace {

// Where each polygon came from, for errors: a .mesh line or a JSON key.
struct Origin {
    int line = 0;
    std::string key;
    std::string text;  // the .mesh line
};

[[noreturn]] void fail(const std::string& source, const Origin& where, const std::string& what) {
    if (where.line > 0) throw InputError(what, {source, where.line, 1}, where.text);
    throw InputError(where.key.empty() ? what : where.key + ": " + what, {source});
}

bool parse_color(std::string_view s, std::uint32_t& out) {
    if (s.size() != 7 || s[0] != '#') return false;
    std::uint32_t v = 0;
    for (char c : s.substr(1)) {
        int d = (c >= '0' && c <= '9')   ? c - '0'
                : (c >= 'a' && c <= 'f') ? c - 'a' + 10
                : (c >= 'A' && c <= 'F') ? c - 'A' + 10
                                         : -1;
        if (d < 0) return false;
        v = v * 16 + static_cast<std::uint32_t>(d);
    }
    out = v;
    return true;
}

void validate(PolygonMesh& mesh, const std::string& source, const std::vector<Origin>& origins) {
    const int nv = static_cast<int>(mesh.vertices.size());
    for (int i = 0; i < nv; ++i)
        if (!std::isfinite(mesh.vertices[i].x) || !std::isfinite(mesh.vertices[i].y) ||
            std::abs(mesh.vertices[i].x) > 1e7 || std::abs(mesh.vertices[i].y) > 1e7)
            throw InputError(
                "vertex " + std::to_string(i) + " is not a finite coordinate within 1e7", {source});
    if (mesh.polygons.empty()) throw InputError("no polygons", {source});
    if (mesh.polygons.size() > 20000) throw InputError("more than 20000 polygons", {source});
    double extent = 1e-300;
    for (const glm::dvec2& p : mesh.vertices)
        extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
    const double eps = extent * 1e-9;

    std::map<std::pair<int, int>, int> directed;  // (a, b) -> polygon with a->b on its boundary
    for (std::size_t k = 0; k < mesh.polygons.size(); ++k) {
        Polygon& poly = mesh.polygons[k];
        const Origin& at = origins[k];
        const int n = static_cast<int>(poly.vertices.size());
        if (n < 3) fail(source, at, "a polygon needs at least 3 vertices (unclosed polygon)");
        for (int i : poly.vertices)
            if (i < 0 || i >= nv)
                fail(source, at,
                     "vertex index " + std::to_string(i) + " out of range (" + std::to_string(nv) +
                         " vertices)");
        std::vector<int> sorted = poly.vertices;
        std::sort(sorted.begin(), sorted.end());
        if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
            fail(source, at, "a polygon repeats a vertex (self-intersecting or unclosed polygon)");
        std::vector<glm::dvec2> pts;
        for (int i : poly.vertices) pts.push_back(mesh.vertices[i]);
        const double area = signed_area(pts);
        if (std::abs(area) <= eps * extent) fail(source, at, "a polygon has zero area");
        if (area < 0) std::reverse(poly.vertices.begin(), poly.vertices.end());
        for (int i = 0; i < n; ++i)
            for (int j = i + 1; j < n; ++j) {
                if (j == i + 1 || (i == 0 && j == n - 1)) continue;
                if (segments_touch(pts[i], pts[(i + 1) % n], pts[j], pts[(j + 1) % n], eps))
                    fail(source, at,
                         "the polygon is self-intersecting (edges " + std::to_string(i) + " and " +
                             std::to_string(j) + " meet)");
            }
        for (int i = 0; i < n; ++i) {
            const int a = poly.vertices[i], b = poly.vertices[(i + 1) % n];
            auto [it, fresh] = directed.emplace(std::pair{a, b}, static_cast<int>(k));
            if (!fresh)
                fail(source, at,
                     "overlaps polygon " + std::to_string(it->second) + " (both have edge " +
                         std::to_string(a) + "-" + std::to_string(b) + " on the same side)");
        }
    }
    // Distinct undirected edges must not cross or touch except at shared endpoints, and no
    // vertex may lie inside an edge (a T-junction).
    std::vector<std::pair<int, int>> edges;
    std::vector<int> edge_polygon;
    for (const auto& [e, k] : directed)
        if (e.first < e.second || !directed.count({e.second, e.first})) {
            edges.push_back(e);
            edge_polygon.push_back(k);
        }
    std::vector<bool> used(nv, false);
    for (const auto& e : edges) used[e.first] = used[e.second] = true;
    for (std::size_t i = 0; i < edges.size(); ++i) {
        const auto [a, b] = edges[i];
        for (int v = 0; v < nv; ++v)
            if (used[v] && v != a && v != b &&
                point_segment_distance(mesh.vertices[v], mesh.vertices[a], mesh.vertices[b]) <= eps)
                fail(source, origins[edge_polygon[i]],
                     "vertex " + std::to_string(v) + " lies on edge " + std::to_string(a) + "-" +
                         std::to_string(b) +
                         " without being one of its corners (T-junction: the boundary is not "
                         "closed)");
        for (std::size_t j = i + 1; j < edges.size(); ++j) {
            const auto [c, d] = edges[j];
            if (a == c || a == d || b == c || b == d) continue;
            if (segments_touch(mesh.vertices[a], mesh.vertices[b], mesh.vertices[c],
                               mesh.vertices[d], eps))
                fail(source, origins[edge_polygon[j]],
                     "edge " + std::to_string(c) + "-" + std::to_string(d) + " crosses edge " +
                         std::to_string(a) + "-" + std::to_string(b) +
                         " (the structure is not planar)");
        }
    }
    // With no crossings, two polygons overlap only if one holds a vertex of the other strictly
    // inside (or one holds the other entirely: then the inner one's vertices are inside).
    for (std::size_t k = 0; k < mesh.polygons.size(); ++k) {
        std::vector<glm::dvec2> pts;
        for (int i : mesh.polygons[k].vertices) pts.push_back(mesh.vertices[i]);
        for (std::size_t m = 0; m < mesh.polygons.size(); ++m) {
            if (m == k) continue;
            // The centroid of a triangle at a convex corner of m lies inside m; checking one
            // interior point of m per polygon catches identical-outline and nested overlaps.
            const Polygon& other = mesh.polygons[m];
            for (int v : other.vertices)
                if (std::find(mesh.polygons[k].vertices.begin(), mesh.polygons[k].vertices.end(),
                              v) == mesh.polygons[k].vertices.end() &&
                    point_in_polygon(mesh.vertices[v], pts, eps) > 0)
                    fail(source, origins[m],
                         "overlaps polygon " + std::to_string(k) + " (vertex " + std::to_string(v) +
                             " lies inside it)");
            // An edge of m through k's inside whose ends lie on k's outline (no vertex inside,
            // no crossing): its midpoint is inside k (fuzz finding: an orchard plot over a path).
            const std::size_t n = other.vertices.size();
            for (std::size_t i = 0; i < n; ++i) {
                const glm::dvec2 mid = 0.5 * (mesh.vertices[other.vertices[i]] +
                                              mesh.vertices[other.vertices[(i + 1) % n]]);
                if (point_in_polygon(mid, pts, eps) > 0)
                    fail(source, origins[m],
                         "overlaps polygon " + std::to_string(k) + " (edge " +
                             std::to_string(other.vertices[i]) + "-" +
                             std::to_string(other.vertices[(i + 1) % n]) + " runs inside it)");
            }
            const glm::dvec2 inside = interior_point(mesh, other);
            if (point_in_polygon(inside, pts, eps) > 0)
                fail(source, origins[m], "overlaps polygon " + std::to_string(k));
        }
    }
}

}  // namespace

glm::dvec2 interior_point(const PolygonMesh& mesh, const Polygon& poly) {
    // Ear-free: the midpoint of a short step inward from the middle of the longest edge.
    const int n = static_cast<int>(poly.vertices.size());
    std::vector<glm::dvec2> pts;
    for (int i : poly.vertices) pts.push_back(mesh.vertices[i]);
    int best = 0;
    double best_len = -1;
    for (int i = 0; i < n; ++i) {
        const double len = glm::length(pts[(i + 1) % n] - pts[i]);
        if (len > best_len) best_len = len, best = i;
    }
    const glm::dvec2 a = pts[best], b = pts[(best + 1) % n];
    const glm::dvec2 mid = 0.5 * (a + b);
    const glm::dvec2 inward = glm::dvec2(-(b - a).y, (b - a).x) / best_len;  // left of a CCW edge
    // Step inward by less than the distance to any other edge.
    double room = best_len;
    for (int i = 0; i < n; ++i)
        if (i != best) room = std::min(room, point_segment_distance(mid, pts[i], pts[(i + 1) % n]));
    return mid + inward * (0.5 * room);
}

void validate_mesh(PolygonMesh& mesh, const std::string& source) {
    std::vector<Origin> origins;
    for (std::size_t k = 0; k < mesh.polygons.size(); ++k)
        origins.push_back({0, "polygons[" + std::to_string(k) + "]", {}});
    validate(mesh, source, origins);
}

PolygonMesh read_mesh_text(std::string_view text, const std::string& source) {
    // A UTF-8 byte order mark, as some editors save, is no content (TOML files take it too).
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
    PolygonMesh mesh;
    std::vector<Origin> origins;
    std::istringstream in{std::string(text)};
    std::string raw;
    int line_no = 0;
    while (std::getline(in, raw)) {
        ++line_no;
        if (!raw.empty() && raw.back() == '\r') raw.pop_back();
        const std::string line = raw.substr(0, raw.find('#') == 0 ? 0 : std::string::npos);
        std::size_t pos = line.find_first_not_of(" \t");
        if (pos == std::string::npos || line[pos] == '#') continue;
        auto error = [&](std::size_t column, const std::string& what) {
            throw InputError(what, {source, line_no, static_cast<int>(column) + 1}, raw);
        };
        // Tokens with their columns.
        std::vector<std::pair<std::string, std::size_t>> tokens;
        for (std::size_t i = pos; i < line.size();) {
            if (line[i] == ' ' || line[i] == '\t') {
                ++i;
                continue;
            }
            std::size_t j = line.find_first_of(" \t", i);
            if (j == std::string::npos) j = line.size();
            tokens.emplace_back(line.substr(i, j - i), i);
            i = j;
        }
        const std::string& kind = tokens[0].first;
        auto number = [&](std::size_t t) {
            const std::string& s = tokens[t].first;
            double v = 0;
            int used = 0;
            if (std::sscanf(s.c_str(), "%lf%n", &v, &used) != 1 ||
                used != static_cast<int>(s.size()) || !std::isfinite(v))
                error(tokens[t].second, "'" + s + "' is not a number");
            return v;
        };
        if (kind == "v") {
            if (tokens.size() != 3) error(pos, "a vertex line is 'v X Y'");
            if (mesh.vertices.size() >= 200000) error(pos, "more than 200000 vertices");
            mesh.vertices.emplace_back(number(1), number(2));
        } else if (kind == "p") {
            if (tokens.size() < 2) error(pos, "a polygon line is 'p #rrggbb I J K ...'");
            Polygon poly;
            if (!parse_color(tokens[1].first, poly.color))
                error(tokens[1].second, "'" + tokens[1].first + "' is not a colour #rrggbb");
            for (std::size_t t = 2; t < tokens.size(); ++t) {
                const double v = number(t);
                if (v != std::floor(v) || v < 0 || v >= static_cast<double>(mesh.vertices.size()))
                    error(tokens[t].second,
                          "'" + tokens[t].first + "' is not the index of a vertex above (0.." +
                              std::to_string(static_cast<long>(mesh.vertices.size()) - 1) + ")");
                poly.vertices.push_back(static_cast<int>(v));
            }
            if (poly.vertices.size() < 3)
                error(tokens.back().second,
                      "a polygon needs at least 3 vertices (unclosed polygon)");
            mesh.polygons.push_back(std::move(poly));
            origins.push_back({line_no, {}, raw});
        } else {
            error(tokens[0].second, "unknown line kind '" + kind + "' (expected 'v' or 'p')");
        }
    }
    validate(mesh, source, origins);
    return mesh;
}

PolygonMesh read_mesh_json(std::string_view text, const std::string& source) {
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        // Byte offset -> line and column.
        int line = 1, column = 1;
        for (std::size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) {
            if (text[i] == '\n')
                ++line, column = 1;
            else
                ++column;
        }
        throw InputError("not JSON: " + std::string(e.what()), {source, line, column});
    } catch (const nlohmann::json::exception& e) {  // e.g. a number beyond double's range
        throw InputError("not readable JSON: " + std::string(e.what()), {source});
    }
    auto key_error = [&](const std::string& key, const std::string& what) -> InputError {
        return InputError(key + ": " + what, {source});
    };
    if (!doc.is_object()) throw key_error("(top level)", "expected an object");
    if (!doc.contains("vertices") || !doc["vertices"].is_array())
        throw key_error("vertices", "expected an array of [x, y]");
    if (!doc.contains("polygons") || !doc["polygons"].is_array())
        throw key_error("polygons",
                        "expected an array of {\"vertices\": [...], \"color\": \"#rrggbb\"}");
    PolygonMesh mesh;
    const auto& vs = doc["vertices"];
    if (vs.size() > 200000) throw key_error("vertices", "more than 200000 vertices");
    for (std::size_t i = 0; i < vs.size(); ++i) {
        const auto& v = vs[i];
        if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
            throw key_error("vertices[" + std::to_string(i) + "]", "expected [x, y]");
        mesh.vertices.emplace_back(v[0].get<double>(), v[1].get<double>());
    }
    std::vector<Origin> origins;
    const auto& ps = doc["polygons"];
    for (std::size_t k = 0; k < ps.size(); ++k) {
        const std::string key = "polygons[" + std::to_string(k) + "]";
        const auto& p = ps[k];
        if (!p.is_object()) throw key_error(key, "expected an object");
        if (!p.contains("vertices") || !p["vertices"].is_array())
            throw key_error(key + ".vertices", "expected an array of vertex indices");
        Polygon poly;
        if (p.contains("color")) {
            if (!p["color"].is_string() || !parse_color(p["color"].get<std::string>(), poly.color))
                throw key_error(key + ".color", "expected a colour \"#rrggbb\"");
        } else {
            throw key_error(key + ".color", "missing");
        }
        const auto& idx = p["vertices"];
        for (std::size_t i = 0; i < idx.size(); ++i) {
            if (!idx[i].is_number_integer() || idx[i].get<long long>() < 0 ||
                idx[i].get<long long>() >= static_cast<long long>(mesh.vertices.size()))
                throw key_error(key + ".vertices[" + std::to_string(i) + "]",
                                "expected the index of a vertex (0.." +
                                    std::to_string(static_cast<long>(mesh.vertices.size()) - 1) +
                                    ")");
            poly.vertices.push_back(static_cast<int>(idx[i].get<long long>()));
        }
        mesh.polygons.push_back(std::move(poly));
        origins.push_back({0, key, {}});
    }
    validate(mesh, source, origins);
    return mesh;
}

PolygonMesh read_mesh_file(const std::filesystem::path& path) {
    const std::string text = read_input_file(path, "layout example");
    if (path.extension() == ".json") return read_mesh_json(text, path.string());
    return read_mesh_text(text, path.string());
}

std::string color_hex(std::uint32_t color) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%06x", color & 0xffffffu);
    return buf;
}

std::string write_mesh_text(const PolygonMesh& mesh) {
    std::string out =
        "# sylva layout mesh: 'v X Y' vertices (from 0), 'p #rrggbb I J K ...' polygons\n";
    char buf[96];
    for (const glm::dvec2& v : mesh.vertices) {
        std::snprintf(buf, sizeof buf, "v %.9g %.9g\n", v.x, v.y);
        out += buf;
    }
    for (const Polygon& p : mesh.polygons) {
        out += "p " + color_hex(p.color);
        for (int i : p.vertices) out += " " + std::to_string(i);
        out += "\n";
    }
    return out;
}

std::string planting_class(std::uint32_t color) {
    struct Class {
        const char* name;
        std::uint32_t color;
    };
    static constexpr Class kClasses[] = {
        {"forest", 0x2e7d32}, {"orchard", 0x9ccc65}, {"meadow", 0xe6ee9c}, {"path", 0xa1887f}};
    auto channel = [](std::uint32_t c, int shift) { return static_cast<int>((c >> shift) & 0xff); };
    const char* best = kClasses[0].name;
    long best_d = -1;
    for (const Class& k : kClasses) {
        long d = 0;
        for (int shift : {0, 8, 16}) {
            const long diff = channel(color, shift) - channel(k.color, shift);
            d += diff * diff;
        }
        if (best_d < 0 || d < best_d) best_d = d, best = k.name;
    }
    return best;
}

std::vector<PlantingPolygon> planting_polygons(const PolygonMesh& mesh) {
    std::vector<PlantingPolygon> out;
    for (const Polygon& p : mesh.polygons) {
        PlantingPolygon& q = out.emplace_back();
        q.planting_class = planting_class(p.color);
        for (int i : p.vertices) q.points.push_back(mesh.vertices[i]);
    }
    return out;
}

std::string write_mesh_json(const PolygonMesh& mesh) {
    nlohmann::ordered_json doc;
    doc["vertices"] = nlohmann::ordered_json::array();
    for (const glm::dvec2& v : mesh.vertices) doc["vertices"].push_back({v.x, v.y});
    doc["polygons"] = nlohmann::ordered_json::array();
    for (const Polygon& p : mesh.polygons) {
        nlohmann::ordered_json poly;
        poly["vertices"] = p.vertices;
        poly["color"] = color_hex(p.color);
        poly["class"] = planting_class(p.color);
        poly["points"] = nlohmann::ordered_json::array();
        for (int i : p.vertices) poly["points"].push_back({mesh.vertices[i].x, mesh.vertices[i].y});
        doc["polygons"].push_back(std::move(poly));
    }
    return doc.dump() + "\n";
}

std::string write_mesh_svg(const PolygonMesh& mesh) {
    glm::dvec2 lo(1e300), hi(-1e300);
    for (const glm::dvec2& v : mesh.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
    if (mesh.vertices.empty()) lo = hi = glm::dvec2(0);
    const double size = std::max({hi.x - lo.x, hi.y - lo.y, 1e-9});
    const double scale = 480.0 / size;
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\">\n",
                  (hi.x - lo.x) * scale + 20, (hi.y - lo.y) * scale + 20);
    std::string out = buf;
    for (const Polygon& p : mesh.polygons) {
        out += "<polygon points=\"";
        for (int i : p.vertices) {
            const glm::dvec2 v = mesh.vertices[i];
            std::snprintf(buf, sizeof buf, "%.2f,%.2f ", (v.x - lo.x) * scale + 10,
                          (hi.y - v.y) * scale + 10);
            out += buf;
        }
        out += "\" fill=\"" + color_hex(p.color) + "\" stroke=\"#333333\" stroke-width=\"1\"/>\n";
    }
    return out + "</svg>\n";
}

}  // namespace sylva::layout
