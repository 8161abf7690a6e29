// The many-tree commands of `sylva`: `batch` (forest/batch.h) and `forest` (forest/forest.h).
// Each parses its own flags (the tree flags -t, --set, --budget, ... as `export` spells
// them) and prints progress on stderr.
#pragma once

#include <cstdio>
#include <string>

namespace sylva {

// Usage text of both commands, for `sylva --help`.
void print_forest_help(std::FILE* to);

// The usage of one of them ("batch" or "forest"), for `sylva batch --help`.
void print_forest_command_help(const std::string& command, std::FILE* to);

// argv[1] is "batch" or "forest". Returns the exit code: 0, or 2 for a usage error (printed
// here); other errors are thrown as the rest of the CLI throws them (InputError, IoError).
int run_batch_command(int argc, char** argv);
int run_forest_command(int argc, char** argv);

}  // namespace sylva
