// Deriving a graph grammar from one example (Schröder 2024, section 3.3, after Merrell 2023).
//
// The split operation cuts every edge of the example's angle graph; the one-vertex pieces
// left are the primitives (generation 1; generation 0 are the distinct edges). The graph
// hierarchy is grown generation by generation: each graph of the newest generation gets
// every loop gluing its open boundaries allow (two opposite half-edges next to each other
// with a -180 degree turn between them) and every branch gluing with a primitive. A new
// graph L is then tested:
//   - it contains an earlier rule's left side: that rule reduces it, so it is dropped
//     (Merrell's pruning);
//   - complete (no half-edges): a starter rule (empty graph -> L); L leaves the hierarchy;
//   - its boundary equals that of an earlier graph R, or is composed of the boundaries of
//     several earlier graphs R1 v R2 ... (one extra negative turn per joint, found
//     recursively, any number of pieces): a DPO rule L <-> {R1, R2, ...} (the interface is
//     the common boundary); L leaves the hierarchy, since the rule reduces it;
//   - else L stays and grows in the next generation (so does a graph with half-edges on
//     more than one boundary, which gives no rule).
// Growth ends when no graph is left open (the grammar then reduces every graph locally
// similar to the example) or at a limit of DeriveSettings; Grammar::hierarchy says which.
// Most examples do not close (Schröder says the same of the thesis's implementation): the
// grammar is partial, and the example is added as a starter when no starter is it.
//
// Deterministic for the same example and settings unless max_seconds ends it. Runs on the
// calling thread; polls `cancel`.
#pragma once

#include "core/cancel.h"
#include "layout/graph_grammar.h"

namespace sylva::layout {

struct DeriveSettings {
    // Graphs the hierarchy may make: the budget that ends most derivations (a few hundred
    // milliseconds for the shipped examples).
    int max_graphs = 6000;
    // Wall time; 0: none. A derivation this ends depends on the machine's speed.
    double max_seconds = 0;
    int max_generations = 0;  // 0: none
    int max_vertices = 0;     // per hierarchy graph; 0: none
    int max_pieces = 0;       // right-hand pieces per rule; 0: any number
    // Steps one boundary decomposition may take (the search is memoised; this only stops
    // pathological boundaries).
    int max_decomposition_steps = 20000;
    CancelFlag cancel = nullptr;
};

Grammar derive_grammar(const Example& example, const DeriveSettings& settings = {});

}  // namespace sylva::layout
