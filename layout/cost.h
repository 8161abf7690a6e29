// What a layout job will cost before it runs: deriving a grammar (bounded by its graph budget
// and the example's size) and generating variations (each grown to its size and drawn; the
// drawing's Gauss-Jordan elimination grows with the cube of the layout's edges). The
// command line refuses, as it does for trees (tree/cost.h), above --max-seconds and
// --max-memory. Fitted on the shipped examples on two cores: a rough guide, not a promise.
#pragma once

#include <string>

#include "layout/derive.h"
#include "layout/variations.h"

namespace sylva::layout {

struct LayoutCost {
    double seconds = 0;  // wall time on two cores, roughly
    double bytes = 0;    // peak memory, roughly
    std::string what;    // "6000 hierarchy graphs", "100 layouts of about 70 polygons"
};

// Deriving a grammar from `example` with `settings`.
LayoutCost derive_cost(const Example& example, const DeriveSettings& settings);

// `count` variations with `settings` from the table's grammar (threads: the worker count,
// 0: every core).
LayoutCost generate_cost(const GrowthTable& table, int count, const VariationSettings& settings);

LayoutCost operator+(const LayoutCost& a, const LayoutCost& b);

}  // namespace sylva::layout
