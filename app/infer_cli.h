// `sylva infer`: rules from an example tree (infer/, docs/infer.md). Parses its own flags.
#pragma once

#include <cstdio>

namespace sylva {

// Usage text, for `sylva --help` and `sylva infer --help`.
void print_infer_help(std::FILE* to);

// argv[1] is "infer". Returns the exit code: 0, or 2 for a usage error (printed here);
// InputError and IoError are thrown as the rest of the CLI throws them.
int run_infer_command(int argc, char** argv);

}  // namespace sylva
