// `sylva layout ...`: the command-line face of the layout module, called from app/main.cpp.
//   sylva layout examples
//   sylva layout derive EXAMPLE [--max-graphs N] [--max-vertices N] -o grammar.json
//   sylva layout generate EXAMPLE|GRAMMAR [--count N] [--seed S] [--steps K] -o DIR/
// --max-graphs / --max-vertices bound the graph hierarchy (DeriveSettings; also for generate
// from an EXAMPLE). EXAMPLE is a shipped example's name (`sylva layout examples`) or a .mesh /
// .json file; GRAMMAR a file written by derive. generate writes DIR/layout_NNN.json and .svg for
// every variation, all or nothing (core/file_set.h).
#pragma once

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "layout/angle_graph.h"

namespace sylva::layout {

// The shipped examples: (name, .mesh text), by name.
const std::vector<std::pair<std::string, std::string>>& builtin_examples();
// A shipped example by name, or a .mesh / .json file. Throws InputError / IoError.
PolygonMesh load_example(const std::string& name_or_path);

// argv[0] is "layout". Returns the exit code (0 ok, 2 usage); bad input and files throw
// InputError / IoError for the caller's boundary.
int run_layout_cli(const std::vector<std::string>& args, std::FILE* out, std::FILE* err);

}  // namespace sylva::layout
