// skeleton.json: Sylva writes it and reads none, so this fuzzes the writer. The input is
// decoded into a valid skeleton (parents before children, coordinates within the 100 km
// the pipeline accepts) and parameters within their ranges; the written text must parse
// as JSON and give back every segment, parameter and polygon.
#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "export/skeleton_json.h"
#include "fuzz_guard.h"
#include "tree/parameters.h"

namespace {

using namespace sylva;

glm::vec3 point(FuzzedDataProvider& in) {
    auto coordinate = [&] { return in.ConsumeFloatingPointInRange<float>(-1e5f, 1e5f); };
    float x = coordinate(), y = coordinate(), z = coordinate();
    return {x, y, z};
}

bool same_point(const nlohmann::json& j, const glm::vec3& p) {
    return j.size() == 3 && j[0].get<float>() == p.x && j[1].get<float>() == p.y &&
           j[2].get<float>() == p.z;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider in(data, size);
    TreeParams params;
    for (const ParamInfo& info : param_infos()) {
        if (!in.ConsumeBool()) continue;
        double value = in.ConsumeFloatingPointInRange<double>(info.min, info.max);
        if (info.integer) value = std::round(value);
        expect_only_input_errors([&] { set_param(params, info.key, value); });
    }
    params.seed = in.ConsumeIntegral<std::uint64_t>();
    Skeleton skeleton;
    const int segments = in.ConsumeIntegralInRange(0, 512);
    for (int i = 0; i < segments && in.remaining_bytes() > 0; ++i) {
        Segment s;
        s.a = point(in);
        s.b = point(in);
        s.ra = in.ConsumeFloatingPointInRange<float>(0.0f, 100.0f);
        s.rb = in.ConsumeFloatingPointInRange<float>(0.0f, 100.0f);
        s.parent = in.ConsumeIntegralInRange(-1, i - 1);
        s.depth = in.ConsumeIntegralInRange(0, 1000);
        s.color = in.ConsumeIntegral<int>();
        skeleton.segments.push_back(s);
    }
    const int polygons = in.ConsumeIntegralInRange(0, 16);
    for (int i = 0; i < polygons; ++i) {
        std::vector<glm::vec3>& polygon = skeleton.polygons.emplace_back();
        const int points = in.ConsumeIntegralInRange(0, 16);
        for (int k = 0; k < points; ++k) polygon.push_back(point(in));
    }

    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(skeleton_json(skeleton, params));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "sylva fuzz: skeleton.json is not JSON: %s\n", e.what());
        std::abort();
    }
    for (const ParamInfo& info : param_infos())
        if (doc["params"][std::string(info.key)].get<double>() != *get_param(params, info.key))
            fuzz_finding("a parameter does not read back");
    if (doc["params"]["seed"].get<std::uint64_t>() != params.seed)
        fuzz_finding("the seed does not read back");
    const nlohmann::json& out = doc["segments"];
    if (out.size() != skeleton.segments.size()) fuzz_finding("segment count differs");
    for (std::size_t i = 0; i < out.size(); ++i) {
        const Segment& s = skeleton.segments[i];
        if (!same_point(out[i]["a"], s.a) || !same_point(out[i]["b"], s.b) ||
            out[i]["ra"].get<float>() != s.ra || out[i]["rb"].get<float>() != s.rb ||
            out[i]["parent"].get<int>() != s.parent || out[i]["color"].get<int>() != s.color)
            fuzz_finding("a segment does not read back");
    }
    if (doc["polygons"].size() != skeleton.polygons.size()) fuzz_finding("polygon count differs");
    if (doc["tips"].size() != tips(skeleton).size()) fuzz_finding("tip count differs");
    return 0;
}
