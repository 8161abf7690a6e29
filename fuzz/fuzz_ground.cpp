// Fuzzes the forest's ground plan reader (polygons with planting classes, a file artists
// share): any bytes give a ground or an InputError, and a ground it gives has polygons of at
// least three finite points.
#include <cmath>

#include "forest/ground.h"
#include "fuzz_guard.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace sylva;
    expect_only_input_errors([&] {
        const forest::Ground ground =
            forest::parse_ground_json(std::string(fuzz_text(data, size)), "fuzz.json");
        for (const auto& polygon : ground.polygons) {
            if (polygon.points.size() < 3)
                fuzz_finding("a ground polygon with fewer than 3 points");
            for (const auto& p : polygon.points)
                if (!std::isfinite(p.x) || !std::isfinite(p.y))
                    fuzz_finding("a ground point that is not finite");
        }
    });
    return 0;
}
