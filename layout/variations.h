// Many layouts from one grammar: each grown to a size (generate.h) and drawn (positions.h),
// in parallel (oneTBB), each from its own seed so the result does not depend on the thread
// count. Without a size, the sizes spread from just above the example's to 12 times it,
// variation i at the golden-ratio point i of that range (any number of variations covers it
// evenly). A graph whose structure cannot be drawn within the length ranges is drawn with
// wider ones; one that cannot be drawn at all is grown again from another seed; the report
// says how often each happened and which limit ended each growth.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/cancel.h"
#include "layout/generate.h"
#include "layout/positions.h"

namespace sylva::layout {

struct VariationSettings {
    // Target size of every variation, in the grammar's measure (generate.h); 0: spread over
    // [spread_low, spread_high] (0: the example's size + 1 and 12 times it).
    int size = 0;
    int spread_low = 0, spread_high = 0;
    // Target area in the example's units squared, instead of a size; 0: none. Grown to the
    // size the example's area per polygon (or corner) suggests, drawn, and grown further
    // while the drawing falls short.
    double area = 0;
    GrowSettings grow;  // its target is set per variation
    LengthSettings lengths;
    int retries = 8;  // graphs grown again when one cannot be drawn
    int threads = 0;  // 0: every core
    CancelFlag cancel = nullptr;
    // After each variation (from a worker thread, serialised): done, total.
    std::function<void(int, int)> progress;
};

struct VariationReport {
    int target = 0;         // size aimed at
    int size = 0;           // size drawn
    GrowReport grow;        // of the graph drawn
    int regrown = 0;        // graphs grown again because the last could not be drawn
    int relax = 0;          // how far the length ranges were widened (positions.h)
    bool fallback = false;  // no grown graph could be drawn: a starter was
    double area = 0;        // of the drawing
};

struct VariationsReport {
    SizeMeasure measure = SizeMeasure::Polygons;
    std::vector<VariationReport> items;
    // "12 stuck, 1 regrown" and the like: which limits bound, or "" when none did.
    std::string limits() const;
};

// `count` layouts from the table's grammar; variation i grows with a seed made from `seed`
// and i, so the same seed gives the same layouts. Each one passes validate_mesh. Throws
// InputError when not even a starter can be drawn, Cancelled when `cancel` is set.
std::vector<PolygonMesh> generate_layouts(const GrowthTable& table, int count, std::uint64_t seed,
                                          const VariationSettings& settings = {},
                                          VariationsReport* report = nullptr);
std::vector<PolygonMesh> generate_layouts(const Grammar& grammar, int count, std::uint64_t seed,
                                          const VariationSettings& settings = {},
                                          VariationsReport* report = nullptr);

// The area of a layout (the sum of its polygons').
double layout_area(const PolygonMesh& mesh);

}  // namespace sylva::layout
