// Rules from an example tree: turns a skeleton into a template whose parametric, possibly
// stochastic L-system regrows it (docs/infer.md).
//
// The design, after Godin and Ferraro's (2010) compression of self-nested trees: branches
// of one order that are similar up to scale and rotation are one module, and a chain of
// orders that repeat one pattern (a fork of a fork of a fork) folds into one recursive
// module. Every module is an axis: X(n, m, l, w, p) draws n more segments of length l
// (times a ratio per segment) and width w; at each node it sheds laterals at the phase p
// (advanced by a divergence angle per node) with a branch angle, each an axis of the next
// module whose segment count follows from the height budget m (a whole-number model per
// branch slot, fitted to the example's counts). Angles are measured in the turtle's frame
// either rolled to the vertical after each step (`$`, ABOP 1.5 ; Prusinkiewicz and
// Lindenmayer 1990), so a branch angle means the same on every branch, or moved by the
// least rotation, as a grammar without `$` moves it; both models are inferred, regrown
// and the closer kept. Where the example's nodes differ in how many laterals they carry,
// the module gets weighted alternatives (stochastic rules) with the observed frequencies.
#pragma once

#include <string>
#include <vector>

#include "core/cancel.h"
#include "core/tree_template.h"
#include "infer/example_tree.h"

namespace sylva {

struct InferSettings {
    int max_rules = 12;        // productions, the alternatives of a stochastic rule counted
    int max_generations = 15;  // the `generations` range of a template
    std::string name = "inferred";
    CancelFlag cancel = nullptr;  // polled between stages; throws Cancelled
};

struct InferredTemplate {
    TreeTemplate tree;  // grows with tree/growth.h's grow()
    std::string text;   // the template file: commented TOML with `#define` sliders
    int rules = 0;      // productions in the grammar
    int modules = 0;    // axis modules (A, B, ...)
    bool within_rule_limit = true;
    int segments_per_step = 1;  // > 1 when the tree is deeper than max_generations steps
    // What the rules state more simply than the example has it, and what they leave out,
    // one sentence each, for the fit report.
    std::vector<std::string> generalised;
    std::vector<std::string> dropped;
};

// Infers the template. Throws InputError when the example cannot be expressed at all
// (it can always be, for a tree that passed finish_example_tree()), Cancelled when
// settings.cancel is set. Deterministic: the same example gives the same text.
// Thread-safe. Regrows up to four candidate templates to choose among them, each linear in
// the segments.
InferredTemplate infer_template(const ExampleTree& example, const InferSettings& settings = {});

}  // namespace sylva
