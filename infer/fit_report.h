// How close an inferred template regrows its example (`sylva infer`'s fit report): the
// figures of both skeletons side by side, the Hausdorff distance, and what the inference
// generalised or dropped. Printed as text, written as JSON (docs/infer.md lists the keys).
#pragma once

#include <filesystem>
#include <string>

#include "core/growth.h"
#include "infer/example_tree.h"
#include "infer/rule_inference.h"
#include "infer/skeleton_figures.h"

namespace sylva {

struct FitReport {
    SkeletonFigures example;
    SkeletonFigures regrown;
    double hausdorff = 0.0;  // meters, between points sampled along both skeletons
    int rules = 0;
    int modules = 0;
    int max_rules = 12;
    bool within_rule_limit = true;
    int segments_per_step = 1;
    std::vector<std::string> generalised;
    std::vector<std::string> dropped;
};

// The example's skeleton with its branch depths filled in from the branch graph where the
// file gave none, so both trees count depths alike.
Skeleton example_skeleton_with_depths(const ExampleTree& example);

// Grows the inferred template (tree/growth.h, with `context`: its cancel flag and progress)
// and compares. Throws what growing throws (InputError for a grammar the inference wrote
// wrong: a bug; Cancelled). Thread-safe.
FitReport fit_report(const ExampleTree& example, const InferredTemplate& inferred,
                     Skeleton* regrown = nullptr, const GrowthContext& context = {});

// Relative difference |b - a| / a (0 when both are 0).
double relative_difference(double a, double b);

// The report as lines of text, and as JSON.
std::string fit_report_text(const FitReport& report);
std::string fit_report_json(const FitReport& report);

}  // namespace sylva
