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
#include "layout/limits.h"

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

// A uniform grid over the example's box: each cell lists the items (edges or polygon boxes)
// that come within eps of it, so pairwise checks only meet items near each other. About one
// cell per item: the checks take time in proportion to the example, not its square, unless
// the example crowds many edges into one spot (then kMaxPairTests stops it).
class Grid {
  public:
    Grid(glm::dvec2 lo, glm::dvec2 hi, std::size_t items) : lo_(lo) {
        const double side = std::max({hi.x - lo.x, hi.y - lo.y, 1e-300});
        const double per_side =
            std::clamp(std::ceil(std::sqrt(static_cast<double>(items))), 1.0, 2048.0);
        cell_ = side / per_side * (1.0 + 1e-9);
        nx_ = std::max(1, static_cast<int>(std::ceil((hi.x - lo.x) / cell_)) + 1);
        ny_ = std::max(1, static_cast<int>(std::ceil((hi.y - lo.y) / cell_)) + 1);
        cells_.resize(static_cast<std::size_t>(nx_) * ny_);
    }
    int column(double x) const {
        return std::clamp(static_cast<int>(std::floor((x - lo_.x) / cell_)), 0, nx_ - 1);
    }
    int row(double y) const {
        return std::clamp(static_cast<int>(std::floor((y - lo_.y) / cell_)), 0, ny_ - 1);
    }
    std::vector<int>& cell(int cx, int cy) {
        return cells_[static_cast<std::size_t>(cy) * nx_ + cx];
    }
    const std::vector<int>& at(glm::dvec2 p) const {
        return cells_[static_cast<std::size_t>(row(p.y)) * nx_ + column(p.x)];
    }
    // The segment ab thickened by eps, column by column: only the cells it passes.
    void add_segment(glm::dvec2 a, glm::dvec2 b, double eps, int id) {
        if (a.x > b.x) std::swap(a, b);
        const int c0 = column(a.x - eps), c1 = column(b.x + eps);
        for (int cx = c0; cx <= c1; ++cx) {
            const double x0 = std::max(a.x, lo_.x + cx * cell_),
                         x1 = std::min(b.x, lo_.x + (cx + 1) * cell_);
            double y0 = a.y, y1 = b.y;
            if (b.x - a.x > 0 && x0 <= x1) {
                const double slope = (b.y - a.y) / (b.x - a.x);
                y0 = a.y + slope * (x0 - a.x);
                y1 = a.y + slope * (x1 - a.x);
            }
            if (y0 > y1) std::swap(y0, y1);
            for (int cy = row(y0 - eps); cy <= row(y1 + eps); ++cy) cell(cx, cy).push_back(id);
        }
    }
    void add_box(glm::dvec2 lo, glm::dvec2 hi, int id) {
        for (int cy = row(lo.y); cy <= row(hi.y); ++cy)
            for (int cx = column(lo.x); cx <= column(hi.x); ++cx) cell(cx, cy).push_back(id);
    }
    const std::vector<std::vector<int>>& cells() const { return cells_; }

  private:
    glm::dvec2 lo_;
    double cell_ = 1;
    int nx_ = 1, ny_ = 1;
    std::vector<std::vector<int>> cells_;
};

// Pairs of nearby items the checks may test before the example counts as too crowded to
// check (a few seconds of work): a limit on adversarial input, far above any drawn plan.
constexpr std::size_t kMaxPairTests = 200'000'000;

