// The seam between a template and its skeleton: a growth method (L-system + turtle, space
// colonization, ...) turns a template into a Skeleton, which every later stage
// (fields, meshing, leaves, low poly, export) shares. Each method lives in its own folder
// with its parameters' table and is registered with one line in tree/growth.cpp; help text,
// --set, template files and the studio find its parameters there.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "core/cancel.h"
#include "core/region.h"
#include "core/skeleton.h"
#include "core/tree_template.h"

namespace sylva {

// How long one stage of making a tree took, for status lines and benchmarks.
struct StageTime {
    std::string name;
    double ms = 0.0;
    // Made at the same time as the other stages marked so: together they took the longest
    // of their times (stages_wall_ms in tree/pipeline.h), not the sum.
    bool beside_others = false;
};

// What growing a template costs, in tree/cost.h's units: estimated from the parameters before
// any growth, or counted as a growth goes.
struct GrowthCost {
    double segments = 0;  // the skeleton's segments (roughly, before growth)
    double seconds = 0;   // wall time of the growth alone on two cores
    double bytes = 0;     // its peak memory
    std::string work;     // what the figures come from ("1000000 points x about 10400 nodes")
};

// The most a growth may cost. A method that counts its work as it goes (colonization) throws
// InputError once the count passes a limit, naming it and `how_to_raise`: the limit holds
// whatever the estimate said, and on every machine alike (work, not a clock).
struct GrowthLimits {
    double max_seconds = std::numeric_limits<double>::infinity();
    double max_bytes = std::numeric_limits<double>::infinity();
    std::string how_to_raise = "raise the limits";
};

struct GrowthContext {
    CancelFlag cancel = nullptr;              // polled between steps; throws Cancelled
    std::vector<StageTime>* times = nullptr;  // when set, each method appends its stages
    // The crown of the built-in template of that name, as a solid (inside where the
    // pipeline's crown field is negative), for a method that fills another template's crown
    // (colonization's envelope = "template"). tree/growth.h's grow() sets it, since only
    // tree/ knows templates and the pipeline; a method called without it throws InputError
    // when it needs one. Throws InputError for an unknown name or a template without crown.
    std::function<Region(std::string_view template_name)> template_crown = nullptr;
    // Called with the finished fraction of the growth (rising, ends with 1), on the growing
    // thread, often enough to draw a progress bar: the L-system per derivation step and every
    // few thousand modules, then through the turtle; colonization per iteration.
    std::function<void(float)> progress = nullptr;
    GrowthLimits limits = {};  // none by default
};

// A parameter a template leaves unread, and why ("every F in the rules gives its own
// length"): the studio greys it out and shows the reason.
struct UnreadParam {
    std::string key;
    std::string reason;
};

class ParamTable;

struct GrowthMethod {
    std::string_view name;         // a template's `growth = "..."`
    std::string_view description;  // one line, for --help and the studio
    // Throws InputError (GrammarError for a grammar) on bad input, naming the template's
    // file and line where it has one; Cancelled when the context's flag is set.
    Skeleton (*grow)(const TreeTemplate& tree, const GrowthContext& context);
    // The method's own parameters (core/param_table.h), kept in TreeParams::blocks; nullptr
    // for a method with none.
    const ParamTable& (*params)() = nullptr;
    // Whether its templates carry a grammar (a template file must then have one).
    bool uses_grammar = false;
    // The shared parameters this method never reads for `tree`, and those of its own that
    // the tree's other choices make moot, each with the reason; nullptr when it reads every
    // one. The parameters of other methods need no mention. May grow the tree (cache the
    // answer); throws what grow throws.
    std::vector<UnreadParam> (*unread)(const TreeTemplate& tree,
                                       const GrowthContext& context) = nullptr;
    // The growth's cost from the template's parameters alone, cheaply (no growth): a rough
    // guide for tree/cost.h's estimate_cost. nullptr: the method has none (tree/cost.h
    // knows the L-system's).
    GrowthCost (*estimate)(const TreeTemplate& tree) = nullptr;
};

}  // namespace sylva
