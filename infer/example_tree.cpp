#include "infer/example_tree.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <sstream>

#include "core/errors.h"
#include "core/input_file.h"
#include "infer/cylinder_csv.h"
#include "infer/segment_obj.h"
#include "infer/skeleton_json_reader.h"

namespace sylva {
namespace {

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::string place_of(const ExampleTree& tree, std::size_t i) {
    return i < tree.places.size() ? tree.places[i] : "segment " + std::to_string(i);
}

[[noreturn]] void fail(const std::string& source, const std::string& what) {
    throw InputError(what, {source, 0, 0});
}

std::string_view skip_space(std::string_view text) {
    std::size_t i = 0;
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    return text.substr(i);
}

// An OBJ has a line starting with "v " or "l " before any other content line; a table has
// numbers or column names.
bool looks_like_obj(std::string_view text) {
    std::istringstream lines{std::string(text.substr(0, 1 << 16))};
    std::string line;
    while (std::getline(lines, line)) {
        std::string_view l = skip_space(line);
        if (l.empty() || l[0] == '#') continue;
        return l.starts_with("v ") || l.starts_with("v\t") || l.starts_with("l ") ||
               l.starts_with("o ") || l.starts_with("g ") || l.starts_with("mtllib");
    }
    return false;
}

}  // namespace

ExampleTree parse_example_tree(std::string_view text, const std::string& source,
                               std::optional<UpAxis> up) {
    std::string_view start = skip_space(text);
    if (!start.empty() && start[0] == '{') return parse_skeleton_json(text, source);
    if (looks_like_obj(text)) return parse_segment_obj(text, source, up.value_or(UpAxis::Y));
    return parse_cylinder_csv(text, source, up.value_or(UpAxis::Z));
}

ExampleTree read_example_tree(const std::filesystem::path& path, std::optional<UpAxis> up) {
    const std::string text = read_input_file(path, "example tree");
    return parse_example_tree(text, path.string(), up);
}

void finish_example_tree(ExampleTree& tree, const std::string& source) {
    std::vector<Segment>& segments = tree.skeleton.segments;
    const std::size_t count = segments.size();
    if (count == 0) fail(source, "the file has no segments");
    if (count > kMaxExampleSegments)
        fail(source, "the file has " + std::to_string(count) + " segments; infer takes at most " +
                         std::to_string(kMaxExampleSegments));
    tree.places.resize(count);
    tree.continuation.resize(count, -1);
    float extent = 0.0f;
    for (std::size_t i = 0; i < count; ++i) {
        const Segment& s = segments[i];
        if (!finite(s.a) || !finite(s.b))
            fail(source, place_of(tree, i) + ": a coordinate is not a finite number");
        if (!std::isfinite(s.ra) || !std::isfinite(s.rb) || s.ra < 0.0f || s.rb < 0.0f)
            fail(source, place_of(tree, i) + ": a radius is negative or not a finite number");
        if (std::abs(s.a.x) > 1e5f || std::abs(s.a.y) > 1e5f || std::abs(s.a.z) > 1e5f ||
            std::abs(s.b.x) > 1e5f || std::abs(s.b.y) > 1e5f || std::abs(s.b.z) > 1e5f)
            fail(source, place_of(tree, i) + ": a coordinate is beyond 100 km");
        if (s.parent < -1 || s.parent >= static_cast<int>(count))
            fail(source, place_of(tree, i) + ": parent " + std::to_string(s.parent) +
                             " is not a segment (there are " + std::to_string(count) + ")");
        if (static_cast<std::size_t>(s.parent) == i)
            fail(source, place_of(tree, i) + ": the segment is its own parent");
        extent = std::max(extent, glm::length(s.b - s.a));
    }
    for (std::size_t i = 0; i < count; ++i) {
        const Segment& s = segments[i];
        if (!(glm::length(s.b - s.a) > 1e-6f * std::max(extent, 1e-3f)))
            fail(source, place_of(tree, i) + ": the segment has no length (its ends coincide)");
    }
    // Cycles: walk each chain of parents once, colouring what is on the current walk.
    std::vector<char> state(count, 0);  // 0 unseen, 1 on the walk, 2 done
    std::vector<std::size_t> walk;
    for (std::size_t i = 0; i < count; ++i) {
        walk.clear();
        std::size_t k = i;
        while (state[k] == 0) {
            state[k] = 1;
            walk.push_back(k);
            if (segments[k].parent < 0) break;
            k = static_cast<std::size_t>(segments[k].parent);
            if (state[k] == 1)
                fail(source, place_of(tree, k) + ": its parents lead back to it (a cycle)");
        }
        for (std::size_t w : walk) state[w] = 2;
    }
    // Children, then parents before children from the roots in file order.
    std::vector<std::vector<int>> children(count);
    std::vector<int> roots;
    for (std::size_t i = 0; i < count; ++i) {
        if (segments[i].parent < 0)
            roots.push_back(static_cast<int>(i));
        else
            children[static_cast<std::size_t>(segments[i].parent)].push_back(static_cast<int>(i));
    }
    const glm::vec3 origin = segments[static_cast<std::size_t>(roots.front())].a;
    float size = 0.0f;
    for (const Segment& s : segments) size = std::max(size, glm::length(s.b - origin));
    for (int r : roots) {
        if (glm::length(segments[static_cast<std::size_t>(r)].a - origin) > 1e-3f * size)
            fail(source, place_of(tree, static_cast<std::size_t>(r)) +
                             ": a second tree (disconnected pieces): it has no parent and "
                             "starts away from " +
                             place_of(tree, static_cast<std::size_t>(roots.front())));
    }
    std::vector<int> order, new_index(count, -1);
    order.reserve(count);
    for (int r : roots) {
        std::size_t head = order.size();
        order.push_back(r);
        while (head < order.size()) {
            const int s = order[head++];
            for (int c : children[static_cast<std::size_t>(s)]) order.push_back(c);
        }
    }
    for (std::size_t i = 0; i < order.size(); ++i)
        new_index[static_cast<std::size_t>(order[i])] = static_cast<int>(i);
    std::vector<Segment> sorted(count);
    std::vector<std::string> places(count);
    std::vector<int> continuation(count, -1);
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t from = static_cast<std::size_t>(order[i]);
        Segment s = segments[from];
        s.parent = s.parent < 0 ? -1 : new_index[static_cast<std::size_t>(s.parent)];
        s.a -= origin;
        s.b -= origin;
        sorted[i] = s;
        places[i] = std::move(tree.places[from]);
        const int c = tree.continuation[from];
        continuation[i] =
            c >= 0 && c < static_cast<int>(count) &&
                    segments[static_cast<std::size_t>(c)].parent == static_cast<int>(from)
                ? new_index[static_cast<std::size_t>(c)]
                : -1;
    }
    segments = std::move(sorted);
    tree.places = std::move(places);
    tree.continuation = std::move(continuation);
    if (glm::length(origin) > 1e-6f) {
        std::ostringstream note;
        note << "moved by (" << -origin.x << ", " << -origin.y << ", " << -origin.z
             << ") so the root starts at the origin";
        tree.notes.push_back(note.str());
    }
}

}  // namespace sylva
