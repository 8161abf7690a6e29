#include "infer/segment_obj.h"

#include <charconv>
#include <cmath>
#include <vector>

#include "core/errors.h"

namespace sylva {
namespace {

std::vector<std::string_view> words(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        std::size_t j = i;
        while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j]))) ++j;
        if (j > i) out.push_back(line.substr(i, j - i));
        i = j;
    }
    return out;
}

struct Edge {
    int from;
    int to;
    int line;
};

}  // namespace

ExampleTree parse_segment_obj(std::string_view text, const std::string& source, UpAxis up) {
    std::vector<glm::vec3> vertices;
    std::vector<Edge> edges;
    int number = 0;
    for (std::size_t at = 0; at < text.size();) {
        std::size_t end = text.find('\n', at);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(at, end - at);
        at = end + 1;
        ++number;
        const std::vector<std::string_view> w = words(line);
        if (w.empty() || w[0].front() == '#') continue;
        auto fail = [&](const std::string& what) -> void {
            throw InputError(what, {source, number, 0}, std::string(line.substr(0, 200)));
        };
        if (w[0] == "v") {
            if (w.size() < 4) fail("a vertex needs x y z");
            double c[3];
            for (int k = 0; k < 3; ++k) {
                std::string_view s = w[static_cast<std::size_t>(k) + 1];
                auto [p, e] = std::from_chars(s.data(), s.data() + s.size(), c[k]);
                if (e != std::errc() || p != s.data() + s.size() || !std::isfinite(c[k]))
                    fail("'" + std::string(s.substr(0, 40)) + "' is not a finite number");
            }
            glm::dvec3 v(c[0], c[1], c[2]);
            if (up == UpAxis::Z) v = {v.x, v.z, -v.y};
            vertices.emplace_back(v);
            if (vertices.size() > 4 * kMaxExampleSegments) fail("too many vertices");
        } else if (w[0] == "l") {
            if (w.size() < 3) fail("a line needs two vertices or more");
            int previous = -1;
            for (std::size_t k = 1; k < w.size(); ++k) {
                std::string_view s = w[k].substr(0, w[k].find('/'));
                long long index = 0;
                auto [p, e] = std::from_chars(s.data(), s.data() + s.size(), index);
                if (e != std::errc() || p != s.data() + s.size() || index == 0)
                    fail("'" + std::string(w[k].substr(0, 40)) + "' is not a vertex index");
                const long long n = static_cast<long long>(vertices.size());
                const long long v = index > 0 ? index - 1 : n + index;
                if (v < 0 || v >= n)
                    fail("vertex " + std::to_string(index) + " is not defined above (" +
                         std::to_string(n) + " vertices)");
                if (previous >= 0) edges.push_back({previous, static_cast<int>(v), number});
                previous = static_cast<int>(v);
                if (edges.size() > kMaxExampleSegments)
                    fail("more than " + std::to_string(kMaxExampleSegments) +
                         " segments; infer takes at most that many");
            }
        }
    }
    if (edges.empty()) throw InputError("the OBJ has no line segments ('l')", {source, 0, 0});

    // Orient the edges away from the lowest vertex used by an edge, breadth first.
    std::vector<std::vector<int>> at_vertex(vertices.size());
    for (std::size_t e = 0; e < edges.size(); ++e) {
        if (edges[e].from == edges[e].to)
            throw InputError("the segment joins a vertex to itself (no length)",
                             {source, edges[e].line, 0});
        at_vertex[static_cast<std::size_t>(edges[e].from)].push_back(static_cast<int>(e));
        at_vertex[static_cast<std::size_t>(edges[e].to)].push_back(static_cast<int>(e));
    }
    int root = edges.front().from;
    for (const Edge& e : edges)
        for (int v : {e.from, e.to})
            if (vertices[static_cast<std::size_t>(v)].y <
                vertices[static_cast<std::size_t>(root)].y)
                root = v;
    ExampleTree tree;
    tree.format = "segment obj";
    std::vector<int> segment_ending_at(vertices.size(), -2);  // -2: not reached
    std::vector<char> edge_used(edges.size(), 0);
    std::vector<int> queue = {root};
    segment_ending_at[static_cast<std::size_t>(root)] = -1;
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const int v = queue[head];
        for (int e : at_vertex[static_cast<std::size_t>(v)]) {
            if (edge_used[static_cast<std::size_t>(e)]) continue;
            edge_used[static_cast<std::size_t>(e)] = 1;
            const Edge& edge = edges[static_cast<std::size_t>(e)];
            const int other = edge.from == v ? edge.to : edge.from;
            if (segment_ending_at[static_cast<std::size_t>(other)] != -2)
                throw InputError("this segment closes a cycle (its vertices are already joined)",
                                 {source, edge.line, 0});
            Segment s;
            s.a = vertices[static_cast<std::size_t>(v)];
            s.b = vertices[static_cast<std::size_t>(other)];
            s.parent = segment_ending_at[static_cast<std::size_t>(v)];
            s.depth = -1;
            segment_ending_at[static_cast<std::size_t>(other)] =
                static_cast<int>(tree.skeleton.segments.size());
            tree.skeleton.segments.push_back(s);
            tree.places.push_back("line " + std::to_string(edge.line));
            queue.push_back(other);
        }
    }
    for (std::size_t e = 0; e < edges.size(); ++e)
        if (!edge_used[e])
            throw InputError(
                "this segment is not connected to the tree's root (disconnected "
                "pieces)",
                {source, edges[e].line, 0});
    tree.notes.push_back("an OBJ has no radii: widths follow the pipe model");
    finish_example_tree(tree, source);
    return tree;
}

}  // namespace sylva
