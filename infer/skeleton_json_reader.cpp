#include "infer/skeleton_json_reader.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/errors.h"
#include "tree/parameters.h"

namespace sylva {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& source, const std::string& key, const std::string& what) {
    throw InputError(key + ": " + what, {source, 0, 0});
}

// 1-based line and column of a byte offset.
SourceLocation locate(std::string_view text, std::size_t offset, const std::string& source) {
    SourceLocation at{source, 1, 1};
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++at.line;
            at.column = 1;
        } else {
            ++at.column;
        }
    }
    return at;
}

float number(const json& value, const std::string& source, const std::string& key) {
    if (!value.is_number()) fail(source, key, "expected a number");
    const double v = value.get<double>();
    if (!std::isfinite(v) || std::abs(v) > 1e30) fail(source, key, "not a finite number");
    return static_cast<float>(v);
}

int integer(const json& value, const std::string& source, const std::string& key) {
    if (!value.is_number_integer()) fail(source, key, "expected a whole number");
    const long long v = value.get<long long>();
    if (v < -1 || v > 1'000'000'000LL) fail(source, key, "out of range");
    return static_cast<int>(v);
}

glm::vec3 point(const json& value, const std::string& source, const std::string& key) {
    if (!value.is_array() || value.size() != 3) fail(source, key, "expected a point [x, y, z]");
    return {number(value[0], source, key + "[0]"), number(value[1], source, key + "[1]"),
            number(value[2], source, key + "[2]")};
}

}  // namespace

ExampleTree parse_skeleton_json(std::string_view text, const std::string& source) {
    json doc;
    try {
        doc = json::parse(text.begin(), text.end());
    } catch (const json::parse_error& e) {
        SourceLocation at = locate(text, e.byte > 0 ? e.byte - 1 : 0, source);
        throw InputError("not JSON: " + std::string(e.what()), at);
    } catch (const json::exception& e) {  // a number too large for a double, and the like
        throw InputError("not JSON Sylva can read: " + std::string(e.what()), {source, 0, 0});
    }
    if (!doc.is_object()) fail(source, "(top)", "expected a JSON object");
    if (!doc.contains("format") || doc["format"] != "sylva-skeleton")
        fail(source, "format", "expected \"sylva-skeleton\"");
    if (doc.contains("version") && doc["version"] != 1)
        fail(source, "version", "only version 1 is known");
    if (!doc.contains("segments") || !doc["segments"].is_array())
        fail(source, "segments", "expected an array of segments");
    const json& segments = doc["segments"];
    if (segments.size() > kMaxExampleSegments)
        fail(source, "segments",
             std::to_string(segments.size()) + " segments; infer takes at most " +
                 std::to_string(kMaxExampleSegments));

    ExampleTree tree;
    tree.format = "skeleton.json";
    tree.skeleton.segments.reserve(segments.size());
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const std::string key = "segments[" + std::to_string(i) + "]";
        const json& s = segments[i];
        if (!s.is_object()) fail(source, key, "expected an object");
        Segment out;
        if (!s.contains("a") || !s.contains("b")) fail(source, key, "needs \"a\" and \"b\"");
        out.a = point(s["a"], source, key + ".a");
        out.b = point(s["b"], source, key + ".b");
        out.ra = s.contains("ra") ? number(s["ra"], source, key + ".ra") : 0.0f;
        out.rb = s.contains("rb") ? number(s["rb"], source, key + ".rb") : out.ra;
        out.parent = s.contains("parent") ? integer(s["parent"], source, key + ".parent") : -1;
        out.depth = s.contains("depth") ? integer(s["depth"], source, key + ".depth") : -1;
        out.color =
            s.contains("color") && s["color"].is_number_integer()
                ? static_cast<int>(std::clamp<long long>(s["color"].get<long long>(), 0, 1'000'000))
                : 0;
        tree.skeleton.segments.push_back(out);
        tree.places.push_back(key);
    }
    if (doc.contains("params")) {
        const json& p = doc["params"];
        if (!p.is_object()) fail(source, "params", "expected an object");
        TreeParams params;
        for (const auto& [key, value] : p.items()) {
            if (key == "seed") {
                if (value.is_number_unsigned())
                    params.seed = value.get<std::uint64_t>();
                else if (value.is_number_integer() && value.get<long long>() >= 0)
                    params.seed = static_cast<std::uint64_t>(value.get<long long>());
                else
                    fail(source, "params.seed", "expected a whole number from 0 to 2^64 - 1");
                continue;
            }
            if (!get_param(params, key)) {
                tree.notes.push_back("params." + key +
                                     " is not a parameter of this Sylva; left out");
                continue;
            }
            if (!value.is_number()) fail(source, "params." + key, "expected a number");
            try {
                set_param(params, key, value.get<double>());
            } catch (const InputError& e) {
                fail(source, "params." + key, e.reason());
            }
        }
        tree.params = params;
    }
    if (doc.contains("polygons") && doc["polygons"].is_array() && !doc["polygons"].empty())
        tree.notes.push_back(std::to_string(doc["polygons"].size()) +
                             " leaf polygons are not regrown (infer regrows branches)");
    finish_example_tree(tree, source);
    return tree;
}

}  // namespace sylva
