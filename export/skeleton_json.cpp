#include "export/skeleton_json.h"

#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "tree/parameters.h"
#include "tree/pipeline.h"

namespace sylva {
namespace {

nlohmann::json point(const glm::vec3& p) {
    return nlohmann::json::array({p.x, p.y, p.z});
}

}  // namespace

std::string skeleton_json(const Skeleton& skeleton, const TreeParams& params) {
    nlohmann::json doc;
    doc["format"] = "sylva-skeleton";
    doc["version"] = 1;
    nlohmann::json& p = doc["params"];
    for (const ParamInfo& info : param_infos()) {
        double value = *get_param(params, info.key);
        if (info.integer)
            p[std::string(info.key)] = static_cast<long long>(value);
        else
            p[std::string(info.key)] = value;
    }
    p["seed"] = params.seed;
    nlohmann::json& segments = doc["segments"] = nlohmann::json::array();
    for (const Segment& s : skeleton.segments) {
        segments.push_back({{"a", point(s.a)},
                            {"b", point(s.b)},
                            {"ra", s.ra},
                            {"rb", s.rb},
                            {"parent", s.parent},
                            {"depth", s.depth},
                            {"color", s.color}});
    }
    doc["tips"] = tips(skeleton);
    nlohmann::json& spheres = doc["crown_spheres"] = nlohmann::json::array();
    for (const Ball& s : crown_spheres(skeleton, params))
        spheres.push_back({{"c", point(s.center)}, {"r", s.radius}});
    nlohmann::json& polygons = doc["polygons"] = nlohmann::json::array();
    for (const auto& polygon : skeleton.polygons) {
        nlohmann::json points = nlohmann::json::array();
        for (const glm::vec3& v : polygon) points.push_back(point(v));
        polygons.push_back(std::move(points));
    }
    return doc.dump(1) + "\n";
}

void write_skeleton_json(const std::filesystem::path& path, const Skeleton& skeleton,
                         const TreeParams& params) {
    std::string text = skeleton_json(skeleton, params);
    write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace sylva
