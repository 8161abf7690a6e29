// `sylva layout ...`: the command-line face of the layout module (layout/, docs/layout.md).
//   sylva layout examples
//   sylva layout derive EXAMPLE [derive flags] -o grammar.json
//   sylva layout generate EXAMPLE|GRAMMAR [--count N] [--seed S] [--size N|A..B] [--area A]
//                          [--length CLASS=LO..HI]... [--sheet FILE.svg] -o DIR/
// EXAMPLE is a shipped example's name (`sylva layout examples`) or a .mesh / .json file;
// GRAMMAR a file written by derive. Every job is estimated before it runs and refused above
// --max-seconds / --max-memory (as tree jobs are). generate writes DIR/layout_NNN.json and .svg
// for every variation (and the sheet), all or nothing (core/file_set.h).
#pragma once

#include <cstdio>
#include <string>
#include <vector>

namespace sylva {

// The usage text, for `sylva --help` and `sylva layout --help`.
void print_layout_help(std::FILE* to);

// args[0] is "layout". Returns the exit code (0 ok, 2 usage, printed to `err`); bad input and
// files throw InputError / IoError for the caller's boundary.
int run_layout_cli(const std::vector<std::string>& args, std::FILE* out, std::FILE* err);

}  // namespace sylva