void validate(PolygonMesh& mesh, const std::string& source, const std::vector<Origin>& origins) {
    const int nv = static_cast<int>(mesh.vertices.size());
    for (int i = 0; i < nv; ++i)
        if (!std::isfinite(mesh.vertices[i].x) || !std::isfinite(mesh.vertices[i].y) ||
            std::abs(mesh.vertices[i].x) > 1e7 || std::abs(mesh.vertices[i].y) > 1e7)
            throw InputError(
                "vertex " + std::to_string(i) + " is not a finite coordinate within 1e7", {source});
    if (mesh.polygons.empty()) throw InputError("no polygons", {source});
    if (mesh.polygons.size() > static_cast<std::size_t>(kMaxExamplePolygons))
        throw InputError("more than " + std::to_string(kMaxExamplePolygons) + " polygons",
                         {source});
    double extent = 1e-300;
    glm::dvec2 lo(1e300), hi(-1e300);
    for (const glm::dvec2& p : mesh.vertices) {
        extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const double eps = extent * 1e-9;
    std::size_t tests = 0;
    auto count_test = [&]() {
        if (++tests > kMaxPairTests)
            throw InputError("too crowded to check: more than " + std::to_string(kMaxPairTests) +
                                 " pairs of edges or polygons lie near each other",
                             {source});
    };

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
    }
    // Every edge against the edges near it: two distinct undirected edges must not cross or
    // touch except at a shared corner (two edges of one polygon that do: a self-intersecting
    // polygon), and no vertex may lie inside an edge (a T-junction).
    struct Edge {
        int a, b, polygon, index;  // index: the edge's place in its polygon
    };
    std::vector<Edge> edges;
    std::map<std::pair<int, int>, int> undirected;  // (min, max) -> edges[]
    for (std::size_t k = 0; k < mesh.polygons.size(); ++k) {
        const Polygon& poly = mesh.polygons[k];
        const int n = static_cast<int>(poly.vertices.size());
        for (int i = 0; i < n; ++i) {
            const int a = poly.vertices[i], b = poly.vertices[(i + 1) % n];
            auto [it, fresh] = directed.emplace(std::pair{a, b}, static_cast<int>(k));
            if (!fresh)
                fail(source, origins[k],
                     "overlaps polygon " + std::to_string(it->second) + " (both have edge " +
                         std::to_string(a) + "-" + std::to_string(b) + " on the same side)");
            if (undirected
                    .emplace(std::pair{std::min(a, b), std::max(a, b)},
                             static_cast<int>(edges.size()))
                    .second)
                edges.push_back({a, b, static_cast<int>(k), i});
        }
    }
    // The first violation in edge order, so the message does not depend on the grid.
    Grid grid(lo, hi, edges.size());
    for (std::size_t e = 0; e < edges.size(); ++e)
        grid.add_segment(mesh.vertices[edges[e].a], mesh.vertices[edges[e].b], eps,
                         static_cast<int>(e));
    // The first violation: by its lower edge, a T-junction before a crossing, then by the
    // other edge.
    std::pair<int, int> worst{-1, -1};
    bool t_junction = false;
    int t_vertex = -1;
    auto note = [&](int i, int j, bool t, int v) {
        const std::pair<int, int> key{std::min(i, j), t ? -1 : std::max(i, j)};
        if (worst.first < 0 || key < worst) worst = key, t_junction = t, t_vertex = v;
    };
    std::vector<char> used(nv, 0);
    for (const Edge& e : edges) used[e.a] = used[e.b] = 1;
    for (int v = 0; v < nv; ++v) {
        if (!used[v]) continue;
        for (int e : grid.at(mesh.vertices[v])) {
            count_test();
            const Edge& ed = edges[e];
            if (v != ed.a && v != ed.b &&
                point_segment_distance(mesh.vertices[v], mesh.vertices[ed.a],
                                       mesh.vertices[ed.b]) <= eps)
                note(e, e, true, v);
        }
    }
    for (const std::vector<int>& cell : grid.cells())
        for (std::size_t x = 0; x < cell.size(); ++x)
            for (std::size_t y = x + 1; y < cell.size(); ++y) {
                count_test();
                const Edge& p = edges[cell[x]];
                const Edge& q = edges[cell[y]];
                if (p.a == q.a || p.a == q.b || p.b == q.a || p.b == q.b) continue;
                if (segments_touch(mesh.vertices[p.a], mesh.vertices[p.b], mesh.vertices[q.a],
                                   mesh.vertices[q.b], eps))
                    note(cell[x], cell[y], false, -1);
            }
    if (worst.first >= 0) {
        const Edge& first = edges[worst.first];
        const Edge& second = edges[t_junction ? worst.first : worst.second];
        if (t_junction)
            fail(source, origins[first.polygon],
                 "vertex " + std::to_string(t_vertex) + " lies on edge " + std::to_string(first.a) +
                     "-" + std::to_string(first.b) +
                     " without being one of its corners (T-junction: the boundary is not closed)");
        // Two edges of one polygon (either side of each counts): the polygon crosses itself.
        auto owners = [&](const Edge& e) {
            std::vector<int> out{e.polygon};
            const auto it = directed.find({e.b, e.a});
            if (it != directed.end()) out.push_back(it->second);
            return out;
        };
        for (int k : owners(first))
            for (int m : owners(second))
                if (k == m) {
                    const Polygon& poly = mesh.polygons[k];
                    auto place = [&](const Edge& e) {
                        const int n = static_cast<int>(poly.vertices.size());
                        for (int i = 0; i < n; ++i)
                            if ((poly.vertices[i] == e.a && poly.vertices[(i + 1) % n] == e.b) ||
                                (poly.vertices[i] == e.b && poly.vertices[(i + 1) % n] == e.a))
                                return i;
                        return -1;
                    };
                    const int i = std::min(place(first), place(second));
                    const int j = std::max(place(first), place(second));
                    fail(source, origins[k],
                         "the polygon is self-intersecting (edges " + std::to_string(i) + " and " +
                             std::to_string(j) + " meet)");
                }
        fail(source, origins[second.polygon],
             "edge " + std::to_string(second.a) + "-" + std::to_string(second.b) +
                 " crosses edge " + std::to_string(first.a) + "-" + std::to_string(first.b) +
                 " (the structure is not planar)");
    }
    // With no crossings, two polygons overlap only if one holds a vertex, an edge's middle or
    // an inner point of the other strictly inside. Only polygons whose boxes share a grid
    // cell with the point are asked.
    const std::size_t np = mesh.polygons.size();
    std::vector<std::vector<glm::dvec2>> rings(np);
    std::vector<std::pair<glm::dvec2, glm::dvec2>> boxes(np);
    Grid boxes_grid(lo, hi, np);
    for (std::size_t k = 0; k < np; ++k) {
        glm::dvec2 blo(1e300), bhi(-1e300);
        for (int i : mesh.polygons[k].vertices) {
            rings[k].push_back(mesh.vertices[i]);
            blo = glm::min(blo, mesh.vertices[i]);
            bhi = glm::max(bhi, mesh.vertices[i]);
        }
        boxes[k] = {blo, bhi};
        boxes_grid.add_box(blo, bhi, static_cast<int>(k));
    }
    auto holder = [&](glm::dvec2 p, std::size_t m) -> int {
        for (int k : boxes_grid.at(p)) {
            count_test();
            if (static_cast<std::size_t>(k) == m) continue;
            const auto& [blo, bhi] = boxes[k];
            if (p.x < blo.x || p.y < blo.y || p.x > bhi.x || p.y > bhi.y) continue;
            if (point_in_polygon(p, rings[k], eps) > 0) return k;
        }
        return -1;
    };
    for (std::size_t m = 0; m < np; ++m) {
        const Polygon& other = mesh.polygons[m];
        for (int v : other.vertices)
            if (const int k = holder(mesh.vertices[v], m); k >= 0)
                fail(source, origins[m],
                     "overlaps polygon " + std::to_string(k) + " (vertex " + std::to_string(v) +
                         " lies inside it)");
        // An edge of m through k's inside whose ends lie on k's outline (no vertex inside,
        // no crossing): its midpoint is inside k (fuzz finding: an orchard plot over a path).
        const std::size_t n = other.vertices.size();
        for (std::size_t i = 0; i < n; ++i) {
            const glm::dvec2 mid = 0.5 * (mesh.vertices[other.vertices[i]] +
                                          mesh.vertices[other.vertices[(i + 1) % n]]);
            if (const int k = holder(mid, m); k >= 0)
                fail(source, origins[m],
                     "overlaps polygon " + std::to_string(k) + " (edge " +
                         std::to_string(other.vertices[i]) + "-" +
                         std::to_string(other.vertices[(i + 1) % n]) + " runs inside it)");
        }
        // The same outline twice, or one polygon exactly inside another's outline.
        if (const int k = holder(interior_point(mesh, other), m); k >= 0)
            fail(source, origins[m], "overlaps polygon " + std::to_string(k));
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
            if (mesh.vertices.size() >= static_cast<std::size_t>(kMaxExampleVertices))
                error(pos, "more than " + std::to_string(kMaxExampleVertices) + " vertices");
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
    if (vs.size() > static_cast<std::size_t>(kMaxExampleVertices))
        throw key_error("vertices",
                        "more than " + std::to_string(kMaxExampleVertices) + " vertices");
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
